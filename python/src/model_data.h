// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A learned model as plain Python data (dicts, lists, numpy arrays), for
// inspection: what `Model.types`, `Model.rules` and the fits return.
#ifndef CGAL_MPM_PYTHON_MODEL_DATA_H
#define CGAL_MPM_PYTHON_MODEL_DATA_H

#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <pybind11/pybind11.h>

namespace mpm_python {

namespace py = pybind11;

/// {"rotation": 3 x 3, "translation": 3}.
py::dict motion_dict(const CGAL::MPM::Rigid_motion& motion);
/// A shape space's mean, modes, sigmas, variances and training instances.
py::dict shape_space_dict(const CGAL::MPM::Shape_space& space);
/// A part type: name, connectivity, docking sites and shape space.
py::dict part_type_dict(const CGAL::MPM::Part_type& type);
/// A docking rule: the two sites (type names and site indices), kind, seam
/// and the pair geometry's shape space.
py::dict docking_rule_dict(const CGAL::MPM::Morphable_part_model& model, const CGAL::MPM::Docking_rule& rule);
/// The model's parameters.
py::dict parameters_dict(const CGAL::MPM::Model_parameters& parameters);

} // namespace mpm_python

#endif
