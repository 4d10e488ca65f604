// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_EMBEDDING_SOLVER_IMPL_H
#define CGAL_MPM_INTERNAL_EMBEDDING_SOLVER_IMPL_H

// The state of `Embedding_solver` shared by its sources: set-up and
// factorization (embedding_solver_setup.cpp), the reduced step's pieces and
// energies (embedding_solver_steps.cpp), the three global steps
// (embedding_solver_global_steps.cpp), and the iterations and the public
// API (embedding_solver.cpp). Parts with one job each have their own
// headers: the factored vertex block (Vertex_block.h), the blocks of its
// inverse the fast steps use (Schur_blocks.h) and the rotation fit
// (Rotation_groups.h).

#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Rotation_groups.h>
#include <CGAL/MPM/internal/Rotation_lbfgs.h>
#include <CGAL/MPM/internal/Schur_blocks.h>
#include <CGAL/MPM/internal/Vertex_block.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <chrono>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// Splits elapsed time into phases.
class Lap_timer
{
public:
  // Milliseconds since the previous lap, or since construction.
  double lap()
  {
    const std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - mark_).count();
    mark_ = now;
    return ms;
  }

private:
  std::chrono::steady_clock::time_point mark_ = std::chrono::steady_clock::now();
};

} // namespace internal

struct Embedding_solver::Impl
{
  using Sparse = internal::embedding::Sparse;
  using Cluster_data = internal::embedding::Cluster_data;
  using Weighted_edge = internal::embedding::Weighted_edge;

  // The global step: for the current rotations, the coordinates and
  // positions of least energy, by one of the methods of `Global_step`
  // (embedding_solver_global_steps.cpp).
  struct Global_step_method
  {
    virtual ~Global_step_method() = default;
    // Moves `d` there and returns the energy; `t` receives each phase's time.
    virtual double step(Impl& d, Iteration_timings& t) const = 0;
    // Whether it needs the Schur blocks, built with the factorization.
    virtual bool uses_blocks() const { return true; }
    // Whether the positions stay implicit, the rotations and coordinates being the state.
    virtual bool implicit_positions() const { return false; }
  };
  struct Direct_step;
  struct Schur_step;
  struct Reduced_step;
  static std::unique_ptr<Global_step_method> make_global_step(Global_step which);

  Embedding_options options;
  std::unique_ptr<Global_step_method> global_step;
  Indexed_mesh mesh;
  int n = 0;
  std::vector<Cluster_data> clusters;
  internal::embedding::Rotation_groups rotation_groups;
  int total_modes = 0;
  Sparse elastic;                 // sum of cluster Laplacians, n x n
  double mean_diagonal = 1.;
  std::vector<int> component;     // connected piece of each vertex (through cluster edges)

  // Handles.
  std::vector<int> handle_vertices;
  Point_matrix handle_targets;
  // The factored vertex block. Not `factored` for the handles after a change
  // of handle set it cannot take as a low-rank update; it still gives the
  // implicit positions of the current state until refactored.
  std::unique_ptr<internal::embedding::Vertex_block> block;
  // S(R) factored at `factored_rotations` (coordinate_factor()): the Newton
  // step after a global step factors the same system. Emptied whenever the
  // blocks S is made of change.
  mutable Eigen::LLT<Eigen::MatrixXd> coordinate_llt;
  // The rotations at the end of the last two solves with this handle set,
  // the older first (start_at_predicted_rotations()).
  std::vector<std::vector<Eigen::Matrix3d>> solved_rotations;
  mutable Eigen::VectorXd coordinate_rhs;
  mutable std::vector<Eigen::Matrix3d> factored_rotations;
  bool factored = false;
  bool handle_terms_ready = false;
  Eigen::VectorXd anchor;         // per-vertex anchor weight
  std::vector<int> anchored;      // the vertices of positive anchor weight
  double anchor_constant = 0.;    // sum over anchored vertices of weight * |rest point|^2
  internal::embedding::Schur_blocks schur; // with the schur and reduced steps
  Eigen::MatrixXd coupling;       // coupled-coordinates term, total_modes x total_modes
  double handle_constant = 0.;    // sum w_h |y_h|^2 + anchors
  Point_matrix b0;                // handle and anchor right-hand side
  // The handle set of the blocks' handle basis (set_block_handle_terms()).
  std::vector<int> handle_columns_for;
  bool handle_columns_valid = false;
  std::vector<int> cluster_of_mode;

  // State. With the reduced step, positions are implicit (A11^-1 b(R, lambda))
  // until asked for; `w_blocks` then holds W for the current coordinates.
  bool implicit = false;
  bool positions_valid = true;
  // Everything is solved relative to the rest centroid, which keeps the
  // handle constants (and so the rounding of reduced energies) small.
  Eigen::RowVector3d origin;
  Point_matrix world_positions;
  std::vector<Eigen::Matrix3d> w_blocks;
  Point_matrix positions;
  Eigen::VectorXd coordinates;
  std::vector<Eigen::Matrix3d> rotations; // per rotation group: cluster c's at c with one per cluster
  int iterations_since_reset = 0;
  Iteration_timings timings; // of the last iterate()

