// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Command-line handling shared by the quality programs (quality_*.cpp):
// plain programs that print CSV, not Google Benchmark timings.
#ifndef CGAL_MPM_BENCH_QUALITY_COMMON_H
#define CGAL_MPM_BENCH_QUALITY_COMMON_H

#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace mpm_quality {

/// `--name value` pairs; every option takes a value. Unknown options are an error.
class Options
{
public:
  Options(int argc, char** argv, const std::map<std::string, std::string>& defaults, const std::string& usage)
    : values_(defaults)
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      if(a == "--help" || a == "-h")
      {
        std::cout << usage;
        std::exit(0);
      }
      if(a.size() < 3 || a.compare(0, 2, "--") != 0 || values_.count(a.substr(2)) == 0 || i + 1 >= argc)
      {
        std::cerr << "error: bad argument '" << a << "'\n" << usage;
        std::exit(2);
      }
      values_[a.substr(2)] = argv[++i];
    }
  }
  std::string text(const std::string& name) const { return values_.at(name); }
  int integer(const std::string& name) const { return std::atoi(values_.at(name).c_str()); }
  std::vector<std::string> list(const std::string& name) const
  {
    std::vector<std::string> items;
    std::stringstream s(values_.at(name));
    for(std::string item; std::getline(s, item, ',');)
      if(!item.empty()) items.push_back(item);
    return items;
  }
  std::vector<int> integers(const std::string& name) const
  {
    std::vector<int> r;
    for(const std::string& s : list(name)) r.push_back(std::atoi(s.c_str()));
    return r;
  }
  std::vector<CGAL::MPM::Synthetic_family> families() const
  {
    if(text("families") == "all") return CGAL::MPM::all_synthetic_families();
    std::vector<CGAL::MPM::Synthetic_family> r;
    for(const std::string& name : list("families")) r.push_back(CGAL::MPM::parse_family(name));
    return r;
  }
  /// The meshes named by `--meshes`, else every NAME.off in `--data`, sorted.
  std::vector<std::string> meshes() const
  {
    std::vector<std::string> names = list("meshes");
    if(names.empty())
      for(const auto& entry : std::filesystem::directory_iterator(text("data")))
        if(entry.path().extension() == ".off") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
  }

private:
  std::map<std::string, std::string> values_;
};

/// Stdout, or the file given by `--csv` (flushed row by row).
class Csv_output
{
public:
  explicit Csv_output(const std::string& path)
  {
    if(!path.empty() && path != "-")
    {
      file_ = std::make_unique<std::ofstream>(path);
      if(!*file_)
      {
        std::cerr << "error: cannot write " << path << "\n";
        std::exit(1);
      }
    }
  }
  std::ostream& stream() { return file_ ? *file_ : std::cout; }

private:
  std::unique_ptr<std::ofstream> file_;
};

/// `%.6g`, NaN and infinities spelled `nan`, `inf`.
inline std::string number(double v)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

} // namespace mpm_quality

#endif
