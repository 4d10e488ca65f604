// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Baselines/Correspondence_evaluation.h>
#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <random>

namespace CGAL {
namespace MPM {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;
using Mesh = internal::Indexed_surface_mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

double quantile(std::vector<double> values, double q)
{
  if(values.empty()) return 0.;
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

double mean_edge_length(const Indexed_mesh& m)
{
  double sum = 0.;
  for(const Triangle& t : m.triangles)
    for(int k = 0; k < 3; ++k) sum += (m.points.row(t[k]) - m.points.row(t[(k + 1) % 3])).norm();
  return m.triangles.empty() ? 0. : sum / (3. * m.triangles.size());
}

} // namespace

Indexed_mesh remesh_isotropically(const Indexed_mesh& mesh, double target_edge_length, int iterations)
{
  Mesh sm = internal::to_surface_mesh(mesh, "remeshing", "remeshing");
  PMP::isotropic_remeshing(faces(sm), target_edge_length, sm, CGAL::parameters::number_of_iterations(iterations));
  sm.collect_garbage();
  return to_indexed_mesh(sm);
}

Point_matrix true_corresponding_points(const Indexed_mesh& truth_template, const Point_matrix& template_points,
                                       const Indexed_mesh& truth_instance)
{
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  const Mesh sm = internal::to_surface_mesh(truth_template, "true correspondence", "locating points");
  Tree tree;
  PMP::build_AABB_tree(sm, tree);
  Point_matrix truth(template_points.rows(), 3);
  for(Eigen::Index v = 0; v < template_points.rows(); ++v)
  {
    const Point_3 p(template_points(v, 0), template_points(v, 1), template_points(v, 2));
    const auto location = PMP::locate_with_AABB_tree(p, tree, sm);
    // Barycentric coordinates follow halfedge(f): source, target, next target.
    const auto h = halfedge(location.first, sm);
    const int corners[3] = {int(source(h, sm)), int(target(h, sm)), int(target(next(h, sm), sm))};
    truth.row(v).setZero();
    for(int k = 0; k < 3; ++k) truth.row(v) += location.second[k] * truth_instance.points.row(corners[k]);
  }
  return truth;
}

std::vector<double> correspondence_errors(const Indexed_mesh& truth_template, const Point_matrix& template_points,
                                          const Indexed_mesh& truth_instance, const Point_matrix& mapped)
{
  const Point_matrix truth = true_corresponding_points(truth_template, template_points, truth_instance);
  const double diameter = internal::bounding_box_diagonal(truth_instance.points);
  std::vector<double> errors;
  for(Eigen::Index v = 0; v < mapped.rows(); ++v) errors.push_back((mapped.row(v) - truth.row(v)).norm() / diameter);
  return errors;
}

namespace {

// Every instance in its true local numbering (first appearance in its
// faces) and remeshed, with seam tags (the type across the seam) carried to
// the remeshed border.
struct Remeshed_instance
{
  const Synthetic_instance* instance = nullptr;
  Indexed_mesh truth;
  Correspondence_segment segment;
};

std::map<std::string, std::vector<Remeshed_instance>> remesh_instances(const Synthetic_model& model, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> factor(0.75, 1.3);
  std::map<int, int> type_of_label;
  for(const Synthetic_instance& instance : model.instances)
    for(std::size_t t = 0; t < model.types.size(); ++t)
      if(model.types[t].name == instance.type) type_of_label[instance.label] = static_cast<int>(t);
  std::map<std::string, std::vector<Remeshed_instance>> result;
  for(const Synthetic_instance& instance : model.instances)
  {
    Remeshed_instance r;
    r.instance = &instance;
    std::map<int, int> local;
    for(std::size_t k = 0; k < instance.vertices.size(); ++k) local[instance.vertices[k]] = static_cast<int>(k);
    Indexed_mesh& part = r.truth;
    part.points.resize(instance.vertices.size(), 3);
    for(std::size_t k = 0; k < instance.vertices.size(); ++k) part.points.row(k) = model.mesh.mesh.points.row(instance.vertices[k]);
    std::vector<int> tags(part.number_of_vertices(), -1);
    for(int f = 0; f < model.mesh.mesh.number_of_faces(); ++f)
    {
      const Triangle& t = model.mesh.mesh.triangles[f];
      if(model.mesh.face_labels[f] == instance.label)
        part.triangles.push_back({local.at(t[0]), local.at(t[1]), local.at(t[2])});
      else
        for(int v : t)
        {
          const auto it = local.find(v);
          if(it != local.end()) tags[it->second] = type_of_label.at(model.mesh.face_labels[f]);
        }
    }
    Correspondence_segment& segment = r.segment;
    segment.mesh = remesh_isotropically(part, factor(random) * mean_edge_length(part), 3);
    segment.name = model.mesh.source + " label " + std::to_string(instance.label);
    segment.seam_tags.assign(segment.mesh.number_of_vertices(), -1);
    for(const std::vector<int>& loop : boundary_loops(segment.mesh))
      for(int v : loop)
      {
        double best = std::numeric_limits<double>::infinity();
        for(int w = 0; w < part.number_of_vertices(); ++w)
          if(tags[w] >= 0 && (part.points.row(w) - segment.mesh.points.row(v)).squaredNorm() < best)
          {
            best = (part.points.row(w) - segment.mesh.points.row(v)).squaredNorm();
            segment.seam_tags[v] = tags[w];
          }
      }
    result[instance.type].push_back(std::move(r));
  }
  return result;
}

} // namespace

Labeled_mesh remesh_parts_independently(const Synthetic_model& model, unsigned seed)
{
  Labeled_mesh result;
  result.source = model.mesh.source + " (parts remeshed)";
  std::vector<Eigen::RowVector3d> points;
  for(const auto& [type, instances] : remesh_instances(model, seed))
    for(const Remeshed_instance& r : instances)
    {
      const int base = static_cast<int>(points.size());
      for(Eigen::Index v = 0; v < r.segment.mesh.points.rows(); ++v) points.push_back(r.segment.mesh.points.row(v));
      for(const Triangle& t : r.segment.mesh.triangles)
      {
        result.mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
        result.face_labels.push_back(r.instance->label);
      }
    }
  result.mesh.points.resize(points.size(), 3);
  for(std::size_t v = 0; v < points.size(); ++v) result.mesh.points.row(v) = points[v];
  return result;
}

std::vector<Correspondence_type_report>
evaluate_correspondence_on_remeshed(const Synthetic_model& model, unsigned seed,
                                    const Dense_correspondence_options& options)
{
  std::vector<Correspondence_type_report> reports;
  std::map<std::string, std::vector<Remeshed_instance>> remeshed = remesh_instances(model, seed);
  for(const Synthetic_type& type : model.types)
  {
    const std::vector<Remeshed_instance>& instances = remeshed[type.name];
    if(instances.size() < 2) continue;
    std::vector<Indexed_mesh> truth;
    std::vector<Correspondence_segment> segments;
    for(const Remeshed_instance& r : instances)
    {
      truth.push_back(r.truth);
      segments.push_back(r.segment);
    }
    const auto start = std::chrono::steady_clock::now();
    const Dense_correspondence c = compute_dense_correspondence(segments, type.name, options);
    Correspondence_type_report r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.type = type.name;
    r.segments = static_cast<int>(segments.size());
    r.template_vertices = segments[0].mesh.number_of_vertices();
    r.before = c.before;
    r.after = c.after;
    std::vector<double> before, after;
    for(std::size_t i = 1; i < segments.size(); ++i)
    {
      const std::vector<double> b = correspondence_errors(truth[0], segments[0].mesh.points, truth[i], c.segments[i].unrefined);
      const std::vector<double> a = correspondence_errors(truth[0], segments[0].mesh.points, truth[i], c.segments[i].positions);
      before.insert(before.end(), b.begin(), b.end());
      after.insert(after.end(), a.begin(), a.end());
    }
    const auto mean = [](const std::vector<double>& v) {
      double s = 0.;
      for(double x : v) s += x;
      return v.empty() ? 0. : s / v.size();
    };
    r.mean_before = mean(before);
    r.p95_before = quantile(before, 0.95);
    r.mean_after = mean(after);
    r.p95_after = quantile(after, 0.95);
    reports.push_back(r);
  }
  return reports;
}

} // namespace MPM
} // namespace CGAL
