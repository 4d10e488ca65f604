// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Embedding_solver.h>
#include <CGAL/MPM/internal/Rotation_lbfgs.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Shape_space.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Weights/utils.h>

#include <Eigen/Cholesky>
#include <Eigen/SVD>
#include <Eigen/SparseCholesky>
#ifdef CGAL_MPM_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <boost/pending/disjoint_sets.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <type_traits>

namespace CGAL {
namespace MPM {

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Kernel = CGAL::Simple_cartesian<double>;

// The constant vertex block is factored through CGAL's solver traits, so any
// Eigen-compatible direct solver plugs in the same way.
class Vertex_block_solver
{
public:
  virtual ~Vertex_block_solver() = default;
  virtual bool factor(const Sparse& a) = 0;
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& b) = 0;
  // After a failed factor(): the row with the smallest pivot, or -1 when the
  // solver does not tell.
  virtual int weakest_row() const { return -1; }
};

// LDLT factors an indefinite matrix without complaint (LLT refuses it): the
// pivots say whether the matrix was positive definite, and where not.
template <class Ldlt>
int non_positive_pivot_row(const Ldlt& ldlt)
{
  const Eigen::VectorXd& pivots = ldlt.vectorD();
  Eigen::Index weakest = 0;
  if(pivots.size() == 0) return -1;
  for(Eigen::Index i = 0; i < pivots.size(); ++i)
    if(!(pivots[i] >= pivots[weakest])) weakest = i;
  if(pivots[weakest] > 0) return -1;
  return ldlt.permutationPinv().indices()[weakest];
}

template <class EigenSolver>
class Traits_solver : public Vertex_block_solver
{
public:
  bool factor(const Sparse& a) override
  {
    matrix_ = std::make_unique<typename Traits::Matrix>(a);
    double d;
    if(!traits_.factor(*matrix_, d)) return false;
    if constexpr(std::is_same_v<EigenSolver, Eigen::SimplicialLDLT<Sparse>>)
      return (weakest_ = non_positive_pivot_row(traits_.solver())) < 0;
    return true;
  }

  int weakest_row() const override { return weakest_; }
  // Columns are independent triangular solves: on large meshes they run in
  // parallel, which is most of the cost of a displayed frame.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) override
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(b.rows() > 20000 && b.cols() > 1)
    {
      Eigen::MatrixXd x(b.rows(), b.cols());
      tbb::parallel_for(Eigen::Index(0), b.cols(), [&](Eigen::Index j) { x.col(j) = traits_.solver().solve(b.col(j)); });
      return x;
    }
#endif
    return traits_.solver().solve(b);
  }

private:
  using Traits = CGAL::Eigen_solver_traits<EigenSolver>;
  Traits traits_;
  std::unique_ptr<typename Traits::Matrix> matrix_;
  int weakest_ = -1;
};

std::unique_ptr<Vertex_block_solver> make_vertex_block_solver(Sparse_solver which)
{
#ifdef CGAL_MPM_HAS_CHOLMOD
  if(which == Sparse_solver::cholmod)
    return std::make_unique<Traits_solver<Eigen::CholmodSupernodalLLT<Sparse>>>();
#else
  (void)which;
#endif
  return std::make_unique<Traits_solver<Eigen::SimplicialLDLT<Sparse>>>();
}

