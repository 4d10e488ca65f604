// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Embedding_solver_impl.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Parallel_for.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace CGAL {
namespace MPM {

using namespace internal::embedding;

void Embedding_solver::Impl::local_step() { rotation_groups.fit(clusters, positions, coordinates, rotations); }

// The shape-coordinate system S(R) lambda = r(R) at the current rotations:
// half the Hessian of the energy in the coordinates, and the right-hand side.
void Embedding_solver::Impl::coordinate_system(Eigen::MatrixXd& s, Eigen::VectorXd& r) const
{
  const int dm = total_modes, nc = static_cast<int>(clusters.size());
  std::vector<Eigen::Matrix3d> relative(std::size_t(nc) * nc); // R_d^T R_c at [c * nc + d]
  for(int c = 0; c < nc; ++c)
    for(int d = 0; d < nc; ++d) relative[std::size_t(c) * nc + d] = rotations[d].transpose() * rotations[c];
  s = schur.s0;
  r = schur.r0;
  // S is symmetric: its lower triangle, mirrored (the blocks are read on
  // every settle of the coordinates, a few per drag frame). Rows in parallel.
  internal::parallel_for_each_index(dm, [&](int a) {
    const int c = cluster_of_mode[a];
    for(int b = 0; b <= a; ++b)
      s(a, b) -= trace_product(schur.h_blocks[std::size_t(a) * dm + b], relative[std::size_t(c) * nc + cluster_of_mode[b]]);
    for(int d = 0; d < nc; ++d)
      r[a] += trace_product(schur.g_blocks[std::size_t(a) * nc + d], relative[std::size_t(c) * nc + d]);
    r[a] += trace_product(schur.z_blocks[a], rotations[c]);
  });
  s = Eigen::MatrixXd(s.selfadjointView<Eigen::Lower>());
}

// The LLT factor of S(R) at the current rotations, and r(R) in `r`.
const Eigen::LLT<Eigen::MatrixXd>& Embedding_solver::Impl::coordinate_factor(Eigen::VectorXd* r) const
{
  if(factored_rotations.empty() || factored_rotations != rotations)
  {
    Eigen::MatrixXd s;
    coordinate_system(s, coordinate_rhs);
    coordinate_llt.compute(s);
    if(coordinate_llt.info() != Eigen::Success)
    {
      factored_rotations.clear();
      throw Computation_error("embedding: the shape-coordinate system is not positive definite");
    }
    factored_rotations = rotations;
  }
  if(r) *r = coordinate_rhs;
  return coordinate_llt;
}

Eigen::VectorXd Embedding_solver::Impl::solve_coordinates() const
{
  if(total_modes == 0) return Eigen::VectorXd::Zero(0);
  Eigen::VectorXd r;
  const Eigen::LLT<Eigen::MatrixXd>& llt = coordinate_factor(&r);
  return llt.solve(r);
}

Eigen::MatrixXd Embedding_solver::Impl::positions_rhs(const Eigen::VectorXd& lambda) const
{
  // The clusters' terms in parallel; added in order, as clusters may share
  // vertices.
  std::vector<Eigen::MatrixXd> rotated(clusters.size());
  const auto term = [&](std::size_t c) {
    const Cluster_data& d = clusters[c];
    Point_matrix lm = d.laplacian_mean;
    for(int k = 0; k < d.number_of_modes(); ++k) lm += lambda[d.offset + k] * d.laplacian_modes[k];
    rotated[c] = lm * rotations[c].transpose();
  };
  internal::parallel_for_each_index(clusters.size(), term);
  Eigen::MatrixXd rhs = b0;
  for(std::size_t c = 0; c < clusters.size(); ++c)
    for(std::size_t i = 0; i < clusters[c].vertices.size(); ++i) rhs.row(clusters[c].vertices[i]) += rotated[c].row(i);
  return rhs;
}

Point_matrix Embedding_solver::Impl::positions_from(const Eigen::VectorXd& lambda) const
{
  return block->solve(positions_rhs(lambda));
}

// W[c][d] = X_c^T A11^-1 X_d at [c * nc + d], and X_c^T Z at [nc * nc + c].
// W[d][c] is W[c][d]^T: half of them are computed (the blocks are read on
// every settle of the coordinates, a few per drag frame).
std::vector<Eigen::Matrix3d> Embedding_solver::Impl::w_of(const Eigen::VectorXd& lambda) const
{
  const int nc = static_cast<int>(clusters.size()), dm = total_modes;
  std::vector<Eigen::Matrix3d> w(std::size_t(nc) * nc + nc);
  // Cluster c writes the pairs (c, d >= c) and their transposes: clusters in parallel.
  internal::parallel_for_each_index(nc, [&](int c) {
    const Cluster_data& cc = clusters[c];
    for(int d = c; d < nc; ++d)
    {
      const Cluster_data& cd = clusters[d];
      Eigen::Matrix3d entry = schur.plm_blocks[std::size_t(d) * nc + c].transpose();
      for(int l = 0; l < cd.number_of_modes(); ++l)
        entry += lambda[cd.offset + l] * schur.qlm_blocks[std::size_t(cd.offset + l) * nc + c].transpose();
      for(int k = 0; k < cc.number_of_modes(); ++k)
      {
        const double lk = lambda[cc.offset + k];
        entry += lk * schur.g_blocks[std::size_t(cc.offset + k) * nc + d];
        for(int l = 0; l < cd.number_of_modes(); ++l)
          entry += lk * lambda[cd.offset + l] * schur.h_blocks[std::size_t(cc.offset + k) * dm + cd.offset + l];
      }
      w[std::size_t(c) * nc + d] = entry;
      w[std::size_t(d) * nc + c] = entry.transpose();
    }
    Eigen::Matrix3d z = schur.zlm_blocks[c].transpose();
    for(int k = 0; k < cc.number_of_modes(); ++k) z += lambda[cc.offset + k] * schur.z_blocks[cc.offset + k];
    w[std::size_t(nc) * nc + c] = z;
  });
  return w;
}

// The energy at the implicit positions: for fixed rotations and coordinates
// the optimal V = A11^-1 b gives E = sum_c <M~_c, L_c M~_c> + priors + handle
// constants - b^T A11^-1 b, all from blocks.
double Embedding_solver::Impl::reduced_energy(const Eigen::VectorXd& lambda, const std::vector<Eigen::Matrix3d>& w) const
{
  const int nc = static_cast<int>(clusters.size());
  double e = schur.mean_energy.sum() - 2. * schur.r0.dot(lambda) + lambda.dot((schur.mode_gram + coupling) * lambda) +
             handle_constant;
  for(const Cluster_data& c : clusters)
    for(int k = 0; k < c.number_of_modes(); ++k) e += c.prior[k] * lambda[c.offset + k] * lambda[c.offset + k];
  double b_a_b = schur.b0_z;
  for(int c = 0; c < nc; ++c)
  {
    for(int d = 0; d < nc; ++d)
      b_a_b += trace_product(w[std::size_t(c) * nc + d], rotations[d].transpose() * rotations[c]);
    b_a_b += 2. * trace_product(w[std::size_t(nc) * nc + c], rotations[c]);
  }
  return e - b_a_b;
}

// The rotation fit's covariance from blocks, for rotations `r`:
// C_c = V^T L_c M~_c = sum_d R_d W[d][c] + (X_c^T Z)^T.
Eigen::Matrix3d Embedding_solver::Impl::fit_covariance(int c, const std::vector<Eigen::Matrix3d>& r) const
{
  const int nc = static_cast<int>(clusters.size());
  Eigen::Matrix3d covariance = w_blocks[std::size_t(nc) * nc + c].transpose();
  for(int d = 0; d < nc; ++d) covariance += r[d] * w_blocks[std::size_t(d) * nc + c];
  return covariance;
}

void Embedding_solver::Impl::reduced_local_step()
{
  const std::vector<Eigen::Matrix3d> previous = rotations;
  for(int c = 0; c < static_cast<int>(clusters.size()); ++c) rotations[c] = closest_rotation(fit_covariance(c, previous));
}

// The gradient of the reduced energy in the rotations, each in its own frame
// (R_c exp([omega]x)). With the coordinates and positions optimal for the
// rotations, only the explicit dependence counts: dE/dR_c = -2 C_c with C_c
// the covariance of the rotation fit, whose skew part in R_c's frame is the
// gradient.
Eigen::VectorXd Embedding_solver::Impl::rotation_gradient() const
{
  const int nc = static_cast<int>(clusters.size());
  Eigen::VectorXd g(3 * nc);
  for(int c = 0; c < nc; ++c)
  {
    const Eigen::Matrix3d m = rotations[c].transpose() * fit_covariance(c, rotations);
    g.segment<3>(3 * c) = -2. * Eigen::Vector3d(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
  }
  return g;
}

// Coordinates and implicit positions optimal for the current rotations (the
// reduced global step); the reduced energy there. `timings`, when given,
// receives the time of each phase.
double Embedding_solver::Impl::settle_at_rotations(Iteration_timings* timings)
{
  Iteration_timings unused;
  Iteration_timings& t = timings ? *timings : unused;
  internal::Lap_timer clock;
  Eigen::VectorXd lambda = solve_coordinates();
  t.schur_ms += clock.lap();
  std::vector<Eigen::Matrix3d> w = w_of(lambda);
  t.right_hand_side_ms += clock.lap();
  const double e = reduced_energy(lambda, w);
  t.energy_ms += clock.lap();
  if(!lambda.allFinite()) check_finite(positions, lambda);
  if(!std::isfinite(e)) fail_on_non_finite_energy(positions_from(lambda), lambda);
  coordinates = std::move(lambda);
  w_blocks = std::move(w);
  implicit = true;
  positions_valid = false;
  return e;
}

// A drag moves its handles a little each frame, and each cluster turns on
// much as it turned in the frame before: the solve starts at the rotations
// so predicted (each the last solve's turned once more by its last turn)
// when they give a lower energy than the last solve's. Returns the energy
// it starts from.
double Embedding_solver::Impl::start_at_predicted_rotations(double energy)
{
  if(solved_rotations.size() < 2 || solved_rotations.back() != rotations) return energy;
  const std::vector<Eigen::Matrix3d>& before = solved_rotations.front();
  const Implicit_state kept = save_implicit();
  for(std::size_t c = 0; c < rotations.size(); ++c) rotations[c] = rotations[c] * (before[c].transpose() * rotations[c]);
  double predicted = std::numeric_limits<double>::infinity();
  try
  {
    predicted = settle_at_rotations();
  }
  catch(const Computation_error&)
  {
    // A turn too large for the coordinate system is only a failed guess.
  }
  if(predicted < energy) return predicted;
  restore_implicit(kept);
  return energy;
}

void Embedding_solver::Impl::remember_solved_rotations()
{
  solved_rotations.push_back(rotations);
  if(solved_rotations.size() > 2) solved_rotations.erase(solved_rotations.begin());
}

// From the rest state, start at the best rigid placement of the handles
// when it fits them better: a rigid edit is then solved at once.
void Embedding_solver::Impl::start_at_rigid_fit_of_handles()
{
  if(handle_vertices.size() < 3) return;
  Point_matrix rest(handle_vertices.size(), 3);
  for(std::size_t h = 0; h < handle_vertices.size(); ++h) rest.row(h) = mesh.points.row(handle_vertices[h]);
  const Rigid_motion motion = fit_rigid_motion(rest, handle_targets);
  if((motion.apply(rest) - handle_targets).squaredNorm() >= (rest - handle_targets).squaredNorm()) return;
  positions = motion.apply(mesh.points);
  implicit = false;
  positions_valid = true;
  local_step();
}

// The state Anderson acceleration combines: rotations and coordinates when
// positions are implicit (so that iterations stay independent of the vertex
// count), positions and coordinates otherwise.
Eigen::VectorXd Embedding_solver::Impl::packed_state() const
{
  const bool reduced = global_step->implicit_positions();
  const int nc = static_cast<int>(clusters.size());
  Eigen::VectorXd x(reduced ? 9 * nc + total_modes : 3 * n + total_modes);
  if(reduced)
    for(int c = 0; c < nc; ++c) x.segment<9>(9 * c) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(rotations[c].data());
  else
    for(int a = 0; a < 3; ++a) x.segment(a * n, n) = positions.col(a);
  x.tail(total_modes) = coordinates;
  return x;
}

// Moves to the packed state `x` (rotations projected onto SO(3)) and returns its energy.
double Embedding_solver::Impl::enter_state(const Eigen::VectorXd& x)
{
  coordinates = x.tail(total_modes);
  if(global_step->implicit_positions())
  {
    for(int c = 0; c < static_cast<int>(clusters.size()); ++c)
      rotations[c] = closest_rotation(Eigen::Map<const Eigen::Matrix3d>(x.segment<9>(9 * c).data()));
    w_blocks = w_of(coordinates);
    return reduced_energy(coordinates, w_blocks);
  }
  for(int a = 0; a < 3; ++a) positions.col(a) = x.segment(a * n, n);
  local_step();
  return energy_of(positions, coordinates);
}

// Moves to the packed `candidate` when its energy is below `energy` (then
// updated); otherwise stays in the current state, the packed `plain`.
bool Embedding_solver::Impl::take_if_lower(const Eigen::VectorXd& candidate, const Eigen::VectorXd& plain,
                                           double& energy)
{
  const std::vector<Eigen::Matrix3d> plain_rotations = rotations, plain_w = w_blocks;
  const Point_matrix plain_positions = global_step->implicit_positions() ? Point_matrix() : positions;
  const double e = candidate.allFinite() ? enter_state(candidate) : std::numeric_limits<double>::infinity();
  if(e < energy)
  {
    energy = e;
    return true;
  }
  coordinates = plain.tail(total_modes);
  rotations = plain_rotations;
  w_blocks = plain_w;
  if(!global_step->implicit_positions()) positions = plain_positions;
  return false;
}

// Each step minimizes the energy over its block of unknowns, so a rise
// beyond rounding means the numbers, not the model, went wrong.
void Embedding_solver::Impl::check_not_diverging(double e, double best, int& rises, int iteration)
{
  const double rounding = 1e-9 * energy_unit();
  if(e > best + 1e-3 * std::max(best, rounding)) ++rises;
  else rises = 0;
  if(rises >= 3 || e > best + 1e3 * std::max(best, rounding))
    throw Computation_error("embedding: diverging in iteration " + std::to_string(iteration) + " (energy " +
                            std::to_string(e) + ", lowest " + std::to_string(best) + "), mostly in " +
                            largest_energy_term(materialized_positions(), coordinates) +
                            "; the previous state is kept");
}

// After an iteration from the settled rotations `start` (energy
// `start_energy`, gradient `gradient`) reached a state of `energy`: with
// `try_step`, the L-BFGS step on the rotations from `start` replaces that
// state where it lowers the energy more. One trial, no line search, so that
// an iteration costs two energy evaluations as with Anderson's
// extrapolation. The step kept feeds the memory; `gradient` becomes the new
// state's.
double Embedding_solver::Impl::quasi_newton_improve(internal::Rotation_lbfgs& lbfgs,
                                                    const std::vector<Eigen::Matrix3d>& start, double start_energy,
                                                    Eigen::VectorXd& gradient, double energy, bool try_step)
{
  double best = energy;
  Eigen::VectorXd step = internal::rotation_step(start, rotations);
  if(try_step && !lbfgs.empty())
  {
    const Implicit_state kept = save_implicit();
    const Eigen::VectorXd direction = lbfgs.direction(gradient);
    const double slope = gradient.dot(direction);
    bool taken = false;
    if(slope < 0.)
    {
      rotations = internal::retract(start, direction);
      const double e = settle_at_rotations();
      taken = e < best && e <= start_energy + 1e-4 * slope;
      if(taken)
      {
        best = e;
        step = direction;
      }
    }
    if(!taken) restore_implicit(kept);
  }
  const Eigen::VectorXd g = rotation_gradient();
  lbfgs.remember(step, g - gradient);
  gradient = g;
  return best;
}

const Point_matrix& Embedding_solver::Impl::materialized_positions()
{
  if(!positions_valid)
  {
    positions = positions_from(coordinates);
    positions_valid = true;
  }
  return positions;
}

// One cluster's edge and prior terms. With one rotation per cluster each
// vertex's offset from its turned target is computed once, and an edge's
// term is the difference of two offsets; the positions are read as rows of
// a local copy (a column-major `Point_matrix` keeps a vertex's coordinates
// a column apart).
double Embedding_solver::Impl::cluster_energy(std::size_t c, const Point_matrix& v, const Eigen::VectorXd& lambda) const
{
  const Cluster_data& d = clusters[c];
  const Eigen::Index size = Eigen::Index(d.vertices.size());
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  const Point_matrix m = target_shape(d, lambda);
  double e = 0.;
  if(rotation_groups.per_cluster())
  {
    Rows offset(size, 3);
    offset.noalias() = -m * rotation_groups.cluster_transform(int(c), rotations).transpose();
    for(Eigen::Index i = 0; i < size; ++i) offset.row(i) += v.row(d.vertices[std::size_t(i)]);
    for(const Weighted_edge& edge : d.edges) e += edge.w * (offset.row(edge.i) - offset.row(edge.j)).squaredNorm();
  }
  else
  {
    Rows at(size, 3);
    for(Eigen::Index i = 0; i < size; ++i) at.row(i) = v.row(d.vertices[std::size_t(i)]);
    for(const Weighted_edge& edge : d.edges)
    {
      const Eigen::Matrix3d transform = rotation_groups.edge_transform(static_cast<int>(c), edge, rotations);
      e += edge.w * ((at.row(edge.i) - at.row(edge.j)).transpose() - transform * (m.row(edge.i) - m.row(edge.j)).transpose())
                      .squaredNorm();
    }
  }
  for(int k = 0; k < d.number_of_modes(); ++k) e += d.prior[k] * lambda[d.offset + k] * lambda[d.offset + k];
  return e;
}

double Embedding_solver::Impl::energy_of(const Point_matrix& v, const Eigen::VectorXd& lambda, int only) const
{
  if(only >= 0) return cluster_energy(std::size_t(only), v, lambda);
  // The clusters' terms in parallel, summed in order so that the energy
  // does not depend on the scheduling.
  std::vector<double> terms(clusters.size());
  const auto term = [&](std::size_t c) { terms[c] = cluster_energy(c, v, lambda); };
  internal::parallel_for_each_index(clusters.size(), term);
  double e = 0.;
  for(double t : terms) e += t;
  e += lambda.dot(coupling * lambda);
  const double handle_weight = options.handle_weight * mean_diagonal;
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
    e += handle_weight * (v.row(handle_vertices[h]) - handle_targets.row(h)).squaredNorm();
  for(int i : anchored) e += anchor[i] * (v.row(i) - mesh.points.row(i)).squaredNorm();
  return e;
}

void Embedding_solver::Impl::check_finite(const Point_matrix& v, const Eigen::VectorXd& lambda) const
{
  if(v.allFinite() && lambda.allFinite()) return;
  for(const Cluster_data& c : clusters)
  {
    bool bad = !lambda.segment(c.offset, c.number_of_modes()).allFinite();
    for(int i : c.vertices) bad = bad || !v.row(i).allFinite();
    if(bad) throw Computation_error("embedding: non-finite result in " + c.name + "; the previous state is kept");
  }
  throw Computation_error("embedding: non-finite result; the previous state is kept");
}

// Finite iterates can still give an energy that overflows (a handle target
// astronomically far away): name the term that does.
void Embedding_solver::Impl::fail_on_non_finite_energy(const Point_matrix& v, const Eigen::VectorXd& lambda) const
{
  check_finite(v, lambda);
  // A far target drags every handle of its piece along: blame the handle
  // whose target is farthest from its rest position.
  const double handle_weight = options.handle_weight * mean_diagonal;
  std::size_t farthest = handle_vertices.size();
  bool overflow = false;
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
  {
    overflow = overflow || !std::isfinite(handle_weight * (v.row(handle_vertices[h]) - handle_targets.row(h)).squaredNorm());
    const double reach = (handle_targets.row(h) - mesh.points.row(handle_vertices[h])).norm();
    if(farthest == handle_vertices.size() ||
       reach > (handle_targets.row(farthest) - mesh.points.row(handle_vertices[farthest])).norm())
      farthest = h;
  }
  if(overflow)
    throw Computation_error("embedding: the energy of handle " + std::to_string(farthest) + " (vertex " +
                            std::to_string(handle_vertices[farthest]) +
                            ") overflows (its target is too far away); the previous state is kept");
  for(std::size_t c = 0; c < clusters.size(); ++c)
    if(!std::isfinite(energy_of(v, lambda, static_cast<int>(c))))
      throw Computation_error("embedding: the energy of " + clusters[c].name +
                              " overflows (its vertices are too far from its shape space); the previous state is kept");
  throw Computation_error("embedding: the energy overflows; the previous state is kept");
}

// The term holding most of the energy: where a diverging solve went wrong.
std::string Embedding_solver::Impl::largest_energy_term(const Point_matrix& v, const Eigen::VectorXd& lambda) const
{
  std::string worst = "the handles";
  double worst_energy = 0.;
  const double handle_weight = options.handle_weight * mean_diagonal;
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
    worst_energy += handle_weight * (v.row(handle_vertices[h]) - handle_targets.row(h)).squaredNorm();
  for(std::size_t c = 0; c < clusters.size(); ++c)
  {
    const double e = energy_of(v, lambda, static_cast<int>(c));
    if(!(e <= worst_energy))
    {
      worst_energy = e;
      worst = clusters[c].name;
    }
  }
  return worst;
}

} // namespace MPM
} // namespace CGAL
