// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Kept in its own translation unit: CGAL's skeletonization is a heavy
// template that only joint cutting needs.
#include <CGAL/MPM/internal/Curve_skeleton.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <CGAL/extract_mean_curvature_flow_skeleton.h>

#include <exception>

namespace CGAL {
namespace MPM {
namespace internal {

Curve_skeleton curve_skeleton(const Indexed_mesh& mesh, const std::string& source)
{
  using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<Indexed_surface_mesh>;
  const Indexed_surface_mesh surface = to_surface_mesh(mesh, source, "joint cutting");
  Skeletonization::Skeleton skeleton;
  try {
    CGAL::extract_mean_curvature_flow_skeleton(surface, skeleton);
  } catch(const std::exception& e) {
    throw Input_error(source, "curve skeleton", std::string("CGAL's skeletonization failed: ") + e.what());
  }
  Curve_skeleton r;
  r.node_of_vertex.assign(std::size_t(mesh.number_of_vertices()), -1);
  for(auto node : CGAL::make_range(boost::vertices(skeleton))) {
    const auto& p = skeleton[node].point;
    r.points.emplace_back(p.x(), p.y(), p.z());
    r.neighbours.emplace_back();
    for(auto v : skeleton[node].vertices) r.node_of_vertex[std::size_t(v)] = int(node);
  }
  for(auto e : CGAL::make_range(boost::edges(skeleton))) {
    const int a = int(boost::source(e, skeleton)), b = int(boost::target(e, skeleton));
    r.neighbours[std::size_t(a)].push_back(b);
    r.neighbours[std::size_t(b)].push_back(a);
  }
  if(boost::num_edges(skeleton) == 0)
    throw Input_error(source, "curve skeleton",
                      "has no edge: the mesh is too coarse or too compact to have a limb axis");
  return r;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