// Closest rotation (no reflection) to a 3x3 matrix, maximizing <R, k>.
Eigen::Matrix3d closest_rotation(const Eigen::Matrix3d& k)
{
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(k, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  if((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0) d(2, 2) = -1;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

Kernel::Point_3 point(const Point_matrix& p, int i) { return Kernel::Point_3(p(i, 0), p(i, 1), p(i, 2)); }

struct Weighted_edge
{
  int i, j;
  double w;
};

struct Cluster_data
{
  std::string name;
  std::vector<int> vertices;
  std::vector<Weighted_edge> edges;   // weights include sigma_sub^-2 and the blend
  Sparse laplacian;                   // local, n_c x n_c
  Point_matrix mean;
  std::vector<Point_matrix> modes;    // n_c x 3 each
  Eigen::VectorXd prior;              // 1 / (4 sigma_k^2)
  Point_matrix laplacian_mean;        // L M
  std::vector<Point_matrix> laplacian_modes; // L B_k
  int offset = 0;                     // of its coordinates in the stacked vector
  int number_of_modes() const { return static_cast<int>(modes.size()); }
};

double trace_product(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) { return (a.array() * b.transpose().array()).sum(); }

} // namespace

struct Embedding_solver::Impl
{
  Embedding_options options;
  Indexed_mesh mesh;
  int n = 0;
  std::vector<Cluster_data> clusters;
  int total_modes = 0;
  Sparse elastic;                 // sum of cluster Laplacians, n x n
  double mean_diagonal = 1.;
  std::vector<int> component;     // connected piece of each vertex (through cluster edges)

  // Handles.
  std::vector<int> handle_vertices;
  Point_matrix handle_targets;
  bool factored = false;
  // A change of handle vertices that keeps the handled pieces is a low-rank
  // (Woodbury) update of the factored block: A = A_f + U diag(w) U^T with U
  // the changed vertices, A^-1 = A_f^-1 - C K^-1 C^T, C = A_f^-1 U,
  // K = diag(1/w) + U^T C.
  std::vector<int> factored_handles;
  std::vector<int> update_vertices;
  Eigen::VectorXd update_weights;
  Eigen::MatrixXd update_columns;      // C, n x k
  Eigen::MatrixXd capacitance_inverse; // K^-1
  std::vector<Eigen::Matrix3d> h_base, g_base, plm_base, qlm_base; // blocks of A_f
  bool handle_terms_ready = false;
  Eigen::VectorXd anchor;         // per-vertex anchor weight
  Sparse system;                  // A11
  std::unique_ptr<Vertex_block_solver> solver;

  // Schur blocks, 3x3 each: H[ck][dl] = (L_c B_ck)^T Q_dl, G[ck][d] = (L_c B_ck)^T P_d,
  // Gz[ck] = (L_c B_ck)^T Z, with Q = A11^-1 L B, P = A11^-1 L M, Z = A11^-1 b0.
  std::vector<Eigen::Matrix3d> h_blocks, g_blocks, z_blocks;
  Eigen::MatrixXd coupling;       // coupled-coordinates term, total_modes x total_modes
  Eigen::MatrixXd mode_gram;      // <B_ck, L_c B_cl>, block diagonal
  Eigen::VectorXd mean_energy;    // <M_c, L_c M_c> per cluster
  // For the reduced step, with X_c = L_c (M_c + sum_k lambda_ck B_ck):
  // plm[d][c] = P_d^T L_c M_c, qlm[dl][c] = Q_dl^T L_c M_c, zlm[c] = Z^T L_c M_c,
  // so that W[c][d] = X_c^T A11^-1 X_d is a short sum of blocks.
  std::vector<Eigen::Matrix3d> plm_blocks, qlm_blocks, zlm_blocks;
  double handle_constant = 0.;    // sum w_h |y_h|^2 + anchors
  double b0_z = 0.;               // <b0, Z>
  Eigen::MatrixXd s0;             // constant part of the Schur complement
  Eigen::VectorXd r0;             // constant part of its right-hand side
  Point_matrix b0;                // handle and anchor right-hand side
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
  std::vector<Eigen::Matrix3d> rotations;
  std::vector<std::vector<Eigen::Matrix3d>> vertex_rotations; // per cluster point, with Rotations::per_vertex
  int iterations_since_reset = 0;
  Iteration_timings timings; // of the last iterate()

  Impl(const Embedding_problem& problem, const Embedding_options& o);
  void prepare_cluster(const Cluster& c, double sigma_sub, int index);
  void compute_anchor();
  void factor();
  bool update_handle_set(const std::vector<int>& vertices);
  void apply_update();
  Eigen::MatrixXd solve_a11(const Eigen::MatrixXd& rhs) const;
  void prepare_handle_terms();
  Eigen::MatrixXd scatter(const Cluster_data& c, const Point_matrix& local) const;
  Eigen::MatrixXd gather(const Cluster_data& c, const Eigen::MatrixXd& global) const;
  Point_matrix target_shape(const Cluster_data& c, const Eigen::VectorXd& lambda) const;
  void local_step();
  Eigen::Matrix3d edge_transform(int c, const Weighted_edge& e) const;
  Eigen::Matrix3d fit_covariance(int c, const std::vector<Eigen::Matrix3d>& r) const;
  void start_at_rigid_fit_of_handles();
  Eigen::VectorXd packed_state() const;
  double enter_state(const Eigen::VectorXd& x);
  bool take_if_lower(const Eigen::VectorXd& candidate, const Eigen::VectorXd& plain, double& energy);
  void check_not_diverging(double e, double best, int& rises, int iteration);
  void reduced_local_step();
  Eigen::VectorXd rotation_gradient() const;
  double settle_at_rotations(Iteration_timings* timings = nullptr);
  double quasi_newton_improve(internal::Rotation_lbfgs& lbfgs, const std::vector<Eigen::Matrix3d>& start,
                              double start_energy, Eigen::VectorXd& gradient, double energy, bool try_step);
  Eigen::VectorXd solve_coordinates() const;
  Eigen::MatrixXd positions_rhs(const Eigen::VectorXd& lambda) const;
  Point_matrix positions_from(const Eigen::VectorXd& lambda) const;
  std::vector<Eigen::Matrix3d> w_of(const Eigen::VectorXd& lambda) const;
  double reduced_energy(const Eigen::VectorXd& lambda, const std::vector<Eigen::Matrix3d>& w) const;
  const Point_matrix& materialized_positions();
  void global_step_direct(Point_matrix& v, Eigen::VectorXd& lambda);
  double energy_of(const Point_matrix& v, const Eigen::VectorXd& lambda, int only = -1) const;
  void check_finite(const Point_matrix& v, const Eigen::VectorXd& lambda) const;
  [[noreturn]] void fail_on_non_finite_energy(const Point_matrix& v, const Eigen::VectorXd& lambda) const;
  std::string largest_energy_term(const Point_matrix& v, const Eigen::VectorXd& lambda) const;

  // Everything iterating changes, so that a failed solve leaves the state it found.
  struct State
  {
    Point_matrix positions;
    Eigen::VectorXd coordinates;
    std::vector<Eigen::Matrix3d> rotations, w_blocks;
    std::vector<std::vector<Eigen::Matrix3d>> vertex_rotations;
    bool implicit = false, positions_valid = true;
    int iterations_since_reset = 0;
  };
  State save() const
  {
    return {positions, coordinates, rotations, w_blocks, vertex_rotations, implicit, positions_valid, iterations_since_reset};
  }
  void restore(State s)
  {
    positions = std::move(s.positions);
    coordinates = std::move(s.coordinates);
    rotations = std::move(s.rotations);
    w_blocks = std::move(s.w_blocks);
    vertex_rotations = std::move(s.vertex_rotations);
    implicit = s.implicit;
    positions_valid = s.positions_valid;
    iterations_since_reset = s.iterations_since_reset;
  }
  // The energy of one handle a bounding-box diagonal away from its target:
  // the unit below which energy changes are rounding, not divergence.
  double energy_unit() const
  {
    const double diagonal = n > 0 ? (mesh.points.colwise().maxCoeff() - mesh.points.colwise().minCoeff()).norm() : 1.;
    return options.handle_weight * mean_diagonal * std::max(diagonal * diagonal, std::numeric_limits<double>::min());
  }
};

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
  for(std::size_t c = 0; c < problem.clusters.size(); ++c)
    prepare_cluster(problem.clusters[c], problem.sigma_sub, static_cast<int>(c));

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
  positions = mesh.points;
  coordinates = Eigen::VectorXd::Zero(total_modes);
  rotations.assign(clusters.size(), Eigen::Matrix3d::Identity());
  if(options.rotations == Rotations::per_vertex)
    for(const Cluster_data& c : clusters) vertex_rotations.emplace_back(c.vertices.size(), Eigen::Matrix3d::Identity());
  compute_anchor();
  local_step();
}

void Embedding_solver::Impl::prepare_cluster(const Cluster& c, double sigma_sub, int index)
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

  // Cotangent weights measured on the mean: half the cotangent of the
  // opposite angle per adjacent triangle. Negative ones are clamped (to a
  // small fraction of the mean weight) so that the matrix stays positive
  // definite and no edge is left without stiffness. Large ones are bounded
  // as CGAL's clamped cotangent bounds them (cosine within +-0.999, as in
  // its ARAP deformation): a sliver of a scanned mesh (cotangent 4e14 on a
  // PSB octopus) otherwise drowned the whole system in rounding, and the
  // energy rose from the rest pose.
  const double largest_cotangent = 0.999 / std::sqrt(1. - 0.999 * 0.999);
  std::map<std::pair<int, int>, double> cotangent;
  for(const Triangle& t : c.triangles)
    for(int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3], o = t[(k + 2) % 3];
      const double cot = CGAL::Weights::cotangent(point(c.mean, a), point(c.mean, o), point(c.mean, b));
      cotangent[{std::min(a, b), std::max(a, b)}] += std::isfinite(cot) ? 0.5 * std::min(cot, largest_cotangent) : 0.;
    }
  double positive_sum = 0.;
  int positive_count = 0;
  for(const auto& [e, w] : cotangent)
    if(w > 0)
    {
      positive_sum += w;
      ++positive_count;
    }
  const double floor_weight = 1e-2 * (positive_count > 0 ? positive_sum / positive_count : 1.);

  std::vector<double> blend(nc, 1.);
  if(!c.border.empty())
  {
    double sigma_bound = c.sigma_bound;
    if(!(sigma_bound > 0))
      sigma_bound = (c.mean.colwise().maxCoeff() - c.mean.colwise().minCoeff()).norm() / 3.;
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
    if(!e.is_virtual && it != cotangent.end()) w = std::max(it->second, floor_weight);
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
  d.offset = total_modes;
  total_modes += c.modes.cols();
  clusters.push_back(std::move(d));
}

