// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm symmetrize MODEL -o OUT`: pulls every instance of a part type (and
// every pair geometry of a rule) toward the same shape.
#include "editing_common.h"

#include <CGAL/MPM/Editing/Editing.h>

#include <cmath>

namespace mpm {

Command make_symmetrize_command()
{
  const CGAL::MPM::Symmetrization_options defaults;
  Editing_command e;
  e.name = "symmetrize";
  e.summary = "make the instances of each part type alike (partial symmetrization)";
  e.synopsis = "[--relative-sigma S]";
  e.description =
    "Partial symmetrization: every instance of a part type, and every pair geometry\n"
    "of a docking rule, is attracted to the mean shape of its space with a small\n"
    "isotropic deviation (--relative-sigma times the space's largest learned one);\n"
    "the placement of the parts is kept. Types with a single instance keep their\n"
    "shape. Optional handles hold chosen vertices in place or move them.";
  e.done = "Symmetrized";
  e.options = {
    {"relative-sigma", 0, Value_kind::real, "S", format_number(defaults.relative_sigma),
     "deviation allowed from the mean, relative to the largest learned one", 0, HUGE_VAL, true},
  };
  e.make_problem = [](const Args& args, const CGAL::MPM::Morphable_part_model& model, int example, Json& settings) {
    CGAL::MPM::Symmetrization_options options;
    options.relative_sigma = args.real("relative-sigma", options.relative_sigma);
    settings["relative_sigma"] = options.relative_sigma;
    return CGAL::MPM::make_symmetrization_problem(model, example, options);
  };
  return make_editing_command(e);
}

} // namespace mpm
