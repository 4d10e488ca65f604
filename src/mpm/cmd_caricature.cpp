// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm caricature MODEL --factor F -o OUT`: exaggerates (F > 1) or inverts
// (F < 0) how each part differs from its type's mean.
#include "editing_common.h"

#include <CGAL/MPM/Editing/Editing.h>

namespace mpm {

Command make_caricature_command()
{
  Editing_command e;
  e.name = "caricature";
  e.summary = "exaggerate (factor > 1) or invert (factor < 0) each part's shape";
  e.synopsis = "--factor F";
  e.description =
    "Caricature and anti-shape: each instance's shape coordinates are scaled away\n"
    "from its type's mean by --factor (and likewise for the pair geometry of each\n"
    "docking); the part of its shape outside the learned subspace is kept. Factor 1\n"
    "gives the input back, 0 the type mean within the subspace, 2 a caricature and\n"
    "-1 the anti-shape.";
  e.done = "Caricatured";
  e.required = {"factor"};
  // Any finite factor is meaningful, 0 included; the parser refuses non-finite ones.
  e.options = {
    {"factor", 0, Value_kind::real, "F", "", "scale of each part's offset from its type's mean (required)"},
  };
  e.make_problem = [](const Args& args, const CGAL::MPM::Morphable_part_model& model, int example, Json& settings) {
    const double factor = args.real("factor", 1.);
    settings["factor"] = factor;
    return CGAL::MPM::make_caricature_problem(model, factor, example);
  };
  return make_editing_command(e);
}

} // namespace mpm
