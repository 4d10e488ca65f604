// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_VERTEX_NORMALS_H
#define CGAL_MPM_INTERNAL_VERTEX_NORMALS_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Geometry>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// Unit vertex normals, one row per point: the normalized sum of the area
// vectors of the vertex's triangles (zero at a vertex in no triangle, or
// where they cancel). CGAL's PMP::compute_vertex_normals() is not used: it
// needs a halfedge mesh, which segments and part shapes need not be, and it
// takes the most visible normal (or sine weights), which moves the
// correspondence results computed with area weights.
inline Point_matrix area_weighted_vertex_normals(const Point_matrix& points, const std::vector<Triangle>& triangles)
{
  Point_matrix n = Point_matrix::Zero(points.rows(), 3);
  for(const Triangle& t : triangles)
  {
    const Eigen::RowVector3d a = (points.row(t[1]) - points.row(t[0])).cross(points.row(t[2]) - points.row(t[0]));
    for(int v : t) n.row(v) += a;
  }
  // Normalized as a contiguous vector: the norm of a row of the column-major
  // matrix sums its squares in another order, and the correspondence moves
  // with that last bit.
  for(Eigen::Index v = 0; v < n.rows(); ++v)
  {
    const Eigen::Vector3d sum = n.row(v).transpose();
    if(sum.norm() > 0.) n.row(v) = sum.normalized().transpose();
  }
  return n;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