  Impl(const Embedding_problem& problem, const Embedding_options& o);
  void prepare_clusters(const Embedding_problem& problem);
  Cluster_data prepared_cluster(const Cluster& c, double sigma_sub, int index) const;
  void compute_anchor();
  Eigen::VectorXd anchor_for(const std::vector<int>& handles) const;
  Eigen::VectorXd diagonal_terms(const std::vector<int>& handles) const;
  void factor();
  bool update_handle_set(const std::vector<int>& vertices);
  Point_matrix anchor_right_hand_side() const;
  void set_block_handle_terms();
  void prepare_handle_terms();
  Point_matrix target_shape(const Cluster_data& c, const Eigen::VectorXd& lambda) const;
  void local_step();
  Eigen::Matrix3d fit_covariance(int c, const std::vector<Eigen::Matrix3d>& r) const;
  void start_at_rigid_fit_of_handles();
  double start_at_predicted_rotations(double energy);
  void remember_solved_rotations();
  Eigen::VectorXd packed_state() const;
  double enter_state(const Eigen::VectorXd& x);
  bool take_if_lower(const Eigen::VectorXd& candidate, const Eigen::VectorXd& plain, double& energy);
  void check_not_diverging(double e, double best, int& rises, int iteration);
  void reduced_local_step();
  Eigen::VectorXd rotation_gradient() const;
  double settle_at_rotations(Iteration_timings* timings = nullptr);
  double quasi_newton_improve(internal::Rotation_lbfgs& lbfgs, const std::vector<Eigen::Matrix3d>& start,
                              double start_energy, Eigen::VectorXd& gradient, double energy, bool try_step);
  void coordinate_system(Eigen::MatrixXd& s, Eigen::VectorXd& r) const;
  const Eigen::LLT<Eigen::MatrixXd>& coordinate_factor(Eigen::VectorXd* r = nullptr) const;
  Eigen::VectorXd solve_coordinates() const;
  Eigen::MatrixXd reduced_hessian() const;
  Eigen::VectorXd without_free_turns(Eigen::VectorXd step) const;
  double newton_improve(double energy, double& damping, double* remaining = nullptr);
  double remaining_decrease(const Eigen::MatrixXd& hessian, const Eigen::LDLT<Eigen::MatrixXd>& ldlt,
                            const Eigen::VectorXd& gradient, const Eigen::VectorXd& step, double decrease) const;
  Eigen::MatrixXd positions_rhs(const Eigen::VectorXd& lambda) const;
  Point_matrix positions_from(const Eigen::VectorXd& lambda) const;
  std::vector<Eigen::Matrix3d> w_of(const Eigen::VectorXd& lambda) const;
  double reduced_energy(const Eigen::VectorXd& lambda, const std::vector<Eigen::Matrix3d>& w) const;
  const Point_matrix& materialized_positions();
  double take_explicit(Point_matrix v, Eigen::VectorXd lambda, Iteration_timings& t);
  double energy_of(const Point_matrix& v, const Eigen::VectorXd& lambda, int only = -1) const;
  double cluster_energy(std::size_t c, const Point_matrix& v, const Eigen::VectorXd& lambda) const;
  void check_finite(const Point_matrix& v, const Eigen::VectorXd& lambda) const;
  [[noreturn]] void fail_on_non_finite_energy(const Point_matrix& v, const Eigen::VectorXd& lambda) const;
  std::string largest_energy_term(const Point_matrix& v, const Eigen::VectorXd& lambda) const;

  // Everything iterating changes, so that a failed solve leaves the state it found.
  struct State
  {
    Point_matrix positions;
    Eigen::VectorXd coordinates;
    std::vector<Eigen::Matrix3d> rotations, w_blocks;
    bool implicit = false, positions_valid = true;
    int iterations_since_reset = 0;
  };
  State save() const
  {
    return {positions, coordinates, rotations, w_blocks, implicit, positions_valid, iterations_since_reset};
  }
  void restore(State s)
  {
    positions = std::move(s.positions);
    coordinates = std::move(s.coordinates);
    rotations = std::move(s.rotations);
    w_blocks = std::move(s.w_blocks);
    implicit = s.implicit;
    positions_valid = s.positions_valid;
    iterations_since_reset = s.iterations_since_reset;
  }
  // What a trial step from settled rotations changes (positions are not
  // materialized while the state is implicit), to go back to when it fails.
  struct Implicit_state
  {
    std::vector<Eigen::Matrix3d> rotations, w_blocks;
    Eigen::VectorXd coordinates;
  };
  Implicit_state save_implicit() const { return {rotations, w_blocks, coordinates}; }
  void restore_implicit(const Implicit_state& s)
  {
    rotations = s.rotations;
    w_blocks = s.w_blocks;
    coordinates = s.coordinates;
  }
  // The energy of one handle a bounding-box diagonal away from its target:
  // the unit below which energy changes are rounding, not divergence.
  double energy_unit() const
  {
    const double diagonal = n > 0 ? internal::bounding_box_diagonal(mesh.points) : 1.;
    return options.handle_weight * mean_diagonal * std::max(diagonal * diagonal, std::numeric_limits<double>::min());
  }
};

} // namespace MPM
} // namespace CGAL

#endif
