// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_FARTHEST_POINT_SAMPLING_H
#define CGAL_MPM_INTERNAL_FARTHEST_POINT_SAMPLING_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <functional>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// Greedy farthest-point sampling of the rows of `points`, returning the
// picks in order. `squared_distance` holds each point's squared distance
// to what is placed already (infinity, or the distance to fixed centres)
// and is kept up to date. `first`, unless -1, is the first pick; then the
// point of `eligible` (all when empty) farthest from everything placed,
// ties to the lowest index, never a point twice, until there are `count`
// picks or the farthest is no farther than `min_squared_distance`.
// `nearest_pick`, when given, receives for each point the index among the
// picks of its nearest pick, where that is nearer than its start distance.
std::vector<int> farthest_point_sampling(const Point_matrix& points, int count, int first,
                                         Eigen::VectorXd& squared_distance,
                                         const std::function<bool(int)>& eligible = {},
                                         double min_squared_distance = -1.,
                                         std::vector<int>* nearest_pick = nullptr);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
