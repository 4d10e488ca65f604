// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_SCHUR_BLOCKS_H
#define CGAL_MPM_INTERNAL_SCHUR_BLOCKS_H

#include <CGAL/MPM/internal/Embedding_cluster.h>
#include <CGAL/MPM/internal/Vertex_block.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {
namespace embedding {

/// With `Z_c` the rows of a matrix `Z` at cluster c's vertices:
/// `(L_c B_ca)^T Z_c` for every mode a (3 x columns of `Z`) and
/// `Z_c^T L_c M_c` for every cluster c (columns of `Z` x 3).
struct Cluster_products
{
  std::vector<Eigen::MatrixXd> of_mode, of_mean;
};

/// What the Schur and reduced global steps know of the vertex block `A11`:
/// 3x3 blocks of `A11^-1` between the clusters' operands, so that an
/// iteration never touches the vertices. Built for the factored block,
/// corrected for its low-rank update, and completed by the handle terms.
struct Schur_blocks
{
  /// Builds the blocks of the factored block of `block` (its update ignored).
  void build(const std::vector<Cluster_data>& clusters, const std::vector<int>& cluster_of_mode,
             const Eigen::MatrixXd& coupling, const Vertex_block& block);
  /// The blocks of `block` with its current update.
  void update(const std::vector<Cluster_data>& clusters, const Vertex_block& block);
  /// The handle terms, from the right-hand side `b0` and `z = A11^-1 b0`
  /// (the reference; one pass over the vertices).
  void set_handle_terms(const std::vector<Cluster_data>& clusters, const Point_matrix& b0, const Eigen::MatrixXd& z);
  /// The handle terms as affine functions of the weighted handle targets `T`
  /// (k x 3), for one handle set: `b0 = a + S T` with `S` putting row `h` at
  /// vertex `handles[h]`, and `z = A11^-1 a + H T` (`anchor_solution`,
  /// `handle_columns`). A drag then sets its targets with
  /// `set_handle_targets()` without touching the vertices.
  void set_handle_basis(const std::vector<Cluster_data>& clusters, const Point_matrix& anchor_rhs,
                        const Point_matrix& anchor_solution, const std::vector<int>& handles,
                        const Eigen::MatrixXd& handle_columns);
  /// The handle terms of `set_handle_terms()` at the weighted targets `T`,
  /// from the basis of the last `set_handle_basis()`.
  void set_handle_targets(const Eigen::MatrixXd& weighted_targets);

  // H[ck][dl] = (L_c B_ck)^T Q_dl, G[ck][d] = (L_c B_ck)^T P_d, Gz[ck] = (L_c B_ck)^T Z,
  // with Q = A11^-1 L B, P = A11^-1 L M, Z = A11^-1 b0.
  std::vector<Eigen::Matrix3d> h_blocks, g_blocks, z_blocks;
  Eigen::MatrixXd mode_gram;   // <B_ck, L_c B_cl>, block diagonal
  Eigen::VectorXd mean_energy; // <M_c, L_c M_c> per cluster
  // For the reduced step, with X_c = L_c (M_c + sum_k lambda_ck B_ck):
  // plm[d][c] = P_d^T L_c M_c, qlm[dl][c] = Q_dl^T L_c M_c, zlm[c] = Z^T L_c M_c,
  // so that W[c][d] = X_c^T A11^-1 X_d is a short sum of blocks.
  std::vector<Eigen::Matrix3d> plm_blocks, qlm_blocks, zlm_blocks;
  double b0_z = 0.;   // <b0, Z>
  Eigen::MatrixXd s0; // constant part of the Schur complement
  Eigen::VectorXd r0; // constant part of its right-hand side

private:
  void build_inverse_blocks(const std::vector<Cluster_data>& clusters, const std::vector<int>& cluster_of_mode,
                            const Vertex_block& block);

  // The blocks of the factored block, which an update corrects.
  std::vector<Eigen::Matrix3d> h_base, g_base, plm_base, qlm_base;

  // With U = [I; T] ((3 + k) x 3): z_blocks[a] = of_mode[a] U and
  // zlm_blocks[c] = U^T of_mean[c] for the products of Z = [z_a H], and
  // b0_z = b_fixed + <b_linear, T> + <T, b_quadratic T>.
  struct Handle_basis
  {
    Cluster_products products;
    double b_fixed = 0.;
    Eigen::MatrixXd b_linear, b_quadratic; // k x 3, k x k
  } handle_basis;
};

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
