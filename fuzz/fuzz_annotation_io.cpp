// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: parse_annotation() on arbitrary text.
#include "fuzz_common.h"

#include <CGAL/MPM/IO/Annotation_io.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text = mpm_fuzz::as_string(data, size);
  mpm_fuzz::expect_input_errors_only([&] {
    const CGAL::MPM::Annotation a = CGAL::MPM::parse_annotation(text, "fuzz.json");
    // What was accepted must write and read back.
    (void)CGAL::MPM::parse_annotation(CGAL::MPM::annotation_to_json(a), "fuzz round trip");
  });
  return 0;
}
