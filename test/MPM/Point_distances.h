// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The distances between point sets that the tests assert on, in one place.
#ifndef MPM_TEST_POINT_DISTANCES_H
#define MPM_TEST_POINT_DISTANCES_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <cmath>

namespace mpm_test {

inline double diagonal(const CGAL::MPM::Point_matrix& p) { return CGAL::MPM::internal::bounding_box_diagonal(p); }

// The largest distance between corresponding rows.
inline double max_distance(const CGAL::MPM::Point_matrix& a, const CGAL::MPM::Point_matrix& b)
{
  return (a - b).rowwise().norm().maxCoeff();
}

// The root mean square of the distances between corresponding rows.
inline double rms_distance(const CGAL::MPM::Point_matrix& a, const CGAL::MPM::Point_matrix& b)
{
  return std::sqrt((a - b).rowwise().squaredNorm().mean());
}

} // namespace mpm_test

#endif
