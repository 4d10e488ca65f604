// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Shape_exaggeration.h>
#include <CGAL/MPM/internal/Vertex_normals.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <set>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Edge_set = std::set<std::pair<int, int>>;

Edge_set edges_of(const std::vector<Triangle>& triangles)
{
  Edge_set edges;
  for(const Triangle& t : triangles)
    for(int k = 0; k < 3; ++k) edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  return edges;
}

// Per vertex, the linear map that best takes the mean's edges at the vertex
// (and its normal, so that the map is defined across the surface) to the
// shape's.
std::vector<Eigen::Matrix3d> local_maps(const Point_matrix& mean, const Point_matrix& shape,
                                        const std::vector<Triangle>& triangles, const Edge_set& edges)
{
  const Eigen::Index n = mean.rows();
  std::vector<Eigen::Matrix3d> cross(n, Eigen::Matrix3d::Zero()), gram(n, Eigen::Matrix3d::Zero());
  std::vector<double> length(n, 0.);
  std::vector<int> degree(n, 0);
  for(const auto& [a, b] : edges)
  {
    const Eigen::Vector3d e = (mean.row(b) - mean.row(a)).transpose(), d = (shape.row(b) - shape.row(a)).transpose();
    for(int v : {a, b})
    {
      cross[v] += d * e.transpose();
      gram[v] += e * e.transpose();
      length[v] += e.norm();
      ++degree[v];
    }
  }
  const Point_matrix mean_normals = area_weighted_vertex_normals(mean, triangles),
                     shape_normals = area_weighted_vertex_normals(shape, triangles);
  std::vector<Eigen::Matrix3d> maps(n, Eigen::Matrix3d::Identity());
  for(Eigen::Index v = 0; v < n; ++v)
  {
    if(degree[v] == 0) continue;
    const double l = length[v] / degree[v];
    const Eigen::Vector3d e = l * mean_normals.row(v).transpose(), d = l * shape_normals.row(v).transpose();
    const Eigen::Matrix3d g = gram[v] + e * e.transpose() + 1e-12 * l * l * Eigen::Matrix3d::Identity();
    maps[v] = (cross[v] + d * e.transpose()) * g.inverse();
  }
  return maps;
}

// The map raised to `factor`: rotation angle times factor, stretch
// eigenvalues to the power factor (a reflected direction stays reflected),
// so that neither turns over however far it is pushed.
Eigen::Matrix3d power(const Eigen::Matrix3d& map, double factor)
{
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(map, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d u = svd.matrixU();
  if((u * svd.matrixV().transpose()).determinant() < 0.) u.col(2) = -u.col(2);
  const Eigen::Matrix3d rotation = u * svd.matrixV().transpose();
  const Eigen::Matrix3d stretch = rotation.transpose() * map;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (stretch + stretch.transpose()));
  Eigen::Vector3d scaled;
  for(int k = 0; k < 3; ++k)
  {
    // A degenerate direction stays bounded under a negative factor.
    const double s = eig.eigenvalues()[k];
    scaled[k] = std::copysign(std::pow(std::clamp(std::abs(s), 1e-3, 1e3), factor), s);
  }
  Eigen::AngleAxisd turn(rotation);
  turn.angle() *= factor;
  return turn.toRotationMatrix() * eig.eigenvectors() * scaled.asDiagonal() * eig.eigenvectors().transpose();
}

// Positions whose edges best follow the averaged maps of their two ends
// applied to the mean's edges, weakly held at `anchor` (which only fixes
// the free translation of each piece).
Point_matrix integrate(const Point_matrix& mean, const std::vector<Eigen::Matrix3d>& maps, const Edge_set& edges,
                       const Point_matrix& anchor)
{
  const Eigen::Index n = mean.rows();
  const double hold = 1e-8;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = hold * anchor;
  for(Eigen::Index v = 0; v < n; ++v) entries.emplace_back(int(v), int(v), hold);
  for(const auto& [a, b] : edges)
  {
    const Eigen::RowVector3d target =
      (0.5 * (maps[a] + maps[b]) * (mean.row(b) - mean.row(a)).transpose()).transpose();
    entries.emplace_back(a, a, 1.);
    entries.emplace_back(b, b, 1.);
    entries.emplace_back(a, b, -1.);
    entries.emplace_back(b, a, -1.);
    rhs.row(b) += target;
    rhs.row(a) -= target;
  }
  Eigen::SparseMatrix<double> system(n, n);
  system.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  return solver.solve(rhs);
}

} // namespace

Point_matrix exaggeration_offsets(const Point_matrix& mean, const Point_matrix& shape,
                                  const std::vector<Triangle>& triangles, double factor)
{
  if(factor == 1.) return Point_matrix::Zero(mean.rows(), 3);
  const Edge_set edges = edges_of(triangles);
  const std::vector<Eigen::Matrix3d> maps = local_maps(mean, shape, triangles, edges);
  std::vector<Eigen::Matrix3d> scaled(maps.size());
  std::transform(maps.begin(), maps.end(), scaled.begin(), [factor](const Eigen::Matrix3d& m) { return power(m, factor); });
  // Both integrations carry the same discretization error, which cancels
  // in the difference; factor 1 is the shape itself up to that error.
  return integrate(mean, scaled, edges, shape) - integrate(mean, maps, edges, shape);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
