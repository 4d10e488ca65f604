// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Small runs of the quality programs (bench/quality_*.cpp): their CSV has
// every row it should and only finite values. No timing is asserted.
#include "Io_test_support.h"

#include <CGAL/MPM/Baselines/Deformation_method.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Rows = std::vector<std::map<std::string, std::string>>;

Rows read_csv(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> header;
  if(std::getline(in, line))
  {
    std::stringstream s(line);
    for(std::string cell; std::getline(s, cell, ',');) header.push_back(cell);
  }
  Rows rows;
  while(std::getline(in, line))
  {
    std::stringstream s(line);
    std::map<std::string, std::string> row;
    std::size_t i = 0;
    for(std::string cell; std::getline(s, cell, ','); ++i) row[i < header.size() ? header[i] : "extra"] = cell;
    EXPECT_EQ(i, header.size()) << line;
    rows.push_back(row);
  }
  return rows;
}

bool finite_number(const std::string& text)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return !text.empty() && end != nullptr && *end == '\0' && std::isfinite(v);
}

#ifdef MPM_BENCH_DIR
int run(const std::string& program, const std::string& csv)
{
  const std::string command = std::string("\"") + MPM_BENCH_DIR + "/" + program +
                              "\" --vertices 1500 --poses 1 --counts 4 --csv \"" + csv + "\" 2>/dev/null";
  return std::system(command.c_str());
}
#endif

} // namespace

TEST(Quality_programs, reconstruction_csv_is_complete_and_finite)
{
#ifndef MPM_BENCH_DIR
  GTEST_SKIP() << "the quality programs are not built (MPM_BUILD_BENCHMARKS off)";
#else
  mpm_test::Scratch_directory scratch;
  const std::string csv = (scratch.path() / "reconstruction.csv").string();
  ASSERT_EQ(run("quality_reconstruction", csv), 0);
  const Rows rows = read_csv(csv);
  const auto families = CGAL::MPM::all_synthetic_families();
  const auto methods = CGAL::MPM::deformation_method_names();
  // Per family: one pose, handle sets "4" and "per-part", each method and the rest pose.
  EXPECT_EQ(rows.size(), families.size() * 2 * (methods.size() + 1));
  std::set<std::string> seen;
  for(const auto& row : rows)
  {
    seen.insert(row.at("family") + "/" + row.at("handles") + "/" + row.at("method"));
    for(const char* column : {"rms_error", "max_error", "detail_error", "handle_rms", "time_ms"})
      EXPECT_TRUE(finite_number(row.at(column))) << row.at("family") << " " << row.at("method") << " " << column
                                                 << " = " << row.at(column);
  }
  for(const auto family : families)
    for(const char* handles : {"4", "per-part"})
    {
      EXPECT_TRUE(seen.count(CGAL::MPM::family_name(family) + "/" + handles + "/rest"));
      for(const std::string& method : methods)
        EXPECT_TRUE(seen.count(CGAL::MPM::family_name(family) + "/" + handles + "/" + method))
          << CGAL::MPM::family_name(family) << " " << handles << " " << method;
    }
#endif
}

TEST(Quality_programs, shape_space_csv_is_complete_and_finite)
{
#ifndef MPM_BENCH_DIR
  GTEST_SKIP() << "the quality programs are not built (MPM_BUILD_BENCHMARKS off)";
#else
  mpm_test::Scratch_directory scratch;
  const std::string csv = (scratch.path() / "shape_space.csv").string();
  ASSERT_EQ(run("quality_shape_space", csv), 0);
  const Rows rows = read_csv(csv);
  ASSERT_FALSE(rows.empty());
  std::map<std::string, std::set<std::string>> measures; // per family/type
  std::set<std::string> families;
  for(const auto& row : rows)
  {
    families.insert(row.at("family"));
    measures[row.at("family") + "/" + row.at("type")].insert(row.at("measure"));
    EXPECT_TRUE(finite_number(row.at("value"))) << row.at("family") << " " << row.at("type") << " "
                                                << row.at("measure");
    const double value = std::strtod(row.at("value").c_str(), nullptr);
    EXPECT_GE(value, 0.);
    if(row.at("measure") == "compactness") EXPECT_LE(value, 1. + 1e-12);
  }
  for(const auto family : CGAL::MPM::all_synthetic_families())
    EXPECT_TRUE(families.count(CGAL::MPM::family_name(family))) << CGAL::MPM::family_name(family);
  // Leave-one-out (generalization) needs three instances.
  for(const auto& row : rows)
    if(std::atoi(row.at("instances").c_str()) >= 3)
      EXPECT_EQ(measures[row.at("family") + "/" + row.at("type")].size(), 3u) << row.at("type");
    else
      EXPECT_EQ(measures[row.at("family") + "/" + row.at("type")].size(), 2u) << row.at("type");
#endif
}