Eigen::MatrixXd Embedding_solver::Impl::scatter(const Cluster_data& c, const Point_matrix& local) const
{
  Eigen::MatrixXd global = Eigen::MatrixXd::Zero(n, 3);
  for(std::size_t i = 0; i < c.vertices.size(); ++i) global.row(c.vertices[i]) += local.row(i);
  return global;
}

Eigen::MatrixXd Embedding_solver::Impl::gather(const Cluster_data& c, const Eigen::MatrixXd& global) const
{
  Eigen::MatrixXd local(c.vertices.size(), global.cols());
  for(std::size_t i = 0; i < c.vertices.size(); ++i) local.row(i) = global.row(c.vertices[i]);
  return local;
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
  std::vector<bool> held(n, false);
  for(int v : handle_vertices) held[component[v]] = true;
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
  // The weight of the piece's vertices together, so that the system is as
  // well conditioned as with every vertex anchored.
  anchor = Eigen::VectorXd::Zero(n);
  for(const auto& [piece, v] : nearest)
    anchor[v] = options.anchor_weight * mean_diagonal * centroid.at(piece).second;
}

void Embedding_solver::Impl::factor()
{
  const double handle_weight = options.handle_weight * mean_diagonal;

  system = elastic;
  for(int v = 0; v < n; ++v) system.coeffRef(v, v) += anchor[v];
  for(int v : handle_vertices) system.coeffRef(v, v) += handle_weight;
  system.makeCompressed();
  solver = make_vertex_block_solver(options.sparse_solver);
  if(!solver->factor(system))
  {
    const int row = solver->weakest_row();
    std::string where = "a cluster may be degenerate";
    for(const Cluster_data& c : clusters)
      if(row >= 0 && std::find(c.vertices.begin(), c.vertices.end(), row) != c.vertices.end())
      {
        where = "at vertex " + std::to_string(row) + " of " + c.name;
        break;
      }
    throw Computation_error("embedding: the vertex block is not positive definite (" + where + ")");
  }
  factored = true;
  handle_terms_ready = false;
  factored_handles = handle_vertices;
  update_vertices.clear();
  update_weights.resize(0);
  update_columns.resize(n, 0);

  if(options.global_step == Global_step::direct) return;
  const int dm = total_modes, nc = static_cast<int>(clusters.size());
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
  h_blocks.assign(std::size_t(dm) * dm, Eigen::Matrix3d::Zero());
  g_blocks.assign(std::size_t(dm) * nc, Eigen::Matrix3d::Zero());
  qlm_blocks.assign(std::size_t(dm) * nc, Eigen::Matrix3d::Zero());
  plm_blocks.assign(std::size_t(nc) * nc, Eigen::Matrix3d::Zero());
  // Right-hand sides are solved in batches to bound memory on large models.
  const int columns = dm + nc;
  const int batch = 16;
  for(int first = 0; first < columns; first += batch)
  {
    const int count = std::min(batch, columns - first);
    Eigen::MatrixXd rhs(n, 3 * count);
    for(int j = 0; j < count; ++j)
    {
      const int column = first + j;
      if(column < dm)
      {
        const Cluster_data& d = clusters[cluster_of_mode[column]];
        rhs.middleCols<3>(3 * j) = scatter(d, d.laplacian_modes[column - d.offset]);
      }
      else
        rhs.middleCols<3>(3 * j) = scatter(clusters[column - dm], clusters[column - dm].laplacian_mean);
    }
    const Eigen::MatrixXd solved = solver->solve(rhs); // of A_f: the update is applied below
    for(const Cluster_data& c : clusters)
    {
      const int ci = static_cast<int>(&c - clusters.data());
      const Eigen::MatrixXd local = gather(c, solved);
      for(int j = 0; j < count; ++j)
      {
        const int column = first + j;
        const Eigen::Matrix3d with_mean = local.middleCols<3>(3 * j).transpose() * c.laplacian_mean;
        if(column < dm) qlm_blocks[std::size_t(column) * nc + ci] = with_mean;
        else plm_blocks[std::size_t(column - dm) * nc + ci] = with_mean;
        for(int k = 0; k < c.number_of_modes(); ++k)
        {
          const Eigen::Matrix3d block = c.laplacian_modes[k].transpose() * local.middleCols<3>(3 * j);
          if(column < dm) h_blocks[std::size_t(c.offset + k) * dm + column] = block;
          else g_blocks[std::size_t(c.offset + k) * nc + (column - dm)] = block;
        }
      }
    }
  }  h_base = h_blocks;
  g_base = g_blocks;
  plm_base = plm_blocks;
  qlm_base = qlm_blocks;
}

