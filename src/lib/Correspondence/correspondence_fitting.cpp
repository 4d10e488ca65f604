// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Correspondence_surface.h>
#include <CGAL/MPM/internal/Cotangent_weights.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>
#include <CGAL/MPM/internal/Farthest_point_sampling.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace CGAL {
namespace MPM {
namespace internal {
namespace correspondence {

namespace {

// The template's own cotangent Laplacian: each negative cotangent clamped
// to zero, and the uniform weight 1 on an edge no triangle gives a usable
// weight. It differs from the package's one rule (internal/
// Cotangent_weights.h), which the learned models were not measured with:
// under that rule the octopus_124 example learned with octopus_126 keeps 6
// open edges (test Segmented_meshes_together.own_shapes_of_two_meshes_are_two_types).
Sparse template_laplacian(const Indexed_mesh& mesh)
{
  const int n = mesh.number_of_vertices();
  // Per edge (i < j): summed weight, and whether any triangle gave a usable one.
  std::map<std::pair<int, int>, std::pair<double, bool>> edges;
  for(const Triangle& t : mesh.triangles)
    for(int k = 0; k < 3; ++k)
    {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      if(i == j) continue;
      const Eigen::RowVector3d a = mesh.points.row(i) - mesh.points.row(t[k]);
      const Eigen::RowVector3d b = mesh.points.row(j) - mesh.points.row(t[k]);
      const double cross = a.cross(b).norm();
      double w = cross > 0 ? 0.5 * a.dot(b) / cross : 0.;
      const bool usable = std::isfinite(w) && cross > 1e-14 * a.norm() * b.norm();
      if(!usable) w = 0.;
      auto& e = edges[{std::min(i, j), std::max(i, j)}];
      e.first += std::max(w, 0.);
      e.second = e.second || usable;
    }
  std::map<std::pair<int, int>, double> weights;
  for(const auto& [edge, value] : edges)
    weights[edge] = value.second && value.first > 0 && std::isfinite(value.first) ? value.first : 1.;
  return internal::edge_weight_laplacian(weights, n);
}

} // namespace

// Near-coincident centres (a user landmark on a loop sample) would make the
// spline singular; the first of them wins.
Thin_plate_spline fit_spline(const Point_matrix& centres, const Point_matrix& displacements, double scale)
{
  std::vector<int> kept;
  for(Eigen::Index i = 0; i < centres.rows(); ++i)
  {
    bool duplicate = false;
    for(int j : kept)
      if((centres.row(i) - centres.row(j)).norm() <= 1e-7 * scale)
      {
        duplicate = true;
        break;
      }
    if(!duplicate) kept.push_back(static_cast<int>(i));
  }
  return Thin_plate_spline(rows_of(centres, kept), rows_of(displacements, kept));
}

Template_info make_template_info(const Surface& t)
{
  Template_info info;
  const int n = t.mesh.number_of_vertices();
  info.loop.assign(n, -1);
  info.parameter.assign(n, 0.);
  for(std::size_t l = 0; l < t.loops.size(); ++l)
    for(std::size_t k = 0; k < t.loops[l].vertices.size(); ++k)
    {
      info.loop[t.loops[l].vertices[k]] = static_cast<int>(l);
      info.parameter[t.loops[l].vertices[k]] = t.loops[l].parameter(static_cast<int>(k));
    }
  const Sparse laplacian = template_laplacian(t.mesh);
  info.laplacian_normal = laplacian.transpose() * laplacian;
  info.laplacian_scale = std::max(1e-300, info.laplacian_normal.diagonal().mean());
  info.neighbours.assign(n, {});
  for(const Cluster_edge& e : internal::mesh_edges(t.mesh.triangles))
  {
    info.neighbours[e.source].push_back(e.target);
    info.neighbours[e.target].push_back(e.source);
  }
  std::vector<Eigen::Triplet<double>> entries;
  for(int v = 0; v < n; ++v)
  {
    if(info.neighbours[v].empty()) continue;
    entries.emplace_back(v, v, 1.);
    for(int w : info.neighbours[v]) entries.emplace_back(v, w, -1. / info.neighbours[v].size());
  }
  // Scaled by diagonal / mean edge length: a smooth tangential drift
  // changes the umbrella vectors by about (edge / diagonal)^2 of the drift,
  // so unscaled E_sample would vanish against trace(Sigma) on fine meshes.
  const double scale = t.edge_length > 0 ? t.diagonal / t.edge_length : 1.;
  for(Eigen::Triplet<double>& e : entries) e = Eigen::Triplet<double>(e.row(), e.col(), scale * e.value());
  info.umbrella.resize(n, n);
  info.umbrella.setFromTriplets(entries.begin(), entries.end());
  return info;
}

namespace {

// Where ICP pulls each template vertex: boundary vertices to their
// arc-length image on the matched loop, landmark vertices to their
// landmark, the others to the closest surface point.
Point_matrix icp_targets(const Surface& s, const Template_info& info, const Landmarks& lm, const Point_matrix& y,
                         std::vector<bool>* constrained = nullptr)
{
  Point_matrix c(y.rows(), 3);
  if(constrained) constrained->assign(y.rows(), false);
  for(Eigen::Index v = 0; v < y.rows(); ++v)
  {
    const int l = info.loop[v];
    if(l >= 0)
    {
      const Loop_match& m = lm.loops[l];
      c.row(v) = s.loops[m.target].at(m.offset + m.orientation * info.parameter[v]).transpose();
      if(constrained) (*constrained)[v] = true;
    }
    else
      c.row(v) = s.closest(y.row(v).transpose()).transpose();
  }
  for(const auto& [v, p] : lm.vertex_targets)
  {
    c.row(v) = p.transpose();
    if(constrained) (*constrained)[v] = true;
  }
  return c;
}

} // namespace

// Coarse deformable ICP: a thin-plate spline through the landmarks and
// farthest-point-sampled free centres, each free centre moved by the mean
// pull of the vertices nearest to it.
Point_matrix spline_icp(const Surface& s, const Template_info& info, const Landmarks& lm, const Point_matrix& base,
                        const Dense_correspondence_options& options, int& iterations)
{
  const Point_matrix fixed_centres = lm.motion.apply(lm.source);
  const Point_matrix fixed_displacements = lm.target - fixed_centres;
  const double scale = bounding_box_diagonal(base);
  const int n = static_cast<int>(base.rows());
  Eigen::VectorXd squared_distance = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  for(int v = 0; v < n; ++v)
    for(Eigen::Index k = 0; k < fixed_centres.rows(); ++k)
      squared_distance[v] = std::min(squared_distance[v], (base.row(v) - fixed_centres.row(k)).squaredNorm());
  // Free centres off the seams, each with the region of vertices nearest to it.
  std::vector<int> region(n, -1);
  const double min_distance = 1e-3 * scale;
  const std::vector<int> free = internal::farthest_point_sampling(
    base, std::min(options.spline_centres, n), -1, squared_distance, [&](int v) { return info.loop[v] < 0; },
    min_distance * min_distance, &region);
  const Point_matrix free_centres = rows_of(base, free);
  const Point_matrix centres = stack({fixed_centres, free_centres});
  Point_matrix free_displacements =
    fit_spline(fixed_centres, fixed_displacements, scale).displacement(free_centres);
  Point_matrix y;
  for(int it = 0;; ++it)
  {
    const Thin_plate_spline spline = fit_spline(centres, stack({fixed_displacements, free_displacements}), scale);
    y = base + spline.displacement(base);
    if(it == options.spline_iterations) break;
    ++iterations;
    const Point_matrix pull = icp_targets(s, info, lm, y) - y;
    Point_matrix sum = Point_matrix::Zero(free.size(), 3);
    std::vector<int> count(free.size(), 0);
    for(int v = 0; v < n; ++v)
      if(region[v] >= 0)
      {
        sum.row(region[v]) += pull.row(v);
        ++count[region[v]];
      }
    for(std::size_t j = 0; j < free.size(); ++j)
      if(count[j] > 0) free_displacements.row(j) += sum.row(j) / count[j];
  }
  return y;
}

// Coarse deformable ICP in the PCA space of the segments already done:
// alternate closest points and the space's best fit to them.
Point_matrix shape_space_icp(const Surface& s, const Template_info& info, const Landmarks& lm,
                             const Shape_space& space, const Point_matrix& start,
                             const Dense_correspondence_options& options, int& iterations)
{
  Point_matrix y = start;
  for(int it = 0; it < options.spline_iterations; ++it, ++iterations)
  {
    Eigen::VectorXd coordinates;
    Rigid_motion motion;
    space.fit(icp_targets(s, info, lm, y), coordinates, motion);
    y = motion.apply(space.shape(coordinates));
  }
  return y;
}

// Fine deformable ICP: minimizes sum_v w_v |y_v - c_v|^2 +
// lambda |L (Y - Y_coarse)|^2 for decreasing lambda, so the coarse result's
// shape guides the vertices onto the surface at mesh resolution.
Point_matrix laplacian_icp(const Surface& s, const Template_info& info, const Landmarks& lm, const Point_matrix& coarse,
                           const Dense_correspondence_options& options, int& iterations)
{
  const Eigen::Index n = coarse.rows();
  std::vector<bool> constrained;
  icp_targets(s, info, lm, coarse, &constrained);
  Eigen::VectorXd w(n);
  for(Eigen::Index v = 0; v < n; ++v) w[v] = constrained[v] ? options.boundary_weight : 1.;
  Sparse weights(n, n);
  {
    std::vector<Eigen::Triplet<double>> d;
    for(Eigen::Index v = 0; v < n; ++v) d.emplace_back(v, v, w[v]);
    weights.setFromTriplets(d.begin(), d.end());
  }
  const Eigen::MatrixXd detail = info.laplacian_normal * Eigen::MatrixXd(coarse);
  Point_matrix y = coarse;
  for(double stiffness : {10., 3., 1.})
  {
    const double lambda = stiffness / info.laplacian_scale;
    Eigen::SimplicialLDLT<Sparse> solver(Sparse(weights + lambda * info.laplacian_normal));
    if(solver.info() != Eigen::Success) break;
    for(int it = 0; it < options.laplacian_iterations; ++it, ++iterations)
    {
      const Point_matrix c = icp_targets(s, info, lm, y);
      const Eigen::MatrixXd rhs = w.asDiagonal() * Eigen::MatrixXd(c) + lambda * detail;
      const Eigen::MatrixXd solution = solver.solve(rhs);
      if(!solution.allFinite()) return y;
      y = solution;
    }
  }
  return y;
}

// Interior vertices onto the surface (with the face normal), boundary
// vertices onto their matched loop (with the loop tangent). A thousandth
// of the way back keeps vertices that land on one point (a corner of the
// segment) or on one straight border edge apart, so no template triangle
// becomes degenerate.
void project(const Surface& s, const Template_info& info, const Landmarks& lm, Point_matrix& y,
             std::vector<Vec3>& frame)
{
  frame.resize(y.rows());
  for(Eigen::Index v = 0; v < y.rows(); ++v)
  {
    const int l = info.loop[v];
    const Vec3 p = y.row(v).transpose();
    const Vec3 q = l >= 0 ? s.closest_on_loop(lm.loops[l].target, p, &frame[v]) : s.closest(p, &frame[v]);
    y.row(v) = (q + 1e-3 * (p - q)).transpose();
  }
}

// Energies of eq. 4.1 with the rigid alignment of every segment to the mean
// (generalized Procrustes), so that the pose of a segment is no variance.
Correspondence_energies evaluate(const std::vector<Point_matrix>& y, const std::vector<const Landmarks*>& landmarks,
                                 const Template_info& info, Alignment& alignment)
{
  const std::size_t m = y.size();
  alignment.mean = y.front();
  alignment.motions.assign(m, Rigid_motion());
  for(int pass = 0; pass < 4; ++pass)
  {
    Point_matrix sum = Point_matrix::Zero(y.front().rows(), 3);
    for(std::size_t i = 0; i < m; ++i)
    {
      alignment.motions[i] = fit_rigid_motion(y[i], alignment.mean);
      sum += alignment.motions[i].apply(y[i]);
    }
    alignment.mean = sum / double(m);
  }
  Correspondence_energies e;
  const Eigen::MatrixXd mean_detail = info.umbrella * Eigen::MatrixXd(alignment.mean);
  for(std::size_t i = 0; i < m; ++i)
  {
    e.trace += (alignment.motions[i].apply(y[i]) - alignment.mean).squaredNorm();
    e.sample += (info.umbrella * Eigen::MatrixXd(y[i]) - mean_detail * alignment.motions[i].rotation).squaredNorm();
    if(landmarks[i])
      for(const auto& [v, p] : landmarks[i]->vertex_targets) e.boundary += (y[i].row(v).transpose() - p).squaredNorm();
  }
  return e;
}

// Gradient descent on eq. 4.1 over the tangent spaces of the segments:
// each vertex moves at most `refinement_step` of its edge length per step,
// then goes back onto its segment (boundary vertices onto their loop).
int refine(const std::vector<std::unique_ptr<Surface>>& surfaces, const std::vector<Landmarks>& landmarks,
           const Template_info& info, int fixed, const Dense_correspondence_options& options,
           std::vector<Point_matrix>& y, Correspondence_energies& before, Correspondence_energies& after)
{
  const std::size_t m = y.size();
  std::vector<const Landmarks*> lm(m, nullptr);
  for(std::size_t i = 0; i < m; ++i)
    if(int(i) != fixed) lm[i] = &landmarks[i];
  std::vector<std::vector<Vec3>> frames(m);
  for(std::size_t i = 0; i < m; ++i)
    if(int(i) != fixed) project(*surfaces[i], info, landmarks[i], y[i], frames[i]);
  const Eigen::Index n = y.front().rows();
  // Step bound per vertex: a fraction of its mean edge length on the segment.
  std::vector<Eigen::VectorXd> bound(m, Eigen::VectorXd::Zero(n));
  for(std::size_t i = 0; i < m; ++i)
    for(Eigen::Index v = 0; v < n; ++v)
    {
      double sum = 0.;
      for(int w : info.neighbours[v]) sum += (y[i].row(v) - y[i].row(w)).norm();
      bound[i][v] = info.neighbours[v].empty() ? 0. : options.refinement_step * sum / info.neighbours[v].size();
    }

  Alignment alignment;
  Correspondence_energies current = evaluate(y, lm, info, alignment);
  before = current;
  const auto total = [&](const Correspondence_energies& e) {
    return e.total(options.sample_weight, options.boundary_weight);
  };
  double alpha = -1.;
  int accepted = 0;
  for(int it = 0; it < options.refinement_iterations && m > 1; ++it)
  {
    std::vector<Point_matrix> direction(m);
    const Eigen::MatrixXd mean_detail = info.umbrella * Eigen::MatrixXd(alignment.mean);
    double largest = 0.;
    for(std::size_t i = 0; i < m; ++i)
    {
      if(int(i) == fixed) continue;
      const Rigid_motion& a = alignment.motions[i];
      Eigen::MatrixXd g = 2. * Eigen::MatrixXd(a.apply(y[i]) - alignment.mean) * a.rotation;
      g += options.sample_weight * 2. * Eigen::MatrixXd(info.umbrella.transpose() *
             (info.umbrella * Eigen::MatrixXd(y[i]) - mean_detail * a.rotation));
      for(const auto& [v, p] : landmarks[i].vertex_targets)
        g.row(v) += options.boundary_weight * 2. * (y[i].row(v).transpose() - p).transpose();
      direction[i] = -g;
      for(Eigen::Index v = 0; v < n; ++v)
      {
        const Vec3 d = direction[i].row(v).transpose();
        const Vec3& f = frames[i][v];
        const Vec3 t = info.loop[v] >= 0 ? Vec3(f.dot(d) * f) : Vec3(d - f.dot(d) * f);
        direction[i].row(v) = t.transpose();
        if(bound[i][v] > 0) largest = std::max(largest, t.norm() / bound[i][v]);
      }
    }
    if(!(largest > 0)) break;
    if(alpha < 0) alpha = 1. / largest;
    bool improved = false;
    for(int attempt = 0; attempt < 10 && !improved; ++attempt)
    {
      std::vector<Point_matrix> trial = y;
      std::vector<std::vector<Vec3>> trial_frames = frames;
      for(std::size_t i = 0; i < m; ++i)
      {
        if(int(i) == fixed) continue;
        for(Eigen::Index v = 0; v < n; ++v)
        {
          Vec3 step = alpha * direction[i].row(v).transpose();
          if(step.norm() > bound[i][v]) step *= bound[i][v] / step.norm();
          trial[i].row(v) += step.transpose();
        }
        project(*surfaces[i], info, landmarks[i], trial[i], trial_frames[i]);
      }
      Alignment trial_alignment;
      const Correspondence_energies e = evaluate(trial, lm, info, trial_alignment);
      // trace(Sigma) is what the refinement is for: it must not grow.
      if(total(e) < total(current) && e.trace <= current.trace)
      {
        improved = total(e) < total(current) * (1. - 1e-7);
        y = std::move(trial);
        frames = std::move(trial_frames);
        alignment = std::move(trial_alignment);
        current = e;
        ++accepted;
        alpha *= 1.5;
        if(!improved) it = options.refinement_iterations; // converged
        improved = true;
      }
      else
        alpha *= 0.3;
    }
    if(!improved) break;
  }
  after = current;
  return accepted;
}

} // namespace correspondence
} // namespace internal
} // namespace MPM
} // namespace CGAL
