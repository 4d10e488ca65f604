// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_COTANGENT_WEIGHTS_H
#define CGAL_MPM_INTERNAL_COTANGENT_WEIGHTS_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/SparseCore>

#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

/// The cotangent weight of each edge `(i, j)`, `i < j`, of `triangles` over
/// `points`: half the sum of the cotangents of the angles opposite the edge.
/// The one clamping rule of the package, shared by the embedding solver and
/// the Laplacian baseline: each cotangent is bounded above as CGAL's clamped
/// cotangent bounds it (cosine 0.999), a non-finite one counts as zero, and
/// a weight below 1% of the mean positive weight is raised to it.
std::map<std::pair<int, int>, double> cotangent_weights(const Point_matrix& points,
                                                        const std::vector<Triangle>& triangles);

/// The Laplacian `L(i,j) = -w_ij`, `L(i,i) = sum_j w_ij` (`n x n`) of the
/// edge weights `weights` (keys `i < j`).
Eigen::SparseMatrix<double> edge_weight_laplacian(const std::map<std::pair<int, int>, double>& weights, int n);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
