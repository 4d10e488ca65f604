// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// A small run of the speed benchmarks (bench/bench_*.cpp, program mpm_bench):
// only the 3k-vertex hand rows, a short minimum time, JSON output. Every
// expected row is there, without error, with a finite positive time and its
// counters finite. No timing is asserted.
#include "Io_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

#ifdef MPM_BENCH_PROGRAM
bool finite_number(const nlohmann::json& value) { return value.is_number() && std::isfinite(value.get<double>()); }
#endif

} // namespace

TEST(Benchmark_program, hand_3k_rows_are_complete_and_finite)
{
#ifndef MPM_BENCH_PROGRAM
  GTEST_SKIP() << "mpm_bench is not built (Google Benchmark not found or MPM_BUILD_BENCHMARKS off)";
#else
  mpm_test::Scratch_directory scratch;
  const std::string output = scratch.file("bench.json");
  // The real meshes are not needed here: point MPM_DATA_DIR nowhere, so that
  // registration does not depend on what a build directory holds.
  const std::string command = std::string("MPM_DATA_DIR=\"") + scratch.file("no-data") + "\" \"" + MPM_BENCH_PROGRAM +
                              "\" --benchmark_filter=/hand_3k/ --benchmark_min_time=0.01 --benchmark_format=json > \"" +
                              output + "\" 2>/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(output);
  nlohmann::json data;
  ASSERT_NO_THROW(in >> data) << mpm_test::read_bytes(output);
  ASSERT_TRUE(data.contains("benchmarks") && data["benchmarks"].is_array());

  // Name (up to the handle count) -> counters every such row must have.
  const std::vector<std::string> sizes{"vertices", "clusters", "modes"};
  const std::vector<std::string> phases{"local_step_ms", "rhs_ms",    "schur_ms",
                                        "back_substitution_ms", "direct_ms", "energy_ms"};
  std::map<std::string, std::vector<std::string>> expected;
  for(const std::string step : {"direct", "schur", "reduced"})
  {
    const std::string variant = "hand_3k/mpm_" + step + "_ldlt/handles:16";
    std::vector<std::string> iteration = sizes;
    iteration.insert(iteration.end(), phases.begin(), phases.end());
    expected["BM_iteration/" + variant] = iteration;
    expected["BM_factor/" + variant] = sizes;
    if(step != "direct") expected["BM_frame/" + variant] = {"vertices", "clusters", "modes", "iterations_per_frame", "converged"};
  }
  expected["BM_first_frame/hand_3k/mpm_reduced_ldlt/handles:16"] = {"vertices", "clusters", "modes",
                                                                   "iterations_per_frame", "converged"};
  expected["BM_handle_set/hand_3k/mpm_reduced_ldlt/handles:16"] = {"vertices", "clusters", "modes"};
  expected["BM_iteration/hand_3k/arap/handles:16"] = {"vertices"};
  expected["BM_factor/hand_3k/arap/handles:16"] = {"vertices"};
  expected["BM_first_frame/hand_3k/arap/handles:16"] = {"vertices", "iterations_per_frame"};
  expected["BM_frame/hand_3k/arap/handles:16"] = {"vertices", "iterations_per_frame"};

  std::set<std::string> seen;
  for(const nlohmann::json& row : data["benchmarks"])
  {
    const std::string name = row.value("name", "");
    SCOPED_TRACE(name);
    EXPECT_FALSE(row.value("error_occurred", false)) << row.value("error_message", "");
    ASSERT_TRUE(row.contains("real_time"));
    EXPECT_TRUE(finite_number(row["real_time"]));
    EXPECT_GT(row["real_time"].get<double>(), 0.);
    // BM_frame rows carry "/iterations:20"; cholmod rows appear when built with CHOLMOD.
    std::string key = name.substr(0, name.find("/iterations:"));
    const std::size_t cholmod = key.find("_cholmod/");
    if(cholmod != std::string::npos) key.replace(cholmod, 8, "_ldlt");
    const auto found = expected.find(key);
    ASSERT_NE(found, expected.end()) << "unexpected row";
    seen.insert(key);
    for(const std::string& counter : found->second)
    {
      ASSERT_TRUE(row.contains(counter)) << counter;
      EXPECT_TRUE(finite_number(row[counter])) << counter;
      EXPECT_GE(row[counter].get<double>(), 0.) << counter;
    }
    if(row.contains("peak_MB")) EXPECT_TRUE(finite_number(row["peak_MB"]));
    if(key.rfind("BM_iteration/", 0) == 0 && key.find("/mpm_") != std::string::npos)
    {
      EXPECT_GT(row["vertices"].get<double>(), 1000.);
      // The phase of the global step that the variant has took some time.
      const std::string main_phase = key.find("mpm_direct") != std::string::npos ? "direct_ms" : "schur_ms";
      EXPECT_GT(row[main_phase].get<double>(), 0.);
      if(key.find("mpm_schur") != std::string::npos) EXPECT_GT(row["back_substitution_ms"].get<double>(), 0.);
    }
  }
  for(const auto& [key, counters] : expected) EXPECT_TRUE(seen.count(key)) << "missing row " << key;
#endif
}
