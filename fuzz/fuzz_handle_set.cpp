// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: parse_handles() on arbitrary text, against a rest mesh
// of 16 vertices.
#include "fuzz_common.h"

#include <CGAL/MPM/Solver/Handle_set.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const CGAL::MPM::Point_matrix rest = [] {
    CGAL::MPM::Point_matrix p(16, 3);
    for(int i = 0; i < 16; ++i) p.row(i) << i % 4, i / 4, 0.25 * i;
    return p;
  }();
  const std::string text = mpm_fuzz::as_string(data, size);
  mpm_fuzz::expect_input_errors_only([&] {
    const CGAL::MPM::Handle_set h = CGAL::MPM::parse_handles(text, "fuzz.json", rest);
    CGAL::MPM::validate_handles(h, int(rest.rows()), "fuzz.json");
    (void)CGAL::MPM::parse_handles(CGAL::MPM::handles_to_json(h), "fuzz round trip", rest);
  });
  return 0;
}