Eigen::MatrixXd Embedding_solver::Impl::solve_a11(const Eigen::MatrixXd& rhs) const
{
  Eigen::MatrixXd x = solver->solve(rhs);
  if(!update_vertices.empty())
  {
    Eigen::MatrixXd at_updates(update_vertices.size(), x.cols());
    for(std::size_t u = 0; u < update_vertices.size(); ++u) at_updates.row(u) = x.row(update_vertices[u]);
    x -= update_columns * (capacitance_inverse * at_updates);
  }
  return x;
}

// Accepts `vertices` as a low-rank change of the factored handle set when the
// same pieces stay handled and few vertices change; false asks for a refactorization.
bool Embedding_solver::Impl::update_handle_set(const std::vector<int>& vertices)
{
  constexpr std::size_t max_update = 32;
  if(!factored) return false;
  const auto pieces = [&](const std::vector<int>& h) {
    std::set<int> p;
    for(int v : h) p.insert(component[v]);
    return p;
  };
  if(pieces(vertices) != pieces(factored_handles)) return false;
  const std::set<int> now(vertices.begin(), vertices.end()), before(factored_handles.begin(), factored_handles.end());
  std::vector<int> changed;
  std::vector<double> weights;
  const double w = options.handle_weight * mean_diagonal;
  for(int v : now)
    if(!before.count(v))
    {
      changed.push_back(v);
      weights.push_back(w);
    }
  for(int v : before)
    if(!now.count(v))
    {
      changed.push_back(v);
      weights.push_back(-w);
    }
  if(changed.size() > max_update) return false;
  update_vertices = changed;
  update_weights = Eigen::Map<const Eigen::VectorXd>(weights.data(), weights.size());
  apply_update();
  return true;
}

