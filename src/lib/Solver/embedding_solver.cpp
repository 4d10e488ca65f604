// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Embedding_solver_impl.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Anderson_acceleration.h>

#include <algorithm>
#include <chrono>

namespace CGAL {
namespace MPM {

using namespace internal::embedding;
using internal::Anderson_acceleration;

Embedding_solver::Embedding_solver(const Embedding_problem& problem, const Embedding_options& options)
  : impl_(std::make_unique<Impl>(problem, options))
{}

Embedding_solver::~Embedding_solver() = default;
Embedding_solver::Embedding_solver(Embedding_solver&&) noexcept = default;
Embedding_solver& Embedding_solver::operator=(Embedding_solver&&) noexcept = default;

void Embedding_solver::set_handles(const std::vector<int>& vertices, const Point_matrix& targets)
{
  Impl& d = *impl_;
  if(targets.rows() != static_cast<Eigen::Index>(vertices.size()))
    throw Input_error("handles", "", std::to_string(vertices.size()) + " vertices but " +
                                       std::to_string(targets.rows()) + " targets");
  std::vector<bool> seen(d.n, false);
  for(std::size_t h = 0; h < vertices.size(); ++h)
  {
    const std::string element = "handle " + std::to_string(h);
    if(vertices[h] < 0 || vertices[h] >= d.n)
      throw Input_error("handles", element, "vertex " + std::to_string(vertices[h]) + " does not exist (the mesh has " +
                                              std::to_string(d.n) + " vertices)");
    if(seen[vertices[h]]) throw Input_error("handles", element, "vertex " + std::to_string(vertices[h]) + " has two handles");
    seen[vertices[h]] = true;
    if(!targets.row(h).allFinite()) throw Input_error("handles", element, "target is not finite");
  }
  // A drag moves the targets of the same handles, which leaves the anchors.
  const bool new_set = vertices != d.handle_vertices;
  if(new_set && !d.update_handle_set(vertices)) d.factored = false;
  d.handle_vertices = vertices;
  d.handle_targets = targets;
  d.handle_targets.rowwise() -= d.origin;
  d.handle_terms_ready = false;
  if(new_set) d.compute_anchor();
}

void Embedding_solver::clear_handles() { set_handles({}, Point_matrix(0, 3)); }

void Embedding_solver::preprocess()
{
  if(!impl_->handle_terms_ready) impl_->prepare_handle_terms();
}

double Embedding_solver::iterate()
{
  Impl& d = *impl_;
  if(!d.handle_terms_ready) d.prepare_handle_terms();
  // Phase times (a few clock reads per iteration), reported by last_iteration_timings().
  using Clock = std::chrono::steady_clock;
  Iteration_timings& t = d.timings;
  t = Iteration_timings();
  struct Total // also on the way out by an exception
  {
    double& ms;
    Clock::time_point start;
    ~Total() { ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }
  } total{t.total_ms, Clock::now()};
  internal::Lap_timer clock;
  const std::vector<Eigen::Matrix3d> previous_rotations = d.rotations;
  if(d.implicit) d.reduced_local_step();
  else d.local_step();
  t.local_step_ms += clock.lap();
  try
  {
    const double e = d.global_step->step(d, t);
    ++d.iterations_since_reset;
    return e;
  }
  catch(...)
  {
    d.rotations = previous_rotations;
    throw;
  }
}

Solve_report Embedding_solver::solve()
{
  Impl& d = *impl_;
  if(!d.handle_terms_ready) d.prepare_handle_terms();
  Impl::State entry = d.save();
  try
  {
    return solve_from_current_state();
  }
  catch(const Computation_error&)
  {
    d.restore(std::move(entry));
    throw;
  }
}

Solve_report Embedding_solver::solve_from_current_state()
{
  Impl& d = *impl_;
  if(d.iterations_since_reset == 0) d.start_at_rigid_fit_of_handles();
  Solve_report report;
  // Implicit positions have their energy from the blocks, without a back-substitution.
  double previous = d.implicit ? d.reduced_energy(d.coordinates, d.w_blocks) : energy();

  // With implicit positions and one rotation per cluster, the rotations
  // alone are the state and Newton's method on them converges in a few
  // iterations (measured on the 36 real-mesh edits of quality_real_meshes:
  // 3-7 iterations, against 31-100 with the extrapolations below, which
  // Newton's step leaves nothing to add to: 3-11 with both).
  const bool newton = d.global_step->implicit_positions() && d.options.newton &&
                      d.options.rotations == Rotations::per_cluster;
  // A prediction taken leaves the state settled at the predicted rotations:
  // the first iteration is then Newton's step alone (the local/global step
  // before it was a sixth of a 64k-vertex drag frame and moved the energy
  // less than the step after it).
  bool settled = false;
  if(newton && d.implicit && d.options.predict_rotations)
  {
    const double unpredicted = previous;
    previous = d.start_at_predicted_rotations(previous);
    settled = previous < unpredicted;
  }
  double damping = 1e-6;
  // Otherwise L-BFGS on the rotations (reduced step only). Memory measured
  // on the 36 real-mesh edits: 3 pairs 8% more iterations than 8, 20 pairs
  // 8% fewer.
  const bool quasi_newton = !newton && d.global_step->implicit_positions() && d.options.quasi_newton;
  // Each iteration evaluates one extrapolation of the local/global step: the
  // L-BFGS step, or Anderson's once L-BFGS failed three times in a row to do
  // better, until Anderson's fails in turn. Which one wins depends on the
  // edit (measured: L-BFGS on symmetrize and caricature, Anderson on some
  // drags).
  bool prefer_lbfgs = true;
  int lbfgs_failures = 0;
  internal::Rotation_lbfgs lbfgs(20);
  Eigen::VectorXd gradient;

  Anderson_acceleration anderson(newton ? 0 : std::max(0, d.options.anderson_history));
  Eigen::VectorXd x = d.packed_state();
  double best = previous;
  int rises = 0;
  for(int it = 0; it < d.options.max_iterations; ++it)
  {
    internal::throw_if_cancelled(d.options.cancel, "solve");
    const std::vector<Eigen::Matrix3d> start = d.rotations;
    const bool newton_only = settled && it == 0;
    double e = newton_only ? previous : iterate();
    const Eigen::VectorXd g = d.packed_state();
    const Eigen::VectorXd candidate = anderson.next(x, g);
    x = g;
    if((!quasi_newton || !prefer_lbfgs) && candidate != g)
    {
      if(d.take_if_lower(candidate, g, e))
        x = d.packed_state();
      else
      {
        anderson.restart();
        prefer_lbfgs = true;
        lbfgs_failures = 0;
      }
    }
    if(quasi_newton && it > 0)
    {
      const double improved = d.quasi_newton_improve(lbfgs, start, previous, gradient, e, prefer_lbfgs);
      lbfgs_failures = improved < e ? 0 : lbfgs_failures + 1;
      if(improved < e) x = d.packed_state();
      if(lbfgs_failures >= 3) prefer_lbfgs = false;
      e = improved;
    }
    else if(quasi_newton)
      gradient = d.rotation_gradient();
    double remaining = std::numeric_limits<double>::infinity();
    if(newton)
    {
      const double improved = d.newton_improve(e, damping, &remaining);
      if(improved < e) x = d.packed_state();
      // Newton's step alone failing says nothing of convergence: the
      // iteration is taken again with the local/global step.
      else if(newton_only)
      {
        settled = false;
        --it;
        continue;
      }
      e = improved;
    }
    d.check_not_diverging(e, best, rises, it + 1);
    best = std::min(best, e);
    report.energies.push_back(e);
    ++report.iterations;
    if(d.options.iteration_callback) d.options.iteration_callback(report.iterations, e);
    const double tolerance = d.options.tolerance;
    if(previous - e <= tolerance * std::max(previous, std::numeric_limits<double>::min()) || remaining <= tolerance * e)
    {
      report.converged = true;
      break;
    }
    previous = e;
  }
  if(newton) d.remember_solved_rotations();
  // Reduced energies are differences of large sums; the reported residual is
  // evaluated exactly at the final positions.
  if(d.global_step->implicit_positions() && !report.energies.empty()) report.energies.back() = energy();
  return report;
}

const Point_matrix& Embedding_solver::positions() const
{
  impl_->world_positions = impl_->materialized_positions().rowwise() + impl_->origin;
  return impl_->world_positions;
}

Eigen::VectorXd Embedding_solver::coordinates(int c) const
{
  const Cluster_data& d = impl_->clusters.at(c);
  return impl_->coordinates.segment(d.offset, d.number_of_modes());
}

const Eigen::Matrix3d& Embedding_solver::rotation(int c) const
{
  // With a rotation per vertex, a cluster has none of its own to report.
  static const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  if(impl_->options.rotations == Rotations::per_vertex)
  {
    static_cast<void>(impl_->clusters.at(c)); // throws on a bad index, as for one rotation per cluster
    return identity;
  }
  return impl_->rotations.at(c);
}

double Embedding_solver::energy() const
{
  return impl_->energy_of(impl_->materialized_positions(), impl_->coordinates);
}

double Embedding_solver::cluster_energy(int c) const
{
  return impl_->energy_of(impl_->materialized_positions(), impl_->coordinates, c);
}

void Embedding_solver::reset()
{
  Impl& d = *impl_;
  d.positions = d.mesh.points;
  d.implicit = false;
  d.positions_valid = true;
  d.coordinates.setZero();
  d.iterations_since_reset = 0;
  d.solved_rotations.clear();
  d.local_step();
}

int Embedding_solver::number_of_clusters() const { return static_cast<int>(impl_->clusters.size()); }

const Iteration_timings& Embedding_solver::last_iteration_timings() const { return impl_->timings; }

} // namespace MPM
} // namespace CGAL
