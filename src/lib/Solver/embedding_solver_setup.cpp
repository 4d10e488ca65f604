// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Embedding_solver_impl.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Cotangent_weights.h>
#include <CGAL/MPM/internal/Parallel_for.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <string>

namespace CGAL {
namespace MPM {

using namespace internal::embedding;

Embedding_solver::Impl::Impl(const Embedding_problem& problem, const Embedding_options& o)
  : options(o), mesh(problem.mesh), n(problem.mesh.number_of_vertices())
{
  origin = n > 0 ? Eigen::RowVector3d(mesh.points.colwise().mean()) : Eigen::RowVector3d::Zero();
  mesh.points.rowwise() -= origin;
  if(!(problem.sigma_sub > 0) || !std::isfinite(problem.sigma_sub))
    throw Input_error("embedding problem", "sigma_sub", "must be positive and finite");
  // A negative weight makes the system indefinite and the energy unbounded.
  const auto require = [](bool ok, const std::string& option, double value, const std::string& rule) {
    if(!ok) throw Input_error("embedding options", option, "must be " + rule + " (got " + std::to_string(value) + ")");
  };
  require(o.handle_weight > 0 && std::isfinite(o.handle_weight), "handle_weight", o.handle_weight, "positive and finite");
  require(o.anchor_weight >= 0 && std::isfinite(o.anchor_weight), "anchor_weight", o.anchor_weight, "non-negative and finite");
  require(o.coupling_weight >= 0 && std::isfinite(o.coupling_weight), "coupling_weight", o.coupling_weight,
          "non-negative and finite");
  require(o.tolerance >= 0 && std::isfinite(o.tolerance), "tolerance", o.tolerance, "non-negative and finite");
  require(o.max_iterations >= 0, "max_iterations", o.max_iterations, "non-negative");
  require(o.anderson_history >= 0, "anderson_history", o.anderson_history, "non-negative");
  if(!problem.mesh.points.allFinite())
    throw Input_error("embedding problem", "rest positions", "contain non-finite coordinates");
  prepare_clusters(problem);

  std::vector<Eigen::Triplet<double>> triplets;
  for(const Cluster_data& c : clusters)
    for(int k = 0; k < c.laplacian.outerSize(); ++k)
      for(Sparse::InnerIterator it(c.laplacian, k); it; ++it)
        triplets.emplace_back(c.vertices[it.row()], c.vertices[it.col()], it.value());
  elastic.resize(n, n);
  elastic.setFromTriplets(triplets.begin(), triplets.end());
  double sum = 0.;
  int count = 0;
  for(int i = 0; i < n; ++i)
    if(elastic.coeff(i, i) > 0)
    {
      sum += elastic.coeff(i, i);
      ++count;
    }
  mean_diagonal = count > 0 ? sum / count : 1.;

  std::vector<int> rank(n), parent(n);
  boost::disjoint_sets<int*, int*> sets(rank.data(), parent.data());
  for(int v = 0; v < n; ++v) sets.make_set(v);
  for(const Cluster_data& c : clusters)
    for(const Weighted_edge& e : c.edges) sets.union_set(c.vertices[e.i], c.vertices[e.j]);
  component.resize(n);
  for(int v = 0; v < n; ++v) component[v] = sets.find_set(v);

  for(const Cluster_data& c : clusters)
    for(int k = 0; k < c.number_of_modes(); ++k) cluster_of_mode.push_back(static_cast<int>(&c - clusters.data()));

  coupling = Eigen::MatrixXd::Zero(total_modes, total_modes);
  for(const auto& [a, b] : problem.coupled_clusters)
  {
    if(a < 0 || b < 0 || a >= int(clusters.size()) || b >= int(clusters.size()) || a == b ||
       clusters[a].number_of_modes() != clusters[b].number_of_modes())
      throw Input_error("embedding problem", "coupled clusters (" + std::to_string(a) + ", " + std::to_string(b) + ")",
                        "must be two distinct clusters with the same number of modes");
    const Cluster_data& ca = clusters[a];
    const Cluster_data& cb = clusters[b];
    for(int k = 0; k < ca.number_of_modes(); ++k)
    {
      const double w = options.coupling_weight * 0.5 * (ca.prior[k] + cb.prior[k]);
      coupling(ca.offset + k, ca.offset + k) += w;
      coupling(cb.offset + k, cb.offset + k) += w;
      coupling(ca.offset + k, cb.offset + k) -= w;
      coupling(cb.offset + k, ca.offset + k) -= w;
    }
  }

  // Per-vertex rotations have no rotation-commuting structure to exploit.
  if(options.rotations == Rotations::per_vertex) options.global_step = Global_step::direct;
  global_step = make_global_step(options.global_step);
  positions = mesh.points;
  coordinates = Eigen::VectorXd::Zero(total_modes);
  rotation_groups = Rotation_groups(clusters, options.rotations);
  rotations.assign(std::size_t(rotation_groups.size()), Eigen::Matrix3d::Identity());
  compute_anchor();
  local_step();
}

// Clusters are independent until their coordinates are numbered: they are
// prepared in parallel (TBB), and the first bad one in order is reported.
void Embedding_solver::Impl::prepare_clusters(const Embedding_problem& problem)
{
  std::vector<Cluster_data> prepared(problem.clusters.size());
  std::vector<std::exception_ptr> failure(problem.clusters.size());
  const auto prepare = [&](std::size_t c) {
    try {
      prepared[c] = prepared_cluster(problem.clusters[c], problem.sigma_sub, static_cast<int>(c));
    } catch(...) {
      failure[c] = std::current_exception();
    }
  };
  internal::parallel_for_each_index(problem.clusters.size(), prepare);
  for(const std::exception_ptr& e : failure)
    if(e) std::rethrow_exception(e);
  for(Cluster_data& d : prepared)
  {
    d.offset = total_modes;
    total_modes += d.number_of_modes();
  }
  clusters = std::move(prepared);
}

Cluster_data Embedding_solver::Impl::prepared_cluster(const Cluster& c, double sigma_sub, int index) const
{
  const std::string name = c.name.empty() ? "cluster " + std::to_string(index) : c.name;
  const int nc = static_cast<int>(c.vertices.size());
  const auto fail = [&](const std::string& what) { throw Input_error("embedding problem", name, what); };
  if(c.mean.rows() != nc) fail("mean has " + std::to_string(c.mean.rows()) + " points for " + std::to_string(nc) + " vertices");
  if(!c.mean.allFinite()) fail("mean has non-finite coordinates");
  if(c.modes.rows() != 3 * nc && c.modes.cols() > 0) fail("modes have the wrong size");
  if(c.sigmas.size() != c.modes.cols()) fail("one standard deviation per mode is needed");
  for(int k = 0; k < c.sigmas.size(); ++k)
    if(!(c.sigmas[k] > 0) || !std::isfinite(c.sigmas[k])) fail("standard deviation " + std::to_string(k) + " is not positive");
  for(int v : c.vertices)
    if(v < 0 || v >= n) fail("vertex " + std::to_string(v) + " is out of range");
  for(const Cluster_edge& e : c.edges)
    if(e.source < 0 || e.source >= nc || e.target < 0 || e.target >= nc || e.source == e.target)
      fail("edge (" + std::to_string(e.source) + ", " + std::to_string(e.target) + ") is invalid");
  for(const Triangle& t : c.triangles)
    for(int k = 0; k < 3; ++k)
      if(t[k] < 0 || t[k] >= nc) fail("triangle corner out of range");

  Cluster_data d;
  d.name = name;
  d.vertices = c.vertices;
  d.mean = c.mean;

  // Cotangent weights measured on the mean, under the package's one clamping
  // rule (internal/Cotangent_weights.h): a sliver of a scanned mesh would
  // otherwise drown the system in rounding.
  const std::map<std::pair<int, int>, double> cotangent = internal::cotangent_weights(c.mean, c.triangles);

  std::vector<double> blend(nc, 1.);
  if(!c.border.empty())
  {
    double sigma_bound = c.sigma_bound;
    if(!(sigma_bound > 0))
      sigma_bound = internal::bounding_box_diagonal(c.mean) / 3.;
    const std::vector<double> distance = internal::edge_graph_distances(c.mean, c.edges, c.border);
    for(int v = 0; v < nc; ++v)
      blend[v] = std::isfinite(distance[v]) ? 1. - std::exp(-distance[v] * distance[v] / (sigma_bound * sigma_bound)) : 1.;
  }
  const double inverse_variance = 1. / (sigma_sub * sigma_sub);
  std::vector<Eigen::Triplet<double>> triplets;
  for(const Cluster_edge& e : c.edges)
  {
    double w = 1.; // uniform on virtual and non-manifold edges
    const auto it = cotangent.find({std::min(e.source, e.target), std::max(e.source, e.target)});
    if(!e.is_virtual && it != cotangent.end()) w = it->second;
    // The blend fades a cluster toward its border, but never to exactly zero.
    w *= std::max(0.5 * (blend[e.source] + blend[e.target]), 1e-3) * inverse_variance;
    d.edges.push_back({e.source, e.target, w});
    triplets.emplace_back(e.source, e.source, w);
    triplets.emplace_back(e.target, e.target, w);
    triplets.emplace_back(e.source, e.target, -w);
    triplets.emplace_back(e.target, e.source, -w);
  }
  d.laplacian.resize(nc, nc);
  d.laplacian.setFromTriplets(triplets.begin(), triplets.end());
  d.laplacian_mean = d.laplacian * d.mean;
  for(int k = 0; k < c.modes.cols(); ++k)
  {
    Point_matrix b(nc, 3);
    for(int i = 0; i < nc; ++i) b.row(i) = c.modes.col(k).segment<3>(3 * i).transpose();
    d.laplacian_modes.push_back(d.laplacian * b);
    d.modes.push_back(std::move(b));
  }
  d.prior = (0.25 * c.sigmas.array().square().inverse()).matrix();
  return d;
}

Point_matrix Embedding_solver::Impl::target_shape(const Cluster_data& c, const Eigen::VectorXd& lambda) const
{
  Point_matrix m = c.mean;
  for(int k = 0; k < c.number_of_modes(); ++k) m += lambda[c.offset + k] * c.modes[k];
  return m;
}

// Pieces no handle reaches are anchored weakly to the rest positions: the
// energy is blind to their translation and rotation. One vertex per piece,
// the one nearest its rest centroid, fixes the translation and pulls on
// nothing else. Anchoring every vertex also pulled the piece's orientation
// back toward rest, ever more weakly: an edit that turns parts (symmetrize)
// then crept for a hundred iterations after its shape had settled.
void Embedding_solver::Impl::compute_anchor()
{
  anchor = anchor_for(handle_vertices);
  anchored.clear();
  anchor_constant = 0.;
  for(int v = 0; v < n; ++v)
    if(anchor[v] > 0)
    {
      anchored.push_back(v);
      anchor_constant += anchor[v] * mesh.points.row(v).squaredNorm();
    }
}

Eigen::VectorXd Embedding_solver::Impl::anchor_for(const std::vector<int>& handles) const
{
  std::vector<bool> held(n, false);
  for(int v : handles) held[component[v]] = true;
  std::map<int, std::pair<Eigen::RowVector3d, int>> centroid; // per free piece: sum of points, count
  for(int v = 0; v < n; ++v)
    if(!held[component[v]])
    {
      auto& [sum, count] = centroid.try_emplace(component[v], Eigen::RowVector3d::Zero(), 0).first->second;
      sum += mesh.points.row(v);
      ++count;
    }
  std::map<int, int> nearest;
  for(int v = 0; v < n; ++v)
  {
    const auto it = centroid.find(component[v]);
    if(it == centroid.end()) continue;
    const Eigen::RowVector3d c = it->second.first / it->second.second;
    const auto [best, added] = nearest.try_emplace(component[v], v);
    if(!added && (mesh.points.row(v) - c).squaredNorm() < (mesh.points.row(best->second) - c).squaredNorm())
      best->second = v;
  }
  // The energy is blind to the piece's translation, which this one vertex
  // alone fixes, so its weight changes no solution; as stiff as a handle,
  // the factored block stays as well conditioned when a piece's anchor is
  // traded for handles by a low-rank update (`update_handle_set()`).
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(n);
  for(const auto& [piece, v] : nearest) weights[v] = options.anchor_weight * mean_diagonal;
  return weights;
}

// What the anchors and handles of a handle set add to the vertex block's diagonal.
Eigen::VectorXd Embedding_solver::Impl::diagonal_terms(const std::vector<int>& handles) const
{
  Eigen::VectorXd d = anchor_for(handles);
  for(int v : handles) d[v] += options.handle_weight * mean_diagonal;
  return d;
}

void Embedding_solver::Impl::factor()
{
  std::unique_ptr<Vertex_block> replacement = make_vertex_block(options.sparse_solver);
  if(!replacement->factor(elastic, diagonal_terms(handle_vertices)))
  {
    const int row = replacement->weakest_row();
    std::string where = "a cluster may be degenerate";
    for(const Cluster_data& c : clusters)
      if(row >= 0 && std::find(c.vertices.begin(), c.vertices.end(), row) != c.vertices.end())
      {
        where = "at vertex " + std::to_string(row) + " of " + c.name;
        break;
      }
    throw Computation_error("embedding: the vertex block is not positive definite (" + where + ")");
  }
  block = std::move(replacement);
  factored = true;
  handle_terms_ready = false;
  handle_columns_valid = false;

  if(global_step->uses_blocks()) schur.build(clusters, cluster_of_mode, coupling, *block);
  factored_rotations.clear();
  solved_rotations.clear();
}

// Accepts `vertices` as a low-rank change of the factored block when few
// diagonal entries differ from it (handles added, removed or moved, and the
// anchors of pieces that gained or lost their handles); false asks for a
// refactorization. A solver factored once, without handles, so serves every
// later handle set of up to `max_update` vertices.
bool Embedding_solver::Impl::update_handle_set(const std::vector<int>& vertices)
{
  constexpr Eigen::Index max_update = 64;
  if(!factored || !block->update(diagonal_terms(vertices), max_update)) return false;
  handle_columns_valid = false;
  if(global_step->uses_blocks()) schur.update(clusters, *block);
  factored_rotations.clear();
  solved_rotations.clear();
  return true;
}

// The anchors' part of b0: each anchored vertex pulled to its rest position.
Point_matrix Embedding_solver::Impl::anchor_right_hand_side() const
{
  Point_matrix b = Point_matrix::Zero(n, 3);
  for(int v : anchored) b.row(v) = anchor[v] * mesh.points.row(v);
  return b;
}

// The handle terms of the blocks, from A11^-1 b0. A drag moves the targets
// of the same handles, so with up to 48 handles the solutions for each
// handle's unit right-hand side (and for the anchors) are computed once per
// handle set, and the terms are affine in the targets
// (Schur_blocks::set_handle_basis()): a frame sets them without a
// back-substitution or a pass over the vertices (measured on a 64k-vertex
// frame: 4 ms less without the back-substitution, 4 ms less without the pass).
void Embedding_solver::Impl::set_block_handle_terms()
{
  constexpr std::size_t max_kept_columns = 48;
  if(handle_vertices.size() > max_kept_columns)
  {
    schur.set_handle_terms(clusters, b0, block->solve(b0));
    return;
  }
  if(!handle_columns_valid || handle_columns_for != handle_vertices)
  {
    const Eigen::Index k = Eigen::Index(handle_vertices.size());
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, k + 3);
    for(Eigen::Index h = 0; h < k; ++h) rhs(handle_vertices[std::size_t(h)], h) = 1.;
    rhs.rightCols<3>() = anchor_right_hand_side();
    Eigen::MatrixXd solved = block->solve(rhs);
    // Through a low-rank update the solutions carry a larger rounding, which
    // the reduced energy (the handle constant minus b0^T z, two sums of the
    // handles' stiffness times their squared targets) would magnify: one
    // step of iterative refinement against the updated block.
    if(!block->update_vertices().empty()) solved += block->solve(rhs - block->product(solved));
    schur.set_handle_basis(clusters, rhs.rightCols<3>(), solved.rightCols<3>(), handle_vertices, solved.leftCols(k));
    handle_columns_for = handle_vertices;
    handle_columns_valid = true;
  }
  schur.set_handle_targets(options.handle_weight * mean_diagonal * handle_targets);
}

void Embedding_solver::Impl::prepare_handle_terms()
{
  if(!factored) factor();
  b0 = anchor_right_hand_side();
  const double handle_weight = options.handle_weight * mean_diagonal;
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
    b0.row(handle_vertices[h]) += handle_weight * handle_targets.row(h);
  handle_constant = anchor_constant;
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
    handle_constant += handle_weight * handle_targets.row(h).squaredNorm();
  if(global_step->uses_blocks()) set_block_handle_terms();
  factored_rotations.clear();
  handle_terms_ready = true;
  // The blocks of the implicit positions depend on the handle terms.
  if(implicit) w_blocks = w_of(coordinates);
}

} // namespace MPM
} // namespace CGAL
