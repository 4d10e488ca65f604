// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Running the `mpm` tool from a test: shell quoting, the run and its output.
#ifndef CGAL_MPM_TEST_TOOL_TEST_SUPPORT_H
#define CGAL_MPM_TEST_TOOL_TEST_SUPPORT_H

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace mpm_test {

struct Run_result
{
  int status = -1; // exit code, or -1 when the tool did not exit normally
  std::string out, err;

  std::vector<std::string> err_lines() const
  {
    std::vector<std::string> lines;
    std::istringstream in(err);
    for(std::string l; std::getline(in, l);)
      if(!l.empty()) lines.push_back(l);
    return lines;
  }
};

inline std::string slurp(const std::filesystem::path& p)
{
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string quote(const std::string& s)
{
  std::string r = "'";
  for(char c : s) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return r + "'";
}

// Runs `mpm ARGS` (ARGS already shell-quoted where needed) with its output
// captured in files of `where`, standard input read from `input` and
// `environment` (`NAME=value ...`, quoted) set.
inline Run_result run_tool(const std::filesystem::path& where, const std::string& arguments,
                           const std::string& input = "/dev/null", const std::string& environment = "")
{
  const std::filesystem::path out = where / "stdout.txt", err = where / "stderr.txt";
  const std::string command = environment + " " + quote(MPM_TOOL_PATH) + " " + arguments + " >" +
                              quote(out.string()) + " 2>" + quote(err.string()) + " <" + quote(input);
  const int raw = std::system(command.c_str());
  Run_result r;
  r.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

} // namespace mpm_test

#endif
