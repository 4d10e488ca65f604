// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_EMBEDDING_CLUSTER_H
#define CGAL_MPM_INTERNAL_EMBEDDING_CLUSTER_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>
#include <Eigen/SVD>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {
namespace embedding {

using Sparse = Eigen::SparseMatrix<double>;

/// Closest rotation (no reflection) to a 3x3 matrix, maximizing `<R, k>`.
inline Eigen::Matrix3d closest_rotation(const Eigen::Matrix3d& k)
{
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(k, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  if((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0) d(2, 2) = -1;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

/// An edge of a cluster (its points `i`, `j`) with its stiffness.
struct Weighted_edge
{
  int i, j;
  double w;
};

/// A cluster of the embedding problem as the solver keeps it.
struct Cluster_data
{
  std::string name;
  std::vector<int> vertices;
  std::vector<Weighted_edge> edges;   // weights include sigma_sub^-2 and the blend
  Sparse laplacian;                   // local, n_c x n_c
  Point_matrix mean;
  std::vector<Point_matrix> modes;    // n_c x 3 each
  Eigen::VectorXd prior;              // 1 / (4 sigma_k^2)
  Point_matrix laplacian_mean;        // L M
  std::vector<Point_matrix> laplacian_modes; // L B_k
  int offset = 0;                     // of its coordinates in the stacked vector
  int number_of_modes() const { return static_cast<int>(modes.size()); }
};

/// The cluster's rows `local` placed in a matrix over all `n` vertices, zero elsewhere.
inline Eigen::MatrixXd scatter(const Cluster_data& c, const Point_matrix& local, int n)
{
  Eigen::MatrixXd global = Eigen::MatrixXd::Zero(n, 3);
  for(std::size_t i = 0; i < c.vertices.size(); ++i) global.row(c.vertices[i]) += local.row(i);
  return global;
}

/// The rows of the cluster's vertices in `global`.
inline Eigen::MatrixXd gather(const Cluster_data& c, const Eigen::MatrixXd& global)
{
  Eigen::MatrixXd local(c.vertices.size(), global.cols());
  for(std::size_t i = 0; i < c.vertices.size(); ++i) local.row(i) = global.row(c.vertices[i]);
  return local;
}

/// `<a, b^T>`: the trace of `a b`.
inline double trace_product(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  return (a.array() * b.transpose().array()).sum();
}

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
