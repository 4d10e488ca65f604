// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_SHAPE_EXAGGERATION_H
#define CGAL_MPM_INTERNAL_SHAPE_EXAGGERATION_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// How far the points of `shape` move when its deviation from `mean` (same
// triangles, in correspondence) is scaled by `factor`, measured as local
// deformations: each vertex's best linear map from the mean's neighbourhood
// to the shape's is split into a rotation and a stretch, the rotation angle
// and the stretch's logarithm are scaled by `factor`, and the surface is
// integrated back (a Poisson solve). Scaling point offsets instead shrinks
// and folds a part whose deviation is a bend: doubling the offsets of a
// segment bent by 40 degrees flattens the inside of the bend. Returns
// exaggerated minus non-exaggerated positions (n x 3), zero for factor 1,
// up to a rigid motion.
Point_matrix exaggeration_offsets(const Point_matrix& mean, const Point_matrix& shape,
                                  const std::vector<Triangle>& triangles, double factor);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
