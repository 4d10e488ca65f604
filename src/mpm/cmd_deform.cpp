// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm deform MODEL --handles H.json -o OUT`: free-form deformation of a
// training example within the learned shape spaces.
#include "editing_common.h"

#include <CGAL/MPM/Editing/Editing.h>

namespace mpm {

Command make_deform_command()
{
  Editing_command e;
  e.name = "deform";
  e.summary = "drag handles of a training example, staying in the learned shape spaces";
  e.synopsis = "--handles H.json";
  e.description =
    "Free-form deformation: every part and docking keeps its learned modes and\n"
    "deviations but its own rest shape as the mean, so the input is the energy's\n"
    "minimum and the handles pull within the learned space (targets equal to the\n"
    "rest positions give the input back).";
  e.done = "Deformed";
  e.required = {"handles"};
  e.make_problem = [](const Args&, const CGAL::MPM::Morphable_part_model& model, int example, Json&) {
    return CGAL::MPM::make_deformation_problem(model, example);
  };
  return make_editing_command(e);
}

} // namespace mpm
