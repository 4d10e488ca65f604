// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Schur_blocks.h>

#include <CGAL/MPM/internal/Parallel_for.h>

#include <algorithm>

namespace CGAL {
namespace MPM {
namespace internal {
namespace embedding {

namespace {

// The cluster's block operands side by side: [L_c B_c1 .. L_c B_cm L_c M_c].
Eigen::MatrixXd cluster_operands(const Cluster_data& d)
{
  const int m = d.number_of_modes();
  Eigen::MatrixXd operands(Eigen::Index(d.vertices.size()), 3 * (m + 1));
  for(int k = 0; k < m; ++k) operands.middleCols<3>(3 * k) = d.laplacian_modes[std::size_t(k)];
  operands.rightCols<3>() = d.laplacian_mean;
  return operands;
}

// One product per cluster, in parallel.
Cluster_products cluster_products(const std::vector<Cluster_data>& clusters, std::size_t modes, const Eigen::MatrixXd& z)
{
  Cluster_products p;
  p.of_mode.resize(modes);
  p.of_mean.resize(clusters.size());
  internal::parallel_for_each_index(clusters.size(), [&](std::size_t c) {
    const Cluster_data& d = clusters[c];
    const Eigen::MatrixXd product = cluster_operands(d).transpose() * gather(d, z);
    for(int k = 0; k < d.number_of_modes(); ++k) p.of_mode[std::size_t(d.offset + k)] = product.middleRows<3>(3 * k);
    p.of_mean[c] = product.bottomRows<3>().transpose();
  });
  return p;
}

} // namespace

void Schur_blocks::build(const std::vector<Cluster_data>& clusters, const std::vector<int>& cluster_of_mode,
                         const Eigen::MatrixXd& coupling, const Vertex_block& block)
{
  const int dm = static_cast<int>(cluster_of_mode.size()), nc = static_cast<int>(clusters.size());
  mode_gram = Eigen::MatrixXd::Zero(dm, dm);
  mean_energy.resize(nc);
  r0 = Eigen::VectorXd::Zero(dm);
  for(const Cluster_data& c : clusters)
  {
    mean_energy[&c - clusters.data()] = (c.mean.array() * c.laplacian_mean.array()).sum();
    for(int k = 0; k < c.number_of_modes(); ++k)
    {
      for(int l = 0; l < c.number_of_modes(); ++l)
        mode_gram(c.offset + k, c.offset + l) = (c.modes[k].array() * c.laplacian_modes[l].array()).sum();
      r0[c.offset + k] = -(c.modes[k].array() * c.laplacian_mean.array()).sum();
    }
  }
  s0 = mode_gram + coupling;
  for(const Cluster_data& c : clusters)
    for(int k = 0; k < c.number_of_modes(); ++k) s0(c.offset + k, c.offset + k) += c.prior[k];
  build_inverse_blocks(clusters, cluster_of_mode, block);
}

// H, G, Q and P of A_f: 3x3 blocks of X^T A_f^-1 X, X = [L_c B_c1 .. L_c B_cm L_c M_c]
// for every cluster c, each local to its cluster.
void Schur_blocks::build_inverse_blocks(const std::vector<Cluster_data>& clusters, const std::vector<int>& cluster_of_mode,
                                        const Vertex_block& block)
{
  const int dm = static_cast<int>(cluster_of_mode.size()), nc = static_cast<int>(clusters.size());
  std::vector<Local_columns> operands(clusters.size());
  for(std::size_t c = 0; c < clusters.size(); ++c)
  {
    operands[c].rows = clusters[c].vertices;
    operands[c].values = cluster_operands(clusters[c]);
  }
  const Eigen::MatrixXd gram = block.inverse_gram(operands);
  const std::vector<Eigen::Index> offset = column_offsets(operands);
  const auto mode_column = [&](int a) {
    const int c = cluster_of_mode[std::size_t(a)];
    return offset[std::size_t(c)] + 3 * (a - clusters[std::size_t(c)].offset);
  };
  const auto mean_column = [&](int c) { return offset[std::size_t(c) + 1] - 3; };
  h_blocks.assign(std::size_t(dm) * dm, Eigen::Matrix3d::Zero());
  g_blocks.assign(std::size_t(dm) * nc, Eigen::Matrix3d::Zero());
  qlm_blocks.assign(std::size_t(dm) * nc, Eigen::Matrix3d::Zero());
  plm_blocks.assign(std::size_t(nc) * nc, Eigen::Matrix3d::Zero());
  for(int a = 0; a < dm; ++a)
  {
    for(int b = 0; b < dm; ++b) h_blocks[std::size_t(a) * dm + b] = gram.block<3, 3>(mode_column(a), mode_column(b));
    for(int d = 0; d < nc; ++d)
      g_blocks[std::size_t(a) * nc + d] = qlm_blocks[std::size_t(a) * nc + d] =
        gram.block<3, 3>(mode_column(a), mean_column(d));
  }
  for(int d = 0; d < nc; ++d)
    for(int c = 0; c < nc; ++c) plm_blocks[std::size_t(d) * nc + c] = gram.block<3, 3>(mean_column(d), mean_column(c));
  h_base = h_blocks;
  g_base = g_blocks;
  plm_base = plm_blocks;
  qlm_base = qlm_blocks;
}

void Schur_blocks::update(const std::vector<Cluster_data>& clusters, const Vertex_block& block)
{
  if(block.update_vertices().empty())
  {
    h_blocks = h_base;
    g_blocks = g_base;
    plm_blocks = plm_base;
    qlm_blocks = qlm_base;
    return;
  }
  // T_X = C^T X for every block operand X (L_c M_c and L_c B_ck), then
  // X^T A^-1 Y = X^T A_f^-1 Y - T_X^T K^-1 T_Y.
  const int dm = static_cast<int>(mode_gram.rows()), nc = static_cast<int>(clusters.size());
  const Cluster_products products = cluster_products(clusters, std::size_t(dm), block.update_columns());
  const std::vector<Eigen::MatrixXd>& t_mean = products.of_mean;
  std::vector<Eigen::MatrixXd> t_mode(dm);
  for(int a = 0; a < dm; ++a) t_mode[a] = products.of_mode[a].transpose();
  const auto correction = [&](const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) -> Eigen::Matrix3d {
    return x.transpose() * (block.capacitance_inverse() * y);
  };
  for(int a = 0; a < dm; ++a)
  {
    for(int b = 0; b < dm; ++b)
      h_blocks[std::size_t(a) * dm + b] = h_base[std::size_t(a) * dm + b] - correction(t_mode[a], t_mode[b]);
    for(int d = 0; d < nc; ++d)
    {
      g_blocks[std::size_t(a) * nc + d] = g_base[std::size_t(a) * nc + d] - correction(t_mode[a], t_mean[d]);
      qlm_blocks[std::size_t(a) * nc + d] = qlm_base[std::size_t(a) * nc + d] - correction(t_mode[a], t_mean[d]);
    }
  }
  for(int d = 0; d < nc; ++d)
    for(int c = 0; c < nc; ++c)
      plm_blocks[std::size_t(d) * nc + c] = plm_base[std::size_t(d) * nc + c] - correction(t_mean[d], t_mean[c]);
}

void Schur_blocks::set_handle_terms(const std::vector<Cluster_data>& clusters, const Point_matrix& b0,
                                    const Eigen::MatrixXd& z)
{
  b0_z = (b0.array() * z.array()).sum();
  const Cluster_products p = cluster_products(clusters, std::size_t(mode_gram.rows()), z);
  z_blocks.assign(p.of_mode.begin(), p.of_mode.end());
  zlm_blocks.assign(p.of_mean.begin(), p.of_mean.end());
}

void Schur_blocks::set_handle_basis(const std::vector<Cluster_data>& clusters, const Point_matrix& anchor_rhs,
                                    const Point_matrix& anchor_solution, const std::vector<int>& handles,
                                    const Eigen::MatrixXd& handle_columns)
{
  const Eigen::Index k = handle_columns.cols();
  Eigen::MatrixXd z(anchor_solution.rows(), 3 + k);
  z << anchor_solution, handle_columns;
  Handle_basis& b = handle_basis;
  b.products = cluster_products(clusters, std::size_t(mode_gram.rows()), z);
  // <a + S T, z_a + H T> = <a, z_a> + <H^T a + S^T z_a, T> + <T, S^T H T>.
  b.b_fixed = (anchor_rhs.array() * anchor_solution.array()).sum();
  b.b_linear = handle_columns.transpose() * anchor_rhs;
  b.b_quadratic.resize(k, k);
  for(Eigen::Index h = 0; h < k; ++h)
  {
    b.b_linear.row(h) += anchor_solution.row(handles[std::size_t(h)]);
    b.b_quadratic.row(h) = handle_columns.row(handles[std::size_t(h)]);
  }
}

void Schur_blocks::set_handle_targets(const Eigen::MatrixXd& weighted_targets)
{
  const Handle_basis& b = handle_basis;
  const Eigen::MatrixXd& t = weighted_targets;
  b0_z = b.b_fixed + (b.b_linear.array() * t.array()).sum() + (t.array() * (b.b_quadratic * t).array()).sum();
  Eigen::MatrixXd lift(3 + t.rows(), 3);
  lift << Eigen::Matrix3d::Identity(), t;
  z_blocks.resize(b.products.of_mode.size());
  for(std::size_t a = 0; a < z_blocks.size(); ++a) z_blocks[a] = b.products.of_mode[a] * lift;
  zlm_blocks.resize(b.products.of_mean.size());
  for(std::size_t c = 0; c < zlm_blocks.size(); ++c) zlm_blocks[c] = lift.transpose() * b.products.of_mean[c];
}

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL
