// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where write_file_atomically() writes: through symbolic links, straight
// into devices, under long names, and what a signal during a write leaves.
#include <CGAL/MPM/internal/Atomic_file.h>

#include "Io_test_support.h"

#include <gtest/gtest.h>

#include <csignal>
#include <ostream>

#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace CGAL::MPM;
using mpm_test::read_bytes;
using mpm_test::write_bytes;
namespace fs = std::filesystem;

void write_text(const std::string& path, const std::string& text)
{
  internal::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

} // namespace

TEST(AtomicFile, SymbolicLinksAreWrittenThroughAndStayLinks)
{
  mpm_test::Scratch_directory dir;
  write_bytes(dir.file("target.json"), "old");
  fs::create_symlink("target.json", dir.file("link.json"));
  write_text(dir.file("link.json"), "new");
  EXPECT_TRUE(fs::is_symlink(dir.file("link.json")));
  EXPECT_EQ(read_bytes(dir.file("target.json")), "new");
  // A dangling link gets its target created.
  fs::create_symlink("later.json", dir.file("dangling.json"));
  write_text(dir.file("dangling.json"), "created");
  EXPECT_TRUE(fs::is_symlink(dir.file("dangling.json")));
  EXPECT_EQ(read_bytes(dir.file("later.json")), "created");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"dangling.json", "later.json", "link.json", "target.json"}));
}

TEST(AtomicFile, DevicesAreWrittenNotReplaced)
{
  if(!fs::is_character_file("/dev/null")) GTEST_SKIP() << "no /dev/null";
  write_text("/dev/null", "discarded");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(AtomicFile, TemporaryNamesFitTheNameLimitOfLongOutputNames)
{
  mpm_test::Scratch_directory dir;
  const std::string name = std::string(245, 'a') + ".json"; // 250 characters, a valid name
  write_text(dir.file(name), "long");
  EXPECT_EQ(read_bytes(dir.file(name)), "long");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{name});
}

// A child process interrupted by SIGTERM in the middle of a write leaves
// neither the output nor the temporary file.
TEST(AtomicFile, ASignalDuringAWriteLeavesNoTemporaryFile)
{
  mpm_test::Scratch_directory dir;
  const std::string path = dir.file("interrupted.off");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if(child == 0)
  {
    internal::remove_temporary_files_on_signals();
    internal::write_file_atomically(path, [](std::ostream& out) {
      out << std::string(1 << 20, 'x');
      out.flush();
      std::raise(SIGTERM);
    });
    std::_Exit(0); // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_TRUE(dir.entries().empty()) << dir.entries().front();
}
