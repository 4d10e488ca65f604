// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cutting at joints from Python: one click per joint, and joints proposed
// from the curve skeleton.
#include "arrays.h"
#include "bindings.h"

#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Cutting/Joint_proposal.h>

#include <pybind11/stl.h>

namespace mpm_python {

namespace {

using namespace CGAL::MPM;

py::dict cutting_dict(Joint_cutting_result&& result)
{
  py::list cuts, skipped;
  for(Joint_cut& c : result.cuts)
    cuts.append(py::dict(py::arg("vertex") = c.vertex, py::arg("path") = int_array(std::move(c.path)),
                         py::arg("length") = c.length, py::arg("limb_radius") = c.limb_radius,
                         py::arg("shift") = c.shift,
                         py::arg("centre") = double_array({c.centre.x(), c.centre.y(), c.centre.z()})));
  for(const Skipped_click& k : result.skipped)
    skipped.append(py::dict(py::arg("vertex") = k.vertex, py::arg("reason") = k.reason));
  return py::dict(py::arg("labels") = int_array(std::move(result.mesh.face_labels)), py::arg("cuts") = cuts,
                  py::arg("skipped") = skipped);
}

Joint_cutting_options joint_options(double feature_weight, double search_range, double snap_band, bool skip_unfound)
{
  Joint_cutting_options options;
  options.feature_weight = feature_weight;
  options.search_range = search_range;
  options.snap_band = snap_band;
  options.skip_unfound = skip_unfound;
  return options;
}

} // namespace

void bind_cutting(py::module_& m)
{
  m.def("cut_at_vertices", [](const py::handle& V, const py::handle& F, const std::vector<int>& vertices,
                              double feature_weight, double search_range, double snap_band, bool skip_unfound) {
    const Indexed_mesh mesh = to_mesh(V, F);
    Joint_cutting_result result;
    {
      py::gil_scoped_release release;
      result = cut_at_vertices(mesh, vertices, joint_options(feature_weight, search_range, snap_band, skip_unfound), "V, F");
    }
    return cutting_dict(std::move(result)); },
        py::arg("V"), py::arg("F"), py::arg("vertices"), py::arg("feature_weight") = 1., py::arg("search_range") = 0.5,
        py::arg("snap_band") = 0.5, py::arg("skip_unfound") = false,
        R"doc(One click per joint: the closed cut around the limb at each vertex.

The mesh must be closed and connected. The limb's axis comes from CGAL's
curve skeleton; the cut is the narrowest small section across it through the
vertex (or within search_range limb radii), then the loop through the vertex
of least crease-weighted length within snap_band limb radii of that section
(0: the section itself), traced so that it settles in the crease. A bad click raises ValueError naming the vertex, unless skip_unfound,
which reports it in "skipped" instead.
Returns {"labels": m int32, "cuts": [{"vertex", "path", "length",
"limb_radius", "shift", "centre"}], "skipped": [{"vertex", "reason"}]}.)doc");

  m.def("cut_at_proposed_joints", [](const py::handle& V, const py::handle& F, double sensitivity,
                                     double feature_weight) {
    const Indexed_mesh mesh = to_mesh(V, F);
    Joint_proposal_options options;
    options.sensitivity = sensitivity;
    options.cutting.feature_weight = feature_weight;
    Joint_proposal proposal;
    { py::gil_scoped_release release; proposal = cut_at_proposed_joints(mesh, options, "V, F"); }
    py::list joints;
    for(const Proposed_joint& j : proposal.joints)
      joints.append(py::dict(py::arg("vertex") = j.vertex, py::arg("limb") = j.limb, py::arg("at_base") = j.at_base,
                             py::arg("strength") = j.strength, py::arg("by_analogy") = j.by_analogy));
    py::dict r = cutting_dict(std::move(proposal.cutting));
    r["limbs"] = proposal.limbs;
    r["joints"] = joints;
    return r; },
        py::arg("V"), py::arg("F"), py::arg("sensitivity") = 0.5, py::arg("feature_weight") = 1.,
        R"doc(Joints proposed automatically: cuts a closed mesh into a body and limb segments.

Limbs are the long branches of CGAL's curve skeleton thinner than the body;
each is cut where it leaves the body and where it narrows, creases or bends
more than the sensitivity (0 to 1; 0: bases only) allows.
Returns the dict of cut_at_vertices with "limbs" (limbs found) and "joints"
([{"vertex", "limb", "at_base", "strength", "by_analogy"}], one per proposal).)doc");
}

} // namespace mpm_python
