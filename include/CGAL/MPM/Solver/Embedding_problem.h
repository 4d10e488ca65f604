// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_EMBEDDING_PROBLEM_H
#define CGAL_MPM_EMBEDDING_PROBLEM_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Part_type.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// One energy term with its own rotation: a part instance or a pair
/// geometry. Its points are vertices of the embedded mesh; its target shape
/// is `mean + sum_k lambda_k modes_k` (in any frame: a rotation is fitted).
struct Cluster
{
  std::string name;               ///< names the cluster in reports and errors (`part 3 (proximal)`)
  std::vector<int> vertices;      ///< cluster point -> mesh vertex
  std::vector<Triangle> triangles; ///< triangles over cluster points (for cotangent weights)
  std::vector<Cluster_edge> edges; ///< edges over cluster points
  Point_matrix mean;              ///< n_c x 3 target shape at zero coordinates
  Eigen::MatrixXd modes;          ///< 3 n_c x d modes (point by point layout)
  Eigen::VectorXd sigmas;         ///< d standard deviations of the coordinates
  /// Cluster points where the blend weight starts: the weight of a point at
  /// edge-graph distance d from the nearest of them is 1 - exp(-d^2/sigma_bound^2),
  /// so the cluster's attraction fades out toward them. Empty: weight 1.
  std::vector<int> border;
  double sigma_bound = -1.;       ///< blend width; negative: a third of the mean's diameter
};

/// \ingroup PkgMPMRef
/// What the embedding solver minimizes: the clusters over a mesh of
/// `rest.rows()` vertices, whose positions start at `rest`. Pieces of the
/// mesh that no handle reaches are anchored weakly to `rest` (the energy is
/// blind to their translation otherwise).
struct Embedding_problem
{
  Indexed_mesh mesh;              ///< connectivity and rest (initial) positions
  std::vector<Cluster> clusters;  ///< energy terms
  double sigma_sub = 1.;          ///< flexibility outside the subspaces
  /// Pairs of clusters of the same shape space whose coordinates the
  /// coupling term `Embedding_options::coupling_weight` pulls together
  /// (neighbouring same-type parts, for locally symmetric edits).
  std::vector<std::pair<int, int>> coupled_clusters;
};

} // namespace MPM
} // namespace CGAL

#endif
