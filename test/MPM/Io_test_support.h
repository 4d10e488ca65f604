// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the input/output tests: scratch directories, file bytes
// and checks of Input_error messages.
#ifndef CGAL_MPM_TEST_IO_TEST_SUPPORT_H
#define CGAL_MPM_TEST_IO_TEST_SUPPORT_H

#include <CGAL/MPM/Input_error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace mpm_test {

namespace fs = std::filesystem;

// A fresh directory removed with everything in it at the end of the test.
class Scratch_directory
{
public:
  Scratch_directory()
  {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("cgal_mpm_io_" + std::to_string(std::random_device{}()) + "_" + std::to_string(counter++));
    fs::create_directories(path_);
  }
  ~Scratch_directory()
  {
    std::error_code ec;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }
  // Names of the entries, sorted, to detect left-over temporary files.
  std::vector<std::string> entries() const
  {
    std::vector<std::string> r;
    for(const auto& e : fs::directory_iterator(path_)) r.push_back(e.path().filename().string());
    std::sort(r.begin(), r.end());
    return r;
  }

private:
  fs::path path_;
};

inline void write_bytes(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

inline std::string read_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Three vertex lines of a mesh file, for the files that vary the rest.
inline const std::string triangle_vertices = "0 0 0\n1 0 0\n0 1 0\n";

// The message of the Input_error that `f` throws, or a marker when it throws none.
template <class F>
std::string input_error_message(F&& f)
{
  try {
    f();
  } catch(const CGAL::MPM::Input_error& e) {
    return e.what();
  }
  return "<no Input_error thrown>";
}

inline ::testing::AssertionResult contains_all(const std::string& message,
                                               std::initializer_list<std::string> pieces)
{
  for(const std::string& p : pieces)
    if(message.find(p) == std::string::npos)
      return ::testing::AssertionFailure() << "\"" << message << "\" lacks \"" << p << "\"";
  if(message.find('\n') != std::string::npos)
    return ::testing::AssertionFailure() << "\"" << message << "\" is not one line";
  return ::testing::AssertionSuccess();
}

// Checks that `statement` throws Input_error whose message contains every piece.
#define MPM_EXPECT_INPUT_ERROR(statement, ...) \
  EXPECT_TRUE(::mpm_test::contains_all(::mpm_test::input_error_message([&] { statement; }), {__VA_ARGS__}))

} // namespace mpm_test

#endif
