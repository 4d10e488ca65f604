// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_CURVE_SKELETON_H
#define CGAL_MPM_INTERNAL_CURVE_SKELETON_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// CGAL's mean curvature flow skeleton of a closed, connected triangle mesh,
// as plain arrays: node positions, the skeleton graph, and the node each
// mesh vertex contracted to (the skeleton point a limb's surface stands for).
struct Curve_skeleton
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> neighbours;
  std::vector<int> node_of_vertex; // -1 for a vertex no node stands for
};

// Throws Input_error(source, ...) when CGAL's skeletonization fails or
// leaves no edge (a mesh too coarse or degenerate to have an axis).
Curve_skeleton curve_skeleton(const Indexed_mesh& mesh, const std::string& source);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
