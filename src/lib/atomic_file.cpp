// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/Input_error.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <system_error>

namespace CGAL {
namespace MPM {
namespace internal {

namespace fs = std::filesystem;

namespace {

// A name no other writer (thread or process) picks at the same time: the
// random part separates processes, the counter separates threads of one.
fs::path unique_temporary_path(const fs::path& target)
{
  static std::atomic<unsigned long> counter{0};
  static const unsigned long long process_salt = std::random_device{}();
  std::ostringstream name;
  name << '.' << target.filename().string() << ".tmp." << std::hex << process_salt << '.'
       << counter++;
  return target.parent_path() / name.str();
}

// Removes the temporary file on every exit path except a successful rename.
struct Temporary_file_guard
{
  fs::path path;
  bool armed = true;
  ~Temporary_file_guard()
  {
    if(armed) {
      std::error_code ignored;
      fs::remove(path, ignored);
    }
  }
};

} // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary)
{
  const fs::path target(path);
  std::error_code ec;
  if(fs::is_directory(target, ec))
    throw Input_error(path, "", "cannot write: the path is a directory");

  fs::path temporary;
  do { temporary = unique_temporary_path(target); } while(fs::exists(temporary, ec));

  Temporary_file_guard guard{temporary};
  {
    std::ofstream out(temporary, binary ? std::ios::out | std::ios::binary | std::ios::trunc
                                        : std::ios::out | std::ios::trunc);
    if(!out)
      throw Input_error(path, "", "cannot write: cannot create a file in directory \"" +
                                      (target.has_parent_path() ? target.parent_path().string()
                                                                : std::string(".")) + "\"");
    write(out);
    out.flush();
    if(!out)
      throw Input_error(path, "", "cannot write: output error (disk full?)");
    out.close();
    if(out.fail())
      throw Input_error(path, "", "cannot write: output error while closing the file");
  }

  // Keep the permissions a user gave the file being replaced.
  if(fs::exists(target, ec))
    fs::permissions(temporary, fs::status(target, ec).permissions(), ec);

  fs::rename(temporary, target, ec);
  if(ec)
    throw Input_error(path, "", "cannot write: " + ec.message());
  guard.armed = false;
}

void check_readable_file(const std::string& path)
{
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if(!fs::exists(status))
    throw Input_error(path, "", "file not found");
  if(fs::is_directory(status))
    throw Input_error(path, "", "is a directory, not a file");
  if(!std::ifstream(path, std::ios::in | std::ios::binary))
    throw Input_error(path, "", "cannot open the file for reading (permission denied?)");
}

std::string read_file(const std::string& path)
{
  check_readable_file(path);
  std::ifstream in(path, std::ios::in | std::ios::binary);
  if(!in)
    throw Input_error(path, "", "cannot open the file for reading");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if(in.bad())
    throw Input_error(path, "", "read error");
  return bytes;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
