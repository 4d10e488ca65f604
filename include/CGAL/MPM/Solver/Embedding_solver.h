// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_EMBEDDING_SOLVER_H
#define CGAL_MPM_EMBEDDING_SOLVER_H

#include <CGAL/MPM/Solver/Cancellation.h>
#include <CGAL/MPM/Solver/Embedding_problem.h>
#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// The sparse factorization behind the constant vertex block.
enum class Sparse_solver
{
  simplicial_ldlt, ///< `Eigen::SimplicialLDLT` through `CGAL::Eigen_solver_traits`
  cholmod          ///< `Eigen::CholmodSupernodalLLT` (when built with CHOLMOD; else simplicial_ldlt)
};

/// \ingroup PkgMPMRef
/// How the quadratic step in positions and shape coordinates is solved.
enum class Global_step
{
  /// Iterations that never touch the vertices: rotations commute with the
  /// prefactored vertex block, so the Schur complement, its right-hand side,
  /// the rotation fit and the energy are sums of 3x3 blocks precomputed once
  /// per handle set. Positions cost one back-substitution, when asked for.
  reduced,
  /// Prefactored vertex block, Schur complement from precomputed blocks, one
  /// back-substitution and an explicit rotation fit per iteration.
  schur,
  /// Assemble and factor the whole system every iteration: the reference.
  direct
};

/// \ingroup PkgMPMRef
/// How many rotations a cluster has.
enum class Rotations
{
  per_cluster, ///< one rotation per cluster (the paper found it best; fast paths apply)
  /// One rotation per cluster vertex, edges rotated by the average of their
  /// ends' rotations (the paper's equation 3.4). Solved by the direct
  /// global step whatever `global_step` says.
  per_vertex
};

/// \ingroup PkgMPMRef
/// Options of the embedding solver.
struct Embedding_options
{
  Global_step global_step = Global_step::reduced; ///< fast path or reference
  Rotations rotations = Rotations::per_cluster;   ///< rotation variables
  Sparse_solver sparse_solver = Sparse_solver::simplicial_ldlt; ///< factorization
  /// Handle stiffness relative to the mean diagonal of the elastic matrix.
  double handle_weight = 100.;
  /// Stiffness of the one vertex (nearest the rest centroid) that anchors
  /// each connected piece without handles to its rest position, relative
  /// likewise. The energy is blind to such a piece's translation, so the
  /// weight changes no solution, only the conditioning; as stiff as a
  /// handle, a solver factored before any handle is chosen (`preprocess()`)
  /// takes each later handle set as a low-rank update.
  double anchor_weight = 100.;
  /// Weight of the coupled-coordinates term `w |lambda_a - lambda_b|^2` over
  /// the problem's coupled cluster pairs, relative to the clusters' mean
  /// prior precision; 0 disables it.
  double coupling_weight = 0.;
  /// Anderson acceleration of `solve()` where Newton's step (below) does not
  /// apply: how many previous iterates it combines (0 disables). A combined step is kept only when it lowers the
  /// energy below the plain local/global step, so the energy still never
  /// increases.
  int anderson_history = 5;
  /// With the reduced global step and Newton's step off, each iteration of
  /// `solve()` also tries an L-BFGS step on the rotations (the coordinates and positions following
  /// them optimally) and keeps it where it lowers the energy more than the
  /// (accelerated) local/global step; the energy still never increases.
  /// On the real-mesh edits of `bench/quality_real_meshes` this takes a
  /// third fewer iterations. False: local/global steps only (plus Anderson's).
  bool quasi_newton = true;
  /// With the reduced global step and one rotation per cluster, each
  /// iteration of `solve()` then tries a damped Newton step on the rotations
  /// (the exact Hessian of the energy as a function of the rotations alone,
  /// coordinates and positions following them optimally), kept where it
  /// lowers the energy further; the energy still never increases. On the
  /// 36 real-mesh edits of `bench/quality_real_meshes` it converges in 3-7
  /// iterations (31-100 without). False: the extrapolations above instead.
  bool newton = true;
  /// With Newton steps, a `solve()` that follows two solves with the same
  /// handle set (a drag) also tries to start where each cluster turns once
  /// more as it turned between them, kept when the energy there is lower.
  /// Drag frames of the synthetic 64k spider take 1.1 iterations instead
  /// of 2.0. False: each solve starts where the last ended.
  bool predict_rotations = true;
  int max_iterations = 100;  ///< iteration cap of `solve()`
  /// `solve()` stops when an iteration lowers the energy by less than this
  /// fraction, or, after a Newton step, when the next Newton step would
  /// (its quadratic model at the new rotations): a drag frame then needs no
  /// iteration that only confirms convergence.
  double tolerance = 1e-6;
  /// Called by `solve()` after each iteration with its number (from 1) and
  /// energy: progress for a long solve. Empty: not called.
  std::function<void(int iteration, double energy)> iteration_callback;
  /// Checked by `solve()` before each iteration: raised, it throws
  /// `Operation_cancelled`; the solver keeps the last finished iteration.
  Cancellation_flag cancel = nullptr;
};