void Embedding_solver::Impl::apply_update()
{
  const int k = static_cast<int>(update_vertices.size());
  if(k == 0)
  {
    update_columns.resize(n, 0);
    h_blocks = h_base;
    g_blocks = g_base;
    plm_blocks = plm_base;
    qlm_blocks = qlm_base;
    return;
  }
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(n, k);
  for(int u = 0; u < k; ++u) unit(update_vertices[u], u) = 1.;
  update_columns = solver->solve(unit);
  Eigen::MatrixXd capacitance(k, k);
  for(int u = 0; u < k; ++u) capacitance.row(u) = update_columns.row(update_vertices[u]);
  capacitance.diagonal() += update_weights.cwiseInverse();
  capacitance_inverse = capacitance.inverse();
  if(options.global_step == Global_step::direct) return;

  // T_X = C^T X for every block operand X (L_c M_c and L_c B_ck), then
  // X^T A^-1 Y = X^T A_f^-1 Y - T_X^T K^-1 T_Y.
  const int dm = total_modes, nc = static_cast<int>(clusters.size());
  std::vector<Eigen::MatrixXd> t_mean(nc), t_mode(dm);
  for(int c = 0; c < nc; ++c)
  {
    const Cluster_data& d = clusters[c];
    const Eigen::MatrixXd local = gather(d, update_columns);
    t_mean[c] = local.transpose() * d.laplacian_mean;
    for(int m = 0; m < d.number_of_modes(); ++m) t_mode[d.offset + m] = local.transpose() * d.laplacian_modes[m];
  }
  const auto correction = [&](const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) -> Eigen::Matrix3d {
    return x.transpose() * (capacitance_inverse * y);
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

void Embedding_solver::Impl::prepare_handle_terms()
{
  if(!factored) factor();
  b0 = Point_matrix::Zero(n, 3);
  for(int v = 0; v < n; ++v)
    if(anchor[v] > 0) b0.row(v) = anchor[v] * mesh.points.row(v);
  const double handle_weight = options.handle_weight * mean_diagonal;
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
    b0.row(handle_vertices[h]) += handle_weight * handle_targets.row(h);
  handle_constant = 0.;
  for(int v = 0; v < n; ++v) handle_constant += anchor[v] * mesh.points.row(v).squaredNorm();
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
    handle_constant += handle_weight * handle_targets.row(h).squaredNorm();
  if(options.global_step != Global_step::direct)
  {
    const Eigen::MatrixXd z = solve_a11(b0);
    b0_z = (b0.array() * z.array()).sum();
    z_blocks.assign(total_modes, Eigen::Matrix3d::Zero());
    zlm_blocks.assign(clusters.size(), Eigen::Matrix3d::Zero());
    for(const Cluster_data& c : clusters)
    {
      const Eigen::MatrixXd local = gather(c, z);
      zlm_blocks[&c - clusters.data()] = local.transpose() * c.laplacian_mean;
      for(int k = 0; k < c.number_of_modes(); ++k)
        z_blocks[c.offset + k] = c.laplacian_modes[k].transpose() * local;
    }
  }
  handle_terms_ready = true;
  // The blocks of the implicit positions depend on the handle terms.
  if(implicit) w_blocks = w_of(coordinates);
}

void Embedding_solver::Impl::local_step()
{
  for(std::size_t c = 0; c < clusters.size(); ++c)
  {
    const Cluster_data& d = clusters[c];
    if(options.rotations == Rotations::per_vertex)
    {
      // Each point's rotation fits its incident edges (its one-ring in the cluster).
      const Point_matrix m = target_shape(d, coordinates);
      std::vector<Eigen::Matrix3d> covariance(d.vertices.size(), Eigen::Matrix3d::Zero());
      for(const Weighted_edge& e : d.edges)
      {
        const Eigen::Vector3d edge = (positions.row(d.vertices[e.i]) - positions.row(d.vertices[e.j])).transpose();
        const Eigen::Vector3d rest = (m.row(e.i) - m.row(e.j)).transpose();
        const Eigen::Matrix3d k = e.w * edge * rest.transpose();
        covariance[e.i] += k;
        covariance[e.j] += k;
      }
      for(std::size_t i = 0; i < d.vertices.size(); ++i) vertex_rotations[c][i] = closest_rotation(covariance[i]);
      continue;
    }
    Point_matrix lm = d.laplacian_mean;
    for(int k = 0; k < d.number_of_modes(); ++k) lm += coordinates[d.offset + k] * d.laplacian_modes[k];
    const Eigen::Matrix3d covariance = gather(d, positions).transpose() * lm;
    rotations[c] = closest_rotation(covariance);
  }
}

// The linear map an edge's target vector goes through: the cluster's rotation,
// or the average of its ends' rotations.
Eigen::Matrix3d Embedding_solver::Impl::edge_transform(int c, const Weighted_edge& e) const
{
  if(options.rotations == Rotations::per_vertex) return 0.5 * (vertex_rotations[c][e.i] + vertex_rotations[c][e.j]);
  return rotations[c];
}

Eigen::VectorXd Embedding_solver::Impl::solve_coordinates() const
{
  const int dm = total_modes, nc = static_cast<int>(clusters.size());
  if(dm == 0) return Eigen::VectorXd::Zero(0);
  std::vector<Eigen::Matrix3d> relative(std::size_t(nc) * nc); // R_d^T R_c at [c * nc + d]
  for(int c = 0; c < nc; ++c)
    for(int d = 0; d < nc; ++d) relative[std::size_t(c) * nc + d] = rotations[d].transpose() * rotations[c];
  Eigen::MatrixXd s = s0;
  Eigen::VectorXd r = r0;
  for(int a = 0; a < dm; ++a)
  {
    const int c = cluster_of_mode[a];
    for(int b = 0; b < dm; ++b)
      s(a, b) -= trace_product(h_blocks[std::size_t(a) * dm + b], relative[std::size_t(c) * nc + cluster_of_mode[b]]);
    for(int d = 0; d < nc; ++d)
      r[a] += trace_product(g_blocks[std::size_t(a) * nc + d], relative[std::size_t(c) * nc + d]);
    r[a] += trace_product(z_blocks[a], rotations[c]);
  }
  s = 0.5 * (s + s.transpose());
  Eigen::LLT<Eigen::MatrixXd> llt(s);
  if(llt.info() != Eigen::Success)
    throw Computation_error("embedding: the shape-coordinate system is not positive definite");
  return llt.solve(r);
}

Eigen::MatrixXd Embedding_solver::Impl::positions_rhs(const Eigen::VectorXd& lambda) const
{
  Eigen::MatrixXd rhs = b0;
  for(std::size_t c = 0; c < clusters.size(); ++c)
  {
    const Cluster_data& d = clusters[c];
    Point_matrix lm = d.laplacian_mean;
    for(int k = 0; k < d.number_of_modes(); ++k) lm += lambda[d.offset + k] * d.laplacian_modes[k];
    const Eigen::MatrixXd rotated = lm * rotations[c].transpose();
    for(std::size_t i = 0; i < d.vertices.size(); ++i) rhs.row(d.vertices[i]) += rotated.row(i);
  }
  return rhs;
}

Point_matrix Embedding_solver::Impl::positions_from(const Eigen::VectorXd& lambda) const
{
  return solve_a11(positions_rhs(lambda));
}

// W[c][d] = X_c^T A11^-1 X_d at [c * nc + d], and X_c^T Z at [nc * nc + c].
std::vector<Eigen::Matrix3d> Embedding_solver::Impl::w_of(const Eigen::VectorXd& lambda) const
{
  const int nc = static_cast<int>(clusters.size()), dm = total_modes;
  std::vector<Eigen::Matrix3d> w(std::size_t(nc) * nc + nc);
  for(int c = 0; c < nc; ++c)
  {
    const Cluster_data& cc = clusters[c];
    for(int d = 0; d < nc; ++d)
    {
      const Cluster_data& cd = clusters[d];
      Eigen::Matrix3d block = plm_blocks[std::size_t(d) * nc + c].transpose();
      for(int l = 0; l < cd.number_of_modes(); ++l)
        block += lambda[cd.offset + l] * qlm_blocks[std::size_t(cd.offset + l) * nc + c].transpose();
      for(int k = 0; k < cc.number_of_modes(); ++k)
      {
        const double lk = lambda[cc.offset + k];
        block += lk * g_blocks[std::size_t(cc.offset + k) * nc + d];
        for(int l = 0; l < cd.number_of_modes(); ++l)
          block += lk * lambda[cd.offset + l] * h_blocks[std::size_t(cc.offset + k) * dm + cd.offset + l];
      }
      w[std::size_t(c) * nc + d] = block;
    }
    Eigen::Matrix3d z = zlm_blocks[c].transpose();
    for(int k = 0; k < cc.number_of_modes(); ++k) z += lambda[cc.offset + k] * z_blocks[cc.offset + k];
    w[std::size_t(nc) * nc + c] = z;
  }
  return w;
}

// The energy at the implicit positions: for fixed rotations and coordinates
// the optimal V = A11^-1 b gives E = sum_c <M~_c, L_c M~_c> + priors + handle
// constants - b^T A11^-1 b, all from blocks.
double Embedding_solver::Impl::reduced_energy(const Eigen::VectorXd& lambda, const std::vector<Eigen::Matrix3d>& w) const
{
  const int nc = static_cast<int>(clusters.size());
  double e = mean_energy.sum() - 2. * r0.dot(lambda) + lambda.dot((mode_gram + coupling) * lambda) + handle_constant;
  for(const Cluster_data& c : clusters)
    for(int k = 0; k < c.number_of_modes(); ++k) e += c.prior[k] * lambda[c.offset + k] * lambda[c.offset + k];
  double b_a_b = b0_z;
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
  using Clock = std::chrono::steady_clock;
  Clock::time_point mark = Clock::now();
  const auto lap = [&](double Iteration_timings::*phase) {
    const Clock::time_point now = Clock::now();
    if(timings) timings->*phase += std::chrono::duration<double, std::milli>(now - mark).count();
    mark = now;
  };
  Eigen::VectorXd lambda = solve_coordinates();
  lap(&Iteration_timings::schur_ms);
  std::vector<Eigen::Matrix3d> w = w_of(lambda);
  lap(&Iteration_timings::right_hand_side_ms);
  const double e = reduced_energy(lambda, w);
  lap(&Iteration_timings::energy_ms);
  if(!lambda.allFinite()) check_finite(positions, lambda);
  if(!std::isfinite(e)) fail_on_non_finite_energy(positions_from(lambda), lambda);
  coordinates = std::move(lambda);
  w_blocks = std::move(w);
  implicit = true;
  positions_valid = false;
  return e;
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
  const bool reduced = options.global_step == Global_step::reduced;
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
  if(options.global_step == Global_step::reduced)
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
  const Point_matrix plain_positions = options.global_step == Global_step::reduced ? Point_matrix() : positions;
  const double e = candidate.allFinite() ? enter_state(candidate) : std::numeric_limits<double>::infinity();
  if(e < energy)
  {
    energy = e;
    return true;
  }
  coordinates = plain.tail(total_modes);
  rotations = plain_rotations;
  w_blocks = plain_w;
  if(options.global_step != Global_step::reduced) positions = plain_positions;
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
    const std::vector<Eigen::Matrix3d> kept_rotations = rotations, kept_w = w_blocks;
    const Eigen::VectorXd kept_coordinates = coordinates;
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
    if(!taken)
    {
      rotations = kept_rotations;
      coordinates = kept_coordinates;
      w_blocks = kept_w;
    }
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

// The reference: the whole quadratic in (x, y, z, lambda), assembled edge by
// edge (not from the cluster Laplacians the fast paths use) and factored
// afresh. Slow, simple, and what the fast paths must agree with. With edge
// transforms T_e, targets t_e = T_e (m_e + sum_k lambda_k b_ke).
void Embedding_solver::Impl::global_step_direct(Point_matrix& v, Eigen::VectorXd& lambda)
{
  const int dm = total_modes, size = 3 * n + dm;
  std::vector<Eigen::Triplet<double>> t;
  for(int a = 0; a < 3; ++a)
    for(int k = 0; k < system.outerSize(); ++k)
      for(Sparse::InnerIterator it(system, k); it; ++it) t.emplace_back(a * n + it.row(), a * n + it.col(), it.value());
  for(std::size_t u = 0; u < update_vertices.size(); ++u)
    for(int a = 0; a < 3; ++a) t.emplace_back(a * n + update_vertices[u], a * n + update_vertices[u], update_weights[u]);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  for(int a = 0; a < 3; ++a) rhs.segment(a * n, n) = b0.col(a);
  Eigen::MatrixXd lambda_block = coupling;
  for(std::size_t c = 0; c < clusters.size(); ++c)
  {
    const Cluster_data& d = clusters[c];
    const int modes = d.number_of_modes();
    std::vector<Eigen::Vector3d> mode_edges(modes);
    for(const Weighted_edge& e : d.edges)
    {
      const Eigen::Matrix3d transform = edge_transform(static_cast<int>(c), e);
      const int gi = d.vertices[e.i], gj = d.vertices[e.j];
      const Eigen::Vector3d u = transform * (d.mean.row(e.i) - d.mean.row(e.j)).transpose();
      for(int a = 0; a < 3; ++a)
      {
        rhs[a * n + gi] += e.w * u[a];
        rhs[a * n + gj] -= e.w * u[a];
      }
      for(int k = 0; k < modes; ++k)
      {
        mode_edges[k] = transform * (d.modes[k].row(e.i) - d.modes[k].row(e.j)).transpose();
        const int row = 3 * n + d.offset + k;
        for(int a = 0; a < 3; ++a)
        {
          const double value = e.w * mode_edges[k][a];
          t.emplace_back(row, a * n + gi, -value);
          t.emplace_back(a * n + gi, row, -value);
          t.emplace_back(row, a * n + gj, value);
          t.emplace_back(a * n + gj, row, value);
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
      if(lambda_block(a, b) != 0.) t.emplace_back(3 * n + a, 3 * n + b, lambda_block(a, b));
  Sparse k(size, size);
  k.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Sparse> ldlt(k);
  if(ldlt.info() != Eigen::Success || non_positive_pivot_row(ldlt) >= 0)
    throw Computation_error("embedding: factorization of the full system failed");
  const Eigen::VectorXd x = ldlt.solve(rhs);
  v.resize(n, 3);
  for(int a = 0; a < 3; ++a) v.col(a) = x.segment(a * n, n);
  lambda = x.tail(dm);
}

double Embedding_solver::Impl::energy_of(const Point_matrix& v, const Eigen::VectorXd& lambda, int only) const
{
  double e = 0.;
  for(std::size_t c = 0; c < clusters.size(); ++c)
  {
    if(only >= 0 && int(c) != only) continue;
    const Cluster_data& d = clusters[c];
    const Point_matrix m = target_shape(d, lambda);
    for(const Weighted_edge& edge : d.edges)
      e += edge.w * ((v.row(d.vertices[edge.i]) - v.row(d.vertices[edge.j])).transpose() -
                     edge_transform(static_cast<int>(c), edge) * (m.row(edge.i) - m.row(edge.j)).transpose())
                      .squaredNorm();
    for(int k = 0; k < d.number_of_modes(); ++k) e += d.prior[k] * lambda[d.offset + k] * lambda[d.offset + k];
  }
  if(only >= 0) return e;
  e += lambda.dot(coupling * lambda);
  const double handle_weight = options.handle_weight * mean_diagonal;
  for(std::size_t h = 0; h < handle_vertices.size(); ++h)
    e += handle_weight * (v.row(handle_vertices[h]) - handle_targets.row(h)).squaredNorm();
  for(int i = 0; i < n; ++i)
    if(anchor[i] > 0) e += anchor[i] * (v.row(i) - mesh.points.row(i)).squaredNorm();
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
  if(vertices != d.handle_vertices && !d.update_handle_set(vertices)) d.factored = false;
  d.handle_vertices = vertices;
  d.handle_targets = targets;
  d.handle_targets.rowwise() -= d.origin;
  d.handle_terms_ready = false;
  d.compute_anchor();
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
  const Clock::time_point start = Clock::now();
  Clock::time_point mark = start;
  const auto lap = [&mark](double& ms) {
    const Clock::time_point now = Clock::now();
    ms += std::chrono::duration<double, std::milli>(now - mark).count();
    mark = now;
  };
  struct Total // also on the way out by an exception
  {
    double& ms;
    Clock::time_point start;
    ~Total() { ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }
  } total{t.total_ms, start};
  const std::vector<Eigen::Matrix3d> previous_rotations = d.rotations;
  if(d.implicit) d.reduced_local_step();
  else d.local_step();
  lap(t.local_step_ms);
  try
  {
    switch(d.options.global_step)
    {
    case Global_step::reduced:
    {
      const double e = d.settle_at_rotations(&t);
      ++d.iterations_since_reset;
      return e;
    }
    case Global_step::schur:
    case Global_step::direct:
    {
      Point_matrix v;
      Eigen::VectorXd lambda;
      if(d.options.global_step == Global_step::schur)
      {
        lambda = d.solve_coordinates();
        lap(t.schur_ms);
        const Eigen::MatrixXd rhs = d.positions_rhs(lambda);
        lap(t.right_hand_side_ms);
        v = d.solve_a11(rhs);
        lap(t.back_substitution_ms);
      }
      else
      {
        d.global_step_direct(v, lambda);
        lap(t.direct_ms);
      }
      d.check_finite(v, lambda);
      mark = Clock::now();
      const double e = d.energy_of(v, lambda);
      lap(t.energy_ms);
      if(!std::isfinite(e)) d.fail_on_non_finite_energy(v, lambda);
      d.positions = std::move(v);
      d.coordinates = std::move(lambda);
      ++d.iterations_since_reset;
      return e;
    }
    }
  }
  catch(...)
  {
    d.rotations = previous_rotations;
    throw;
  }
  return 0.;
}

namespace {

// Anderson acceleration (type II) of a fixed-point iteration x <- G(x): the
// next iterate combines the last few images so as to minimize the combined
// residual G(x) - x in the least-squares sense.
class Anderson_acceleration
{
public:
  explicit Anderson_acceleration(int history) : history_(history) {}

  // Records x and its image g; returns the accelerated candidate, or g when
  // there is no history yet.
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& g)
  {
    const Eigen::VectorXd f = g - x;
    if(history_ > 0 && previous_f_.size() > 0)
    {
      delta_f_.push_back(f - previous_f_);
      delta_g_.push_back(g - previous_g_);
      if(static_cast<int>(delta_f_.size()) > history_)
      {
        delta_f_.erase(delta_f_.begin());
        delta_g_.erase(delta_g_.begin());
      }
    }
    previous_f_ = f;
    previous_g_ = g;
    const int m = static_cast<int>(delta_f_.size());
    if(m == 0) return g;
    Eigen::MatrixXd normal(m, m);
    Eigen::VectorXd rhs(m);
    for(int i = 0; i < m; ++i)
    {
      rhs[i] = delta_f_[i].dot(f);
      for(int j = 0; j < m; ++j) normal(i, j) = delta_f_[i].dot(delta_f_[j]);
    }
    const Eigen::VectorXd theta = normal.completeOrthogonalDecomposition().solve(rhs);
    Eigen::VectorXd candidate = g;
    for(int i = 0; i < m; ++i) candidate -= theta[i] * delta_g_[i];
    return candidate;
  }

  // Forgets the history (after a rejected candidate).
  void restart()
  {
    delta_f_.clear();
    delta_g_.clear();
  }

private:
  int history_;
  Eigen::VectorXd previous_f_, previous_g_;
  std::vector<Eigen::VectorXd> delta_f_, delta_g_;
};

} // namespace

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

  // With implicit positions the rotations alone are the state: L-BFGS on
  // them. Memory measured on the 36 real-mesh edits of quality_real_meshes:
  // 3 pairs 8% more iterations than 8, 20 pairs 8% fewer.
  const bool quasi_newton = d.options.global_step == Global_step::reduced && d.options.quasi_newton;
  // Each iteration evaluates one extrapolation of the local/global step: the
  // L-BFGS step, or Anderson's once L-BFGS failed three times in a row to do
  // better, until Anderson's fails in turn. Which one wins depends on the
  // edit (measured: L-BFGS on symmetrize and caricature, Anderson on some
  // drags).
  bool prefer_lbfgs = true;
  int lbfgs_failures = 0;
  internal::Rotation_lbfgs lbfgs(20);
  Eigen::VectorXd gradient;

  Anderson_acceleration anderson(std::max(0, d.options.anderson_history));
  Eigen::VectorXd x = d.packed_state();
  double best = previous;
  int rises = 0;
  for(int it = 0; it < d.options.max_iterations; ++it)
  {
    internal::throw_if_cancelled(d.options.cancel, "solve");
    const std::vector<Eigen::Matrix3d> start = d.rotations;
    double e = iterate();
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
    d.check_not_diverging(e, best, rises, it + 1);
    best = std::min(best, e);
    report.energies.push_back(e);
    ++report.iterations;
    if(d.options.iteration_callback) d.options.iteration_callback(report.iterations, e);
    if(previous - e <= d.options.tolerance * std::max(previous, std::numeric_limits<double>::min()))
    {
      report.converged = true;
      break;
    }
    previous = e;
  }
  // Reduced energies are differences of large sums; the reported residual is
  // evaluated exactly at the final positions.
  if(d.options.global_step == Global_step::reduced && !report.energies.empty()) report.energies.back() = energy();
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

const Eigen::Matrix3d& Embedding_solver::rotation(int c) const { return impl_->rotations.at(c); }

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
  d.local_step();
}

int Embedding_solver::number_of_clusters() const { return static_cast<int>(impl_->clusters.size()); }

const Iteration_timings& Embedding_solver::last_iteration_timings() const { return impl_->timings; }

} // namespace MPM
} // namespace CGAL
