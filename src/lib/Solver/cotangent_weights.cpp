// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Cotangent_weights.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Weights/utils.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;

Kernel::Point_3 point(const Point_matrix& p, int i) { return Kernel::Point_3(p(i, 0), p(i, 1), p(i, 2)); }

} // namespace

std::map<std::pair<int, int>, double> cotangent_weights(const Point_matrix& points,
                                                        const std::vector<Triangle>& triangles)
{
  // Large cotangents are bounded as in CGAL's ARAP deformation: a sliver of
  // a scanned mesh (cotangent 4e14 on a PSB octopus) otherwise drowned the
  // whole system in rounding, and the solver's energy rose from the rest
  // pose. Negative sums are raised rather than zeroed so that the matrix
  // stays positive definite on each piece and no edge is left without
  // stiffness.
  const double largest_cotangent = 0.999 / std::sqrt(1. - 0.999 * 0.999);
  std::map<std::pair<int, int>, double> weights;
  for(const Triangle& t : triangles)
    for(int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3], o = t[(k + 2) % 3];
      if(a == b) continue;
      const double cot = CGAL::Weights::cotangent(point(points, a), point(points, o), point(points, b));
      weights[{std::min(a, b), std::max(a, b)}] += std::isfinite(cot) ? 0.5 * std::min(cot, largest_cotangent) : 0.;
    }
  double positive_sum = 0.;
  int positive_count = 0;
  for(const auto& [edge, w] : weights)
    if(w > 0)
    {
      positive_sum += w;
      ++positive_count;
    }
  const double floor_weight = 1e-2 * (positive_count > 0 ? positive_sum / positive_count : 1.);
  for(auto& [edge, w] : weights) w = std::max(w, floor_weight);
  return weights;
}

Eigen::SparseMatrix<double> edge_weight_laplacian(const std::map<std::pair<int, int>, double>& weights, int n)
{
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<double> diagonal(std::size_t(n), 0.);
  for(const auto& [edge, w] : weights)
  {
    triplets.emplace_back(edge.first, edge.second, -w);
    triplets.emplace_back(edge.second, edge.first, -w);
    diagonal[std::size_t(edge.first)] += w;
    diagonal[std::size_t(edge.second)] += w;
  }
  for(int i = 0; i < n; ++i)
    if(diagonal[std::size_t(i)] != 0.) triplets.emplace_back(i, i, diagonal[std::size_t(i)]);
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(triplets.begin(), triplets.end());
  return laplacian;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