/// \ingroup PkgMPMRef
/// What `Embedding_solver::solve()` did.
struct Solve_report
{
  /// Energy after each iteration. With `Global_step::reduced` they come from
  /// precomputed blocks (a difference of two large sums, exact to about
  /// 1e-14 of the data term); the last one is evaluated at the positions.
  std::vector<double> energies;
  int iterations = 0;           ///< iterations run
  bool converged = false;       ///< stopped on the tolerance, not the cap
  /// Final energy (the residual energy of the embedding).
  double energy() const { return energies.empty() ? 0. : energies.back(); }
};

/// \ingroup PkgMPMRef
/// Wall-clock time of the phases of the last `Embedding_solver::iterate()`,
/// in milliseconds; a phase the global step does not have is 0.
struct Iteration_timings
{
  /// Rotation fit: from precomputed blocks (reduced) or from the positions.
  double local_step_ms = 0.;
  /// Right-hand side: the vertex right-hand side b(R, lambda) (schur), or
  /// the blocks W(lambda) that stand for it (reduced).
  double right_hand_side_ms = 0.;
  /// Schur part: assembling and solving the shape-coordinate system.
  double schur_ms = 0.;
  /// Positions from the prefactored vertex block (schur; reduced defers it
  /// to `positions()`).
  double back_substitution_ms = 0.;
  /// Assembling, factoring and solving the whole system (direct).
  double direct_ms = 0.;
  /// Energy after the step: from blocks (reduced) or from the positions.
  double energy_ms = 0.;
  /// The whole `iterate()`.
  double total_ms = 0.;
};

/// \ingroup PkgMPMRef
/// Computes the embedding of a part graph: minimizes the elastic subspace
/// energy of every cluster plus soft handle constraints over vertex
/// positions, one rotation per cluster and the clusters' shape coordinates,
/// by local/global alternation (fit rotations; solve the quadratic in
/// positions and coordinates).
///
/// The vertex block is factored once per handle set; a change of handle
/// targets costs no factorization. Numerical failures throw
/// `Computation_error` naming the cluster at fault, leaving the previous
/// state intact.
class Embedding_solver
{
public:
  /// Prepares the solver: weights, Laplacians, factorization without handles.
  /// Throws `Input_error` for an inconsistent problem (naming the cluster).
  explicit Embedding_solver(const Embedding_problem& problem, const Embedding_options& options = Embedding_options());
  ~Embedding_solver();
  /// Movable, not copyable.
  Embedding_solver(Embedding_solver&&) noexcept;
  /// Movable, not copyable.
  Embedding_solver& operator=(Embedding_solver&&) noexcept;

  /// Sets the handle vertices and their targets (k x 3). The same vertices
  /// with new targets cost no factorization; a new vertex set changes a few
  /// diagonal entries of the factored block (its handles, and the anchor of
  /// a piece that gains or loses its handles), a low-rank update when at
  /// most 64 entries change, else a refactorization. Throws
  /// `Input_error` for a vertex out of range, a duplicate vertex or a
  /// non-finite target.
  void set_handles(const std::vector<int>& vertices, const Point_matrix& targets);
  /// Removes all handles.
  void clear_handles();
  /// Factors the vertex block and precomputes the blocks for the current
  /// handle set now (otherwise the first iteration does it), so that the
  /// cost of a new handle set can be paid, and timed, apart from iterating.
  /// Called before any handle is set (when a model is loaded), it pays the
  /// factorization once: later handle sets are low-rank updates.
  void preprocess();

  /// Runs local/global iterations (Anderson-accelerated) from the current
  /// state until the energy decreases by less than `options.tolerance`
  /// (relative; with Newton's steps, also when the next step's predicted
  /// decrease is below it) or `options.max_iterations` is reached.
  ///
  /// Throws `Computation_error` naming the part (cluster) or handle at fault
  /// when a factorization fails or is not positive definite, an iterate or
  /// the energy becomes non-finite, or the energy rises (the iterations only
  /// ever lower it, so a rise means divergence); the state is then the one
  /// `solve()` started from.
  Solve_report solve();
  /// Runs exactly one local/global iteration; returns the energy after it.
  /// On a `Computation_error` the positions and coordinates are unchanged.
  double iterate();

  /// Current vertex positions (n x 3). With `Global_step::reduced` the first
  /// call after iterating costs one back-substitution.
  const Point_matrix& positions() const;
  /// Current shape coordinates of cluster `c`.
  Eigen::VectorXd coordinates(int c) const;
  /// Current rotation of cluster `c`.
  const Eigen::Matrix3d& rotation(int c) const;
  /// Energy of the current state.
  double energy() const;
  /// Energy of cluster `c` alone in the current state.
  double cluster_energy(int c) const;
  /// Restarts from the rest positions with zero coordinates.
  void reset();
  /// Number of clusters.
  int number_of_clusters() const;
  /// Phase times of the last `iterate()` (also the last one `solve()` ran).
  const Iteration_timings& last_iteration_timings() const;

private:
  Solve_report solve_from_current_state();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace MPM
} // namespace CGAL

#endif
