// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Embedding_solver_impl.h>

#include <CGAL/MPM/Input_error.h>

#include <Eigen/SparseCholesky>

#include <cmath>

namespace CGAL {
namespace MPM {

using namespace internal::embedding;

// Positions and coordinates found with the positions explicit: the solver
// moves there, after its checks, and the energy there is returned.
double Embedding_solver::Impl::take_explicit(Point_matrix v, Eigen::VectorXd lambda, Iteration_timings& t)
{
  check_finite(v, lambda);
  internal::Lap_timer clock;
  const double e = energy_of(v, lambda);
  t.energy_ms += clock.lap();
  if(!std::isfinite(e)) fail_on_non_finite_energy(v, lambda);
  positions = std::move(v);
  coordinates = std::move(lambda);
  return e;
}

// The reference: the whole quadratic in (x, y, z, lambda), assembled edge by
// edge (not from the cluster Laplacians the fast paths use) and factored
// afresh. Slow, simple, and what the fast paths must agree with. With edge
// transforms T_e, targets t_e = T_e (m_e + sum_k lambda_k b_ke).
struct Embedding_solver::Impl::Direct_step final : Global_step_method
{
  double step(Impl& d, Iteration_timings& t) const override
  {
    internal::Lap_timer clock;
    Point_matrix v;
    Eigen::VectorXd lambda;
    solve(d, v, lambda);
    t.direct_ms += clock.lap();
    return d.take_explicit(std::move(v), std::move(lambda), t);
  }
  bool uses_blocks() const override { return false; }

  static void solve(const Impl& s, Point_matrix& v, Eigen::VectorXd& lambda)
  {
    const int dm = s.total_modes, size = 3 * s.n + dm;
    std::vector<Eigen::Triplet<double>> t;
    const Sparse& system = s.block->factored_matrix();
    for(int a = 0; a < 3; ++a)
      for(int k = 0; k < system.outerSize(); ++k)
        for(Sparse::InnerIterator it(system, k); it; ++it)
          t.emplace_back(a * s.n + it.row(), a * s.n + it.col(), it.value());
    const std::vector<int>& update_vertices = s.block->update_vertices();
    const Eigen::VectorXd& update_weights = s.block->update_weights();
    for(std::size_t u = 0; u < update_vertices.size(); ++u)
      for(int a = 0; a < 3; ++a)
        t.emplace_back(a * s.n + update_vertices[u], a * s.n + update_vertices[u], update_weights[Eigen::Index(u)]);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
    for(int a = 0; a < 3; ++a) rhs.segment(a * s.n, s.n) = s.b0.col(a);
    Eigen::MatrixXd lambda_block = s.coupling;
    for(std::size_t c = 0; c < s.clusters.size(); ++c)
    {
      const Cluster_data& d = s.clusters[c];
      const int modes = d.number_of_modes();
      std::vector<Eigen::Vector3d> mode_edges(modes);
      for(const Weighted_edge& e : d.edges)
      {
        const Eigen::Matrix3d transform = s.rotation_groups.edge_transform(static_cast<int>(c), e, s.rotations);
        const int gi = d.vertices[e.i], gj = d.vertices[e.j];
        const Eigen::Vector3d u = transform * (d.mean.row(e.i) - d.mean.row(e.j)).transpose();
        for(int a = 0; a < 3; ++a)
        {
          rhs[a * s.n + gi] += e.w * u[a];
          rhs[a * s.n + gj] -= e.w * u[a];
        }
        for(int k = 0; k < modes; ++k)
        {
          mode_edges[k] = transform * (d.modes[k].row(e.i) - d.modes[k].row(e.j)).transpose();
          const int row = 3 * s.n + d.offset + k;
          for(int a = 0; a < 3; ++a)
          {
            const double value = e.w * mode_edges[k][a];
            t.emplace_back(row, a * s.n + gi, -value);
            t.emplace_back(a * s.n + gi, row, -value);
            t.emplace_back(row, a * s.n + gj, value);
            t.emplace_back(a * s.n + gj, row, value);
          }
          rhs[row] -= e.w * mode_edges[k].dot(u);
        }
        for(int k = 0; k < modes; ++k)
          for(int l = 0; l < modes; ++l)
            lambda_block(d.offset + k, d.offset + l) += e.w * mode_edges[k].dot(mode_edges[l]);
      }
      for(int k = 0; k < modes; ++k) lambda_block(d.offset + k, d.offset + k) += d.prior[k];
    }
    for(int a = 0; a < dm; ++a)
      for(int b = 0; b < dm; ++b)
        if(lambda_block(a, b) != 0.) t.emplace_back(3 * s.n + a, 3 * s.n + b, lambda_block(a, b));
    Sparse k(size, size);
    k.setFromTriplets(t.begin(), t.end());
    Eigen::SimplicialLDLT<Sparse> ldlt(k);
    if(ldlt.info() != Eigen::Success || non_positive_pivot_row(ldlt) >= 0)
      throw Computation_error("embedding: factorization of the full system failed");
    const Eigen::VectorXd x = ldlt.solve(rhs);
    v.resize(s.n, 3);
    for(int a = 0; a < 3; ++a) v.col(a) = x.segment(a * s.n, s.n);
    lambda = x.tail(dm);
  }
};

// Coordinates from the Schur complement of the prefactored vertex block,
// then positions by one back-substitution.
struct Embedding_solver::Impl::Schur_step final : Global_step_method
{
  double step(Impl& d, Iteration_timings& t) const override
  {
    internal::Lap_timer clock;
    Eigen::VectorXd lambda = d.solve_coordinates();
    t.schur_ms += clock.lap();
    const Eigen::MatrixXd rhs = d.positions_rhs(lambda);
    t.right_hand_side_ms += clock.lap();
    Point_matrix v = d.block->solve(rhs);
    t.back_substitution_ms += clock.lap();
    return d.take_explicit(std::move(v), std::move(lambda), t);
  }
};

// Coordinates from the blocks alone; the positions stay implicit.
struct Embedding_solver::Impl::Reduced_step final : Global_step_method
{
  double step(Impl& d, Iteration_timings& t) const override { return d.settle_at_rotations(&t); }
  bool implicit_positions() const override { return true; }
};

std::unique_ptr<Embedding_solver::Impl::Global_step_method> Embedding_solver::Impl::make_global_step(Global_step which)
{
  switch(which)
  {
  case Global_step::direct: return std::make_unique<Direct_step>();
  case Global_step::schur: return std::make_unique<Schur_step>();
  case Global_step::reduced: break;
  }
  return std::make_unique<Reduced_step>();
}

} // namespace MPM
} // namespace CGAL
