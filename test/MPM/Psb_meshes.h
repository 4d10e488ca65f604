// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Where the tests find the segmented PSB meshes (../shared/data/psb beside
// the checkout, as CI lays them out), and how they skip without them.
#ifndef CGAL_MPM_TEST_PSB_MESHES_H
#define CGAL_MPM_TEST_PSB_MESHES_H

#include <cstdlib>
#include <filesystem>
#include <string>

namespace mpm_test {

// MPM_PSB_DIR in the environment, else the directory configured at build
// time; the sanitizer suite points the variable at an empty place to leave
// these tests to the release suite.
inline std::string psb_directory()
{
  const char* dir = std::getenv("MPM_PSB_DIR");
  return dir && *dir ? dir : MPM_PSB_DIR;
}

// The file `name` (with its extension) of the PSB directory.
inline std::string psb_file(const std::string& name) { return psb_directory() + "/" + name; }

// Why a test on the PSB meshes skips: `path` (a mesh or their directory) is absent.
inline std::string psb_not_found(const std::string& path)
{
  return path + " not found: the segmented PSB meshes are not there (set MPM_PSB_DIR to their directory)";
}

} // namespace mpm_test

// Skips the test with a message when the PSB mesh `name` (no extension) is absent.
#define MPM_REQUIRE_PSB(name)                                                            \
  if(!std::filesystem::is_regular_file(mpm_test::psb_file(std::string(name) + ".off"))) \
  GTEST_SKIP() << mpm_test::psb_not_found(mpm_test::psb_file(std::string(name) + ".off"))

#endif
