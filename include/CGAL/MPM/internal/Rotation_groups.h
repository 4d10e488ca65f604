// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_ROTATION_GROUPS_H
#define CGAL_MPM_INTERNAL_ROTATION_GROUPS_H

#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/internal/Embedding_cluster.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {
namespace embedding {

/// The rotation fit of the local step as one group operator (as libigl's
/// `arap` fits its rotations): a group is a set of cluster edges sharing one
/// rotation, fitted to the covariance `V_g^T L_g M~` of the group's edge
/// Laplacian `L_g` between the positions `V` and the target shape
/// `M~ = M + sum_k lambda_k B_k`. A cluster is one group with
/// `Rotations::per_cluster`; each cluster point's incident edges are one
/// with `Rotations::per_vertex`.
class Rotation_groups
{
public:
  /// No groups.
  Rotation_groups() = default;
  /// The groups of `clusters` for `kind`, cluster by cluster; with one
  /// rotation per cluster, group `c` is cluster `c`.
  Rotation_groups(const std::vector<Cluster_data>& clusters, Rotations kind);
  /// The number of groups.
  int size() const { return static_cast<int>(groups_.size()); }
  /// Fits the rotations of all groups (`rotations`, one per group) to
  /// `positions` and the targets at the stacked `coordinates`.
  void fit(const std::vector<Cluster_data>& clusters, const Point_matrix& positions,
           const Eigen::VectorXd& coordinates, std::vector<Eigen::Matrix3d>& rotations) const;
  /// The linear map the target vector of edge `e` of cluster `c` goes
  /// through: the mean rotation of the groups holding the edge.
  Eigen::Matrix3d edge_transform(int c, const Weighted_edge& e, const std::vector<Eigen::Matrix3d>& rotations) const;
  /// Whether every edge of a cluster goes through the same map (one group
  /// per cluster), `cluster_transform()`.
  bool per_cluster() const { return !per_vertex_; }
  /// With `per_cluster()`, the map of every edge of cluster `c`.
  const Eigen::Matrix3d& cluster_transform(int c, const std::vector<Eigen::Matrix3d>& rotations) const
  {
    return rotations[std::size_t(first_group_[std::size_t(c)])];
  }

private:
  struct Group
  {
    int cluster = 0;
    std::vector<int> support;                  // the cluster points of its edges, none for the whole cluster
    Point_matrix laplacian_mean;               // L_g M on the support
    std::vector<Point_matrix> laplacian_modes; // L_g B_k on the support
  };
  std::vector<Group> groups_;
  std::vector<int> first_group_; // per cluster
  bool per_vertex_ = false;
};

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
