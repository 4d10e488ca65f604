// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: parse_part_graph() on arbitrary text, against a model
// learned once from the synthetic hexa-grid (about 300 vertices).
#include "fuzz_common.h"

#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <memory>

namespace {

std::unique_ptr<CGAL::MPM::Morphable_part_model> model;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  CGAL::MPM::Synthetic_options o;
  o.vertices = 300;
  const auto truth = CGAL::MPM::make_synthetic_model(CGAL::MPM::Synthetic_family::hexa_grid, o);
  model = std::make_unique<CGAL::MPM::Morphable_part_model>(
    CGAL::MPM::learn_morphable_part_model(truth.mesh, truth.annotation));
  mpm_fuzz::maybe_write_seed(
    CGAL::MPM::part_graph_to_json(*model, CGAL::MPM::part_graph_of_example(*model, 0)));
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text = mpm_fuzz::as_string(data, size);
  mpm_fuzz::expect_input_errors_only([&] {
    const CGAL::MPM::Part_graph g = CGAL::MPM::parse_part_graph(text, *model, "fuzz.json");
    (void)CGAL::MPM::parse_part_graph(CGAL::MPM::part_graph_to_json(*model, g), *model, "fuzz round trip");
  });
  return 0;
}
