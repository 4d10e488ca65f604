// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "model_data.h"

#include "arrays.h"

#include <pybind11/stl.h>

namespace mpm_python {

using namespace CGAL::MPM;

py::dict motion_dict(const Rigid_motion& motion)
{
  return py::dict(py::arg("rotation") = matrix_array(motion.rotation),
                  py::arg("translation") = vector_array(motion.translation));
}

py::dict shape_space_dict(const Shape_space& space)
{
  py::list motions;
  for(const Rigid_motion& m : space.instance_motions) motions.append(motion_dict(m));
  return py::dict(py::arg("mean") = points_array(Point_matrix(space.mean)),
                  py::arg("modes") = matrix_array(space.modes), py::arg("sigmas") = vector_array(space.sigmas),
                  py::arg("variances") = vector_array(space.variances),
                  py::arg("instance_coordinates") = matrix_array(space.instance_coordinates),
                  py::arg("instance_motions") = motions,
                  py::arg("instance_residuals") = double_array(space.instance_residuals));
}

namespace {

std::string kind_name(Docking_kind kind) { return kind == Docking_kind::boundary ? "boundary" : "generalized"; }

py::dict site_ref_dict(const Morphable_part_model& model, const Site_ref& site)
{
  return py::dict(py::arg("type") = model.types.at(site.type).name, py::arg("type_index") = site.type,
                  py::arg("site") = site.site);
}

} // namespace

py::dict part_type_dict(const Part_type& type)
{
  py::list sites;
  for(const Docking_site& s : type.sites)
    sites.append(py::dict(py::arg("kind") = kind_name(s.kind), py::arg("vertices") = int_array(std::vector<int>(s.vertices))));
  py::dict d = shape_space_dict(type.space);
  d["name"] = type.name;
  d["vertices"] = type.number_of_vertices;
  d["triangles"] = triangles_array(std::vector<Triangle>(type.triangles));
  d["sites"] = sites;
  d["modes_kept"] = type.space.number_of_modes();
  d["instances"] = type.space.number_of_instances();
  return d;
}

py::dict docking_rule_dict(const Morphable_part_model& model, const Docking_rule& rule)
{
  std::vector<int> seam;
  for(const auto& [a, b] : rule.seam) seam.insert(seam.end(), {a, b});
  py::array seam_array = int_array(std::move(seam)).attr("reshape")(-1, 2);
  py::dict d = shape_space_dict(rule.space);
  d["first"] = site_ref_dict(model, rule.first);
  d["second"] = site_ref_dict(model, rule.second);
  d["kind"] = kind_name(rule.kind);
  d["seam"] = seam_array;
  d["merged_seam"] = rule.merged_seam.size();
  d["points"] = rule.points.size();
  d["modes_kept"] = rule.space.number_of_modes();
  d["instances"] = rule.space.number_of_instances();
  return d;
}

py::dict parameters_dict(const Model_parameters& p)
{
  return py::dict(py::arg("sigma_sub") = p.sigma_sub, py::arg("sigma_bound") = p.sigma_bound,
                  py::arg("docking_radius") = p.docking_radius, py::arg("modes") = p.modes,
                  py::arg("explained_variance") = p.explained_variance);
}

} // namespace mpm_python
