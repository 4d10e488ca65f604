// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Newton's method on the reduced energy E(R) = min over coordinates and
// positions, a function of one rotation per cluster only. Alternating local
// and global steps converge linearly, slowly where parts bend against each
// other (real meshes took 40-100 iterations); the reduced problem is small
// (three unknowns per cluster), so its exact Hessian costs little.
#include <CGAL/MPM/internal/Embedding_solver_impl.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Parallel_for.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_invoke.h>
#endif

#include <cmath>
#include <map>
#include <limits>

namespace CGAL {
namespace MPM {

using namespace internal::embedding;

namespace {

Eigen::Matrix3d cross_matrix(int i)
{
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  m(k, j) = 1.;
  m(j, k) = -1.;
  return m;
}

double frobenius(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return a.cwiseProduct(b).sum(); }

} // namespace

// With R_c <- R_c exp([w_c]x), the energy with coordinates lambda held is
// F = Q(lambda) - beta(R, lambda), beta = sum_cd <R_c W_cd, R_d> +
// 2 sum_c <R_c, Wz_c^T> (reduced_energy()), whose derivative in R_c is
// 2 C_c (fit_covariance()). Second order in w:
//   beta: sum_c <R_c [w_c]^2, C_c> + sum_cd <R_c [w_c] W_cd, R_d [w_d]>,
// and the coordinates enter through W(lambda) and Wz(lambda) (w_of()).
// With lambda optimal for R, the Hessian of E is the Schur complement
//   E_ww = F_ww - F_wl F_ll^-1 F_lw,  F_ll = 2 S(R) (coordinate_system()).
Eigen::MatrixXd Embedding_solver::Impl::reduced_hessian() const
{
  const int nc = static_cast<int>(clusters.size()), dm = total_modes;
  std::vector<Eigen::Matrix3d> a(3 * std::size_t(nc)); // R_c [e_i]x
  for(int c = 0; c < nc; ++c)
    for(int i = 0; i < 3; ++i) a[3 * std::size_t(c) + i] = rotations[c] * cross_matrix(i);
  const auto w = [&](int c, int d) -> const Eigen::Matrix3d& { return w_blocks[std::size_t(c) * nc + d]; };

  Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(3 * nc, 3 * nc);
  // Cluster c writes the blocks (c, d >= c) and their transposes: clusters in parallel.
  internal::parallel_for_each_index(nc, [&](int c) {
    const Eigen::Matrix3d covariance = fit_covariance(c, rotations);
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
      {
        const Eigen::Matrix3d square = cross_matrix(i) * cross_matrix(j) + cross_matrix(j) * cross_matrix(i);
        hessian(3 * c + i, 3 * c + j) -= frobenius(rotations[c] * square, covariance);
      }
    // The pair (d, c) adds what (c, d) adds, transposed (W[d][c] is
    // W[c][d]^T): each pair is computed once, counted twice.
    for(int d = c; d < nc; ++d)
    {
      const double count = d == c ? 1. : 2.;
      for(int i = 0; i < 3; ++i)
      {
        const Eigen::Matrix3d aw = a[3 * std::size_t(c) + i] * w(c, d);
        for(int j = 0; j < 3; ++j)
        {
          const double x = count * frobenius(aw, a[3 * std::size_t(d) + j]);
          hessian(3 * c + i, 3 * d + j) -= x;
          hessian(3 * d + j, 3 * c + i) -= x;
        }
      }
    }
  });
  if(dm == 0) return 0.5 * (hessian + hessian.transpose());

  // F_wl: -2 <R_c [e_i]x, dC_c / dlambda_a>, with (from w_of())
  //   dC_c/dlambda_a = [a in c] (z_a^T + sum_d R_d qlm_ad^T + sum_k lambda_k R_d(k) h_ka)
  //                  + R_d(a) (g_ac + sum_{l in c} lambda_l h_al).
  // Each mode's column on its own, in parallel.
  Eigen::MatrixXd mixed = Eigen::MatrixXd::Zero(3 * nc, dm);
  internal::parallel_for_each_index(std::size_t(dm), [&](std::size_t mode) {
    const int own = cluster_of_mode[mode];
    // One product per cluster d: sum_k lambda_k R_d h_km over d's modes k.
    Eigen::Matrix3d in_own = schur.z_blocks[mode].transpose();
    for(int d = 0; d < nc; ++d)
    {
      Eigen::Matrix3d sum = schur.qlm_blocks[mode * nc + d].transpose();
      for(int k = clusters[d].offset; k < clusters[d].offset + clusters[d].number_of_modes(); ++k)
        sum += coordinates[k] * schur.h_blocks[std::size_t(k) * dm + mode];
      in_own += rotations[d] * sum;
    }
    for(int c = 0; c < nc; ++c)
    {
      const Cluster_data& cc = clusters[c];
      Eigen::Matrix3d derivative = schur.g_blocks[mode * nc + c];
      for(int l = 0; l < cc.number_of_modes(); ++l)
        derivative += coordinates[cc.offset + l] * schur.h_blocks[mode * dm + cc.offset + l];
      derivative = rotations[own] * derivative;
      if(c == own) derivative += in_own;
      for(int i = 0; i < 3; ++i)
        mixed(3 * c + i, Eigen::Index(mode)) = -2. * frobenius(a[3 * std::size_t(c) + i], derivative);
    }
  });
  // mixed (2 S)^-1 mixed^T = 0.5 Y^T Y with Y = L^-1 mixed^T, S = L L^T
  // factored by the global step before (the same rotations): one triangular
  // solve, its column halves in parallel, and a symmetric product (a third
  // of a 64k-vertex frame was this term as two solves and a full product).
  const Eigen::LLT<Eigen::MatrixXd>& factor = coordinate_factor();
  Eigen::MatrixXd y = mixed.transpose();
  const Eigen::Index half = y.cols() / 2;
  const auto forward = [&](Eigen::Index first, Eigen::Index count) {
    factor.matrixL().solveInPlace(y.middleCols(first, count));
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_invoke([&] { forward(0, half); }, [&] { forward(half, y.cols() - half); });
#else
  forward(0, y.cols());
#endif
  // Y^T Y's lower triangle as two diagonal blocks beside one off-diagonal
  // block, of about equal work.
  const Eigen::Index rest = y.cols() - half;
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(y.cols(), y.cols());
  const auto diagonal_blocks = [&] {
    gram.topLeftCorner(half, half).selfadjointView<Eigen::Lower>().rankUpdate(y.leftCols(half).transpose(), 0.5);
    gram.bottomRightCorner(rest, rest).selfadjointView<Eigen::Lower>().rankUpdate(y.rightCols(rest).transpose(), 0.5);
  };
  const auto off_diagonal_block = [&] {
    gram.bottomLeftCorner(rest, half).noalias() = 0.5 * y.rightCols(rest).transpose() * y.leftCols(half);
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_invoke(diagonal_blocks, off_diagonal_block);
#else
  diagonal_blocks();
  off_diagonal_block();
#endif
  hessian -= Eigen::MatrixXd(gram.selfadjointView<Eigen::Lower>());
  return 0.5 * (hessian + hessian.transpose());
}

// `step` without the turns the handles leave free. Turning all clusters of
// a connected piece together about an axis a (w_c = R_c^T a; positions
// follow) leaves the energy as it is when the piece's handles lie on a line
// along a: every axis for a piece with no handle (held by one anchored
// vertex) or one, the line's direction for two. The Hessian is singular
// there, and the rounding of the gradient along those directions, divided
// by the damping, turned a caricature by 5 degrees and a hand held by two
// finger tips by 16 degrees about the line between them.
Eigen::VectorXd Embedding_solver::Impl::without_free_turns(Eigen::VectorXd step) const
{
  std::map<int, std::vector<int>> clusters_of_piece;
  for(std::size_t c = 0; c < clusters.size(); ++c)
    if(!clusters[c].vertices.empty()) clusters_of_piece[component[clusters[c].vertices.front()]].push_back(int(c));
  std::map<int, std::vector<Eigen::RowVector3d>> handles_of_piece;
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
    handles_of_piece[component[handle_vertices[h]]].push_back(handle_targets.row(Eigen::Index(h)));
  for(const auto& [piece, members] : clusters_of_piece)
  {
    std::vector<Eigen::Vector3d> axes{Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
    const std::vector<Eigen::RowVector3d>& held = handles_of_piece[piece];
    if(held.size() >= 2)
    {
      Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
      for(const Eigen::RowVector3d& p : held) mean += p;
      mean /= double(held.size());
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
      for(const Eigen::RowVector3d& p : held) covariance += (p - mean).transpose() * (p - mean);
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
      axes.clear();
      if(eigen.eigenvalues()(1) <= 1e-12 * eigen.eigenvalues()(2)) axes.push_back(eigen.eigenvectors().col(2));
    }
    std::vector<Eigen::VectorXd> turns;
    for(const Eigen::Vector3d& axis : axes)
    {
      Eigen::VectorXd t = Eigen::VectorXd::Zero(step.size());
      for(int c : members) t.segment<3>(3 * c) = rotations[c].transpose() * axis;
      for(const Eigen::VectorXd& u : turns) t -= u.dot(t) * u;
      if(t.norm() > 0.) turns.push_back(t.normalized());
    }
    for(const Eigen::VectorXd& u : turns) step -= u.dot(step) * u;
  }
  return step;
}

// A damped Newton step from the current (settled) rotations, kept when it
// lowers `energy`; the damping (Levenberg-Marquardt, relative to the
// Hessian's mean diagonal) adapts across calls. Returns the energy reached.
// `remaining`, when given, receives the decrease a further Newton step would
// bring (remaining_decrease()), or infinity when the step was not taken or
// its model did not predict it.
double Embedding_solver::Impl::newton_improve(double energy, double& damping, double* remaining)
{
  if(remaining) *remaining = std::numeric_limits<double>::infinity();
  // Reduced energies are differences of large sums (reduced_energy()): a
  // decrease below their rounding is noise, and a step taken on it moves
  // an exact solution (the rest under caricature factor 1) off by 1e-8.
  const double rounding = 1e-13 * (std::abs(schur.mean_energy.sum()) + std::abs(handle_constant) + std::abs(schur.b0_z));
  const int nc = static_cast<int>(clusters.size());
  if(nc == 0 || energy <= rounding) return energy;
  const Eigen::MatrixXd hessian = reduced_hessian();
  const Eigen::VectorXd gradient = rotation_gradient();
  const double scale = std::max(hessian.diagonal().cwiseAbs().mean(), std::numeric_limits<double>::min());
  const Implicit_state kept = save_implicit();
  for(int attempt = 0; attempt < 4; ++attempt, damping = std::max(1e-6, 10. * damping))
  {
    Eigen::MatrixXd damped = hessian;
    damped.diagonal().array() += damping * scale;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(damped);
    if(ldlt.info() != Eigen::Success || !ldlt.isPositive() || (ldlt.vectorD().array() <= 0.).any()) continue;
    const Eigen::VectorXd step = without_free_turns(-ldlt.solve(gradient));
    if(!step.allFinite() || gradient.dot(step) >= 0.) continue;
    rotations = internal::retract(kept.rotations, step);
    double e = std::numeric_limits<double>::infinity();
    try
    {
      e = settle_at_rotations();
    }
    catch(const Computation_error&)
    {
      // A step too long for the coordinate system is only a failed trial.
    }
    if(e < energy - rounding)
    {
      damping *= 0.1;
      if(remaining) *remaining = remaining_decrease(hessian, ldlt, gradient, step, energy - e);
      return e;
    }
    restore_implicit(kept);
  }
  return energy;
}

// The decrease still to come after a Newton step `step` (from gradient
// `gradient`, Hessian `hessian`, factored damped as `ldlt`) that lowered the
// energy by `decrease`: the quadratic model's decrease along the next
// Newton step, from the gradient at the new rotations and this Hessian (the
// Hessian changes little between two steps that near the solution). Without
// it, a solve ran one more iteration to see the energy not move: 9 of 12
// drag frames on the 64k spider (relative change 2e-9 to 4e-8 against the
// tolerance 1e-6). Trusted only where the model predicted `decrease` within
// a factor 2; infinity otherwise.
double Embedding_solver::Impl::remaining_decrease(const Eigen::MatrixXd& hessian,
                                                  const Eigen::LDLT<Eigen::MatrixXd>& ldlt,
                                                  const Eigen::VectorXd& gradient, const Eigen::VectorXd& step,
                                                  double decrease) const
{
  const auto model_decrease = [&](const Eigen::VectorXd& g, const Eigen::VectorXd& s) {
    return -g.dot(s) - 0.5 * s.dot(hessian * s);
  };
  const double predicted = model_decrease(gradient, step);
  if(!(predicted > 0.) || decrease < 0.5 * predicted || decrease > 2. * predicted)
    return std::numeric_limits<double>::infinity();
  const Eigen::VectorXd next_gradient = rotation_gradient();
  const Eigen::VectorXd next = without_free_turns(-ldlt.solve(next_gradient));
  const double next_decrease = model_decrease(next_gradient, next);
  return next.allFinite() && next_decrease >= 0. ? next_decrease : std::numeric_limits<double>::infinity();
}

} // namespace MPM
} // namespace CGAL
