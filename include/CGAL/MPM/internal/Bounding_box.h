// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_BOUNDING_BOX_H
#define CGAL_MPM_INTERNAL_BOUNDING_BOX_H

#include <CGAL/MPM/Indexed_mesh.h>

namespace CGAL {
namespace MPM {
namespace internal {

// The length of the diagonal of the axis-aligned bounding box of the rows
// of `points`, 0 when there are none: the scale that tolerances, radii and
// reported errors are measured in.
inline double bounding_box_diagonal(const Point_matrix& points)
{
  if(points.rows() == 0) return 0.;
  const Eigen::RowVector3d extent = points.colwise().maxCoeff() - points.colwise().minCoeff();
  // Squares of extents below about 1e-154 underflow, so a mesh at 1e-200
  // would get a diagonal of 0; stableNorm() scales first. It is not used
  // throughout because it rounds differently, and learning on some real
  // meshes changes with the last bit of this length.
  const double diagonal = extent.norm();
  return diagonal > 1e-140 ? diagonal : extent.stableNorm();
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
