// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Learning/Model_fit.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Correspondence_surface.h>
#include <CGAL/MPM/internal/Training_segments.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>

namespace CGAL {
namespace MPM {

namespace {

// A segment of the new mesh with its vertices numbered by first appearance
// in its faces, in face order: the numbering learning gives a part, so that
// a segment with its type's connectivity compares equal triangle by triangle.
struct Segment
{
  int label = -1;
  std::vector<int> vertices; // local -> mesh vertex
  Indexed_mesh mesh;
};

Segment extract_segment(const Indexed_mesh& mesh, const std::vector<int>& faces, int label)
{
  Segment s;
  s.label = label;
  std::vector<int> local_of(std::size_t(mesh.number_of_vertices()), -1);
  internal::local_part(mesh, faces, local_of, s.vertices, s.mesh.triangles);
  s.mesh.points.resize(Eigen::Index(s.vertices.size()), 3);
  for(std::size_t k = 0; k < s.vertices.size(); ++k) s.mesh.points.row(Eigen::Index(k)) = mesh.points.row(s.vertices[k]);
  return s;
}

// What the type-matching rule compares: seam-loop count, area and loop
// perimeters (longest first).
struct Size_signature
{
  int loops = 0;
  double area = 0.;
  std::vector<double> perimeters;
};

Size_signature size_signature(const Indexed_mesh& mesh)
{
  Size_signature s;
  for(const Triangle& t : mesh.triangles)
  {
    const Eigen::Vector3d a = mesh.points.row(t[0]), b = mesh.points.row(t[1]), c = mesh.points.row(t[2]);
    s.area += 0.5 * (b - a).cross(c - a).norm();
  }
  const std::vector<std::vector<int>> loops = boundary_loops(mesh);
  s.loops = static_cast<int>(loops.size());
  for(const std::vector<int>& loop : loops)
  {
    double length = 0.;
    for(std::size_t k = 0; k < loop.size(); ++k)
      length += (mesh.points.row(loop[k]) - mesh.points.row(loop[(k + 1) % loop.size()])).norm();
    s.perimeters.push_back(length);
  }
  std::sort(s.perimeters.begin(), s.perimeters.end(), std::greater<double>());
  return s;
}

// Log ratios treat "twice as large" and "half as large" alike; a zero
// measure on either side (a degenerate template) counts as a poor fit.
double log_ratio(double a, double b)
{
  if(!(a > 0.) || !(b > 0.)) return 10.;
  return std::abs(std::log(a / b));
}

double size_mismatch(const Size_signature& segment, const Size_signature& type)
{
  double perimeter = 0.;
  for(std::size_t i = 0; i < segment.perimeters.size(); ++i)
    perimeter += log_ratio(segment.perimeters[i], type.perimeters[i]);
  if(!segment.perimeters.empty()) perimeter /= double(segment.perimeters.size());
  return log_ratio(segment.area, type.area) + perimeter;
}

Indexed_mesh template_of(const Part_type& type)
{
  Indexed_mesh m;
  m.points = type.space.mean;
  m.triangles = type.triangles;
  return m;
}

std::string segment_element(int label) { return "segment " + std::to_string(label); }

// Everything about the model the fit needs per type, computed once.
struct Model_templates
{
  std::vector<Indexed_mesh> meshes;
  std::vector<Size_signature> signatures;
  std::vector<std::vector<int>> seam_tags; // per type, per local vertex: the type across, -1
};

// The template's seam tags come from the docking rules: the vertices of a
// site are tagged with the type of the part docked there. Boundary sites
// first; a generalized site only tags vertices no boundary site tagged.
Model_templates model_templates(const Morphable_part_model& model)
{
  Model_templates t;
  for(const Part_type& type : model.types)
  {
    t.meshes.push_back(template_of(type));
    t.signatures.push_back(size_signature(t.meshes.back()));
    t.seam_tags.emplace_back(std::size_t(type.space.mean.rows()), -1);
  }
  for(const Docking_kind kind : {Docking_kind::boundary, Docking_kind::generalized})
    for(const Docking_rule& rule : model.rules)
    {
      if(rule.kind != kind) continue;
      const std::pair<Site_ref, Site_ref> sides[2] = {{rule.first, rule.second}, {rule.second, rule.first}};
      for(const auto& [own, other] : sides)
      {
        if(own.type < 0 || own.type >= int(model.types.size())) continue;
        const Part_type& type = model.types[std::size_t(own.type)];
        if(own.site < 0 || own.site >= int(type.sites.size())) continue;
        std::vector<int>& tags = t.seam_tags[std::size_t(own.type)];
        for(int v : type.sites[std::size_t(own.site)].vertices)
          if(v >= 0 && v < int(tags.size()) && tags[std::size_t(v)] < 0) tags[std::size_t(v)] = other.type;
      }
    }
  return t;
}

std::string loop_counts_of_types(const Morphable_part_model& model, const Model_templates& templates)
{
  std::ostringstream s;
  for(std::size_t t = 0; t < model.types.size(); ++t)
    s << (t ? ", " : "") << '"' << model.types[t].name << "\" " << templates.signatures[t].loops;
  return s.str();
}

// The type of one segment, or an empty reason on success; a non-empty
// reason is what `Input_error` (or `Skipped_segment`) says.
struct Type_choice
{
  int type = -1;
  Fit_type_source source = Fit_type_source::annotation;
  std::string problem;
};

Type_choice choose_type(const Morphable_part_model& model, const Model_templates& templates,
                        const Annotation& annotation, int label, const Size_signature& segment)
{
  Type_choice c;
  const auto named = annotation.part_type_of_label.find(label);
  if(named != annotation.part_type_of_label.end())
  {
    c.type = model.find_type(named->second);
    if(c.type < 0)
    {
      c.problem = "part type \"" + named->second + "\" is not a type of the model";
      return c;
    }
    const int loops = templates.signatures[std::size_t(c.type)].loops;
    if(loops != segment.loops)
      c.problem = "has " + std::to_string(segment.loops) + " seam loops but part type \"" + named->second +
                  "\" has " + std::to_string(loops);
    return c;
  }
  c.source = Fit_type_source::seams_and_size;
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t t = 0; t < model.types.size(); ++t)
  {
    if(templates.signatures[t].loops != segment.loops) continue;
    const double score = size_mismatch(segment, templates.signatures[t]);
    if(score < best) best = score, c.type = static_cast<int>(t);
  }
  if(c.type < 0)
    c.problem = "has " + std::to_string(segment.loops) + " seam loops and no part type of the model has as many (" +
                loop_counts_of_types(model, templates) + ")";
  return c;
}

} // namespace

namespace {

// Tags each boundary vertex of the segment with the type of the segment
// across the seam, as learning tags its segments, so that the two ends of
// a tube are told apart by their neighbours.
std::vector<int> seam_tags_of(const Labeled_mesh& mesh, const Segment& segment, const std::map<int, int>& type_of_label)
{
  std::map<int, int> local;
  for(std::size_t k = 0; k < segment.vertices.size(); ++k) local[segment.vertices[k]] = static_cast<int>(k);
  std::vector<int> tags(segment.vertices.size(), -1);
  for(int f = 0; f < mesh.mesh.number_of_faces(); ++f)
  {
    const int other = mesh.face_labels[std::size_t(f)];
    if(other == segment.label) continue;
    const auto type = type_of_label.find(other);
    for(int v : mesh.mesh.triangles[std::size_t(f)])
    {
      const auto it = local.find(v);
      if(it != local.end()) tags[std::size_t(it->second)] = type == type_of_label.end() ? -1 : type->second;
    }
  }
  return tags;
}

bool has_type_connectivity(const Segment& segment, const Part_type& type)
{
  return segment.mesh.number_of_vertices() == type.space.mean.rows() && segment.mesh.triangles == type.triangles;
}

// Puts the type's template on the segment (or takes the segment's own
// vertices when it has the template's connectivity) and records how well
// the template covers it.
void correspond_segment(const Morphable_part_model& model, const Model_templates& templates, const Labeled_mesh& mesh,
                        const Segment& segment, const std::map<int, int>& type_of_label,
                        const Model_fit_options& options, Segment_fit& fit, std::vector<std::string>& warnings)
{
  const Part_type& type = model.types[std::size_t(fit.type)];
  if(options.use_known_correspondence && has_type_connectivity(segment, type))
  {
    fit.known_correspondence = true;
    fit.corresponded = segment.mesh.points;
    return;
  }
  std::vector<Correspondence_segment> pair(2);
  pair[0].mesh = templates.meshes[std::size_t(fit.type)];
  pair[0].name = "model part type \"" + type.name + "\" template";
  pair[0].seam_tags = templates.seam_tags[std::size_t(fit.type)];
  pair[1].mesh = segment.mesh;
  pair[1].name = mesh.source + " label " + std::to_string(segment.label);
  pair[1].seam_tags = seam_tags_of(mesh, segment, type_of_label);
  Dense_correspondence_options correspondence = options.correspondence;
  correspondence.prior = type.space;
  const Dense_correspondence c = compute_dense_correspondence(pair, type.name, correspondence);
  const Segment_correspondence& s = c.segments[1];
  fit.corresponded = s.positions;
  fit.coverage_residual = s.residual;
  fit.mirrored = s.mirrored;
  fit.flipped_faces = s.flipped_faces;
  for(const std::string& w : c.warnings)
  {
    warnings.push_back(w);
    if(options.warning) options.warning(w);
  }
}

// Distances of the segment's vertices to the fitted surface: what the fit
// leaves uncovered (a fit that shrank onto part of the segment).
double segment_to_fit_rms(const Segment& segment, const Point_matrix& fitted, const std::vector<Triangle>& triangles)
{
  namespace C = internal::correspondence;
  std::vector<C::Kernel::Triangle_3> faces;
  for(const Triangle& t : triangles)
    faces.emplace_back(C::to_point(fitted.row(t[0])), C::to_point(fitted.row(t[1])), C::to_point(fitted.row(t[2])));
  const C::Triangle_tree tree(faces.begin(), faces.end());
  double squared = 0.;
  for(Eigen::Index j = 0; j < segment.mesh.points.rows(); ++j)
    squared += tree.squared_distance(C::to_point(segment.mesh.points.row(j)));
  return std::sqrt(squared / double(std::max<Eigen::Index>(1, segment.mesh.points.rows())));
}

// The fit's residuals, in mesh units and over the diagonals.
void measure_fit(const Part_type& type, const Segment& segment, double mesh_diagonal, Segment_fit& fit)
{
  const Shape_space& space = type.space;
  fit.coordinates_in_sigmas = Eigen::VectorXd::Zero(fit.coordinates.size());
  for(Eigen::Index k = 0; k < fit.coordinates.size(); ++k)
    if(space.sigmas(k) > 0) fit.coordinates_in_sigmas(k) = fit.coordinates(k) / space.sigmas(k);
  const Eigen::Index n = std::max<Eigen::Index>(1, fit.corresponded.rows());
  fit.rms = (fit.fitted - fit.corresponded).norm() / std::sqrt(double(n));
  fit.rms_over_segment_diagonal = fit.segment_diagonal > 0 ? fit.rms / fit.segment_diagonal : 0.;
  fit.rms_over_mesh_diagonal = mesh_diagonal > 0 ? fit.rms / mesh_diagonal : 0.;
  const double back = segment_to_fit_rms(segment, fit.fitted, type.triangles);
  fit.segment_to_fit_over_mesh_diagonal = mesh_diagonal > 0 ? back / mesh_diagonal : 0.;
}

// Where each of `from`'s points has its nearest point among `to`'s rows.
std::vector<int> nearest_rows(const Point_matrix& from, const Point_matrix& to)
{
  using Kernel = internal::correspondence::Kernel;
  using Point_map = CGAL::Pointer_property_map<Kernel::Point_3>::type;
  using Traits = CGAL::Search_traits_adapter<int, Point_map, CGAL::Search_traits_3<Kernel>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  std::vector<Kernel::Point_3> points;
  for(Eigen::Index v = 0; v < to.rows(); ++v) points.push_back(internal::correspondence::to_point(to.row(v)));
  std::vector<int> indices(points.size());
  std::iota(indices.begin(), indices.end(), 0);
  const Point_map point_map = CGAL::make_property_map(points);
  const Search::Tree tree(indices.begin(), indices.end(), Search::Tree::Splitter(), Traits(point_map));
  std::vector<int> nearest(std::size_t(from.rows()), 0);
  for(Eigen::Index j = 0; j < from.rows(); ++j)
  {
    const Search search(tree, internal::correspondence::to_point(from.row(j)), 1, 0., true,
                        Search::Distance(point_map));
    nearest[std::size_t(j)] = search.begin()->first;
  }
  return nearest;
}

// The dense correspondence put the template on the segment without the
// type's shape space; among the placements of the template's vertices on
// the segment, the model explains some better than others (a template slid
// along a tube covers it as well). Alternating closest points on the
// segment (its own seam for a seam vertex; each target also pulled toward
// the segment vertices nearest to its vertex, so that the fit cannot
// shrink onto part of the segment) and the shape space fit is the
// iterative closest point fit of a morphable model: a step is kept while
// it lowers the distance between the model's shape and the surface.
void fit_on_surface(const Part_type& type, const Indexed_mesh& template_mesh, const Segment& segment, int iterations,
                    Segment_fit& fit)
{
  namespace C = internal::correspondence;
  const C::Surface surface(segment.mesh, type.name, "segment " + std::to_string(segment.label));
  std::vector<int> loop_of(std::size_t(fit.corresponded.rows()), -1);
  for(const std::vector<int>& loop : C::loops_of(template_mesh))
    for(int v : loop)
    {
      const C::Vec3 p = fit.corresponded.row(v).transpose();
      double best = std::numeric_limits<double>::infinity();
      for(std::size_t l = 0; l < surface.loops.size(); ++l)
      {
        const double d = (surface.closest_on_loop(int(l), p) - p).squaredNorm();
        if(d < best) best = d, loop_of[std::size_t(v)] = int(l);
      }
    }
  const Eigen::Index n = fit.corresponded.rows();
  const auto closest_on_segment = [&](const Point_matrix& points) {
    Point_matrix closest(n, 3);
    for(Eigen::Index v = 0; v < n; ++v)
    {
      const C::Vec3 p = points.row(v).transpose();
      const int l = loop_of[std::size_t(v)];
      closest.row(v) = (l >= 0 ? surface.closest_on_loop(l, p) : surface.closest(p)).transpose();
    }
    return closest;
  };
  double previous = (fit.fitted - fit.corresponded).norm();
  for(int it = 0; it < iterations; ++it)
  {
    Point_matrix target = closest_on_segment(fit.fitted);
    Eigen::VectorXd count = Eigen::VectorXd::Ones(n);
    const std::vector<int> nearest = nearest_rows(segment.mesh.points, fit.fitted);
    for(std::size_t j = 0; j < nearest.size(); ++j)
      if(loop_of[std::size_t(nearest[j])] < 0)
        target.row(nearest[j]) += segment.mesh.points.row(Eigen::Index(j)), count(nearest[j]) += 1.;
    target.array().colwise() /= count.array();
    Eigen::VectorXd coordinates;
    Rigid_motion motion;
    type.space.fit(target, coordinates, motion);
    const Point_matrix fitted = motion.apply(type.space.shape(coordinates));
    const Point_matrix on_surface = closest_on_segment(fitted);
    const double distance = (fitted - on_surface).norm();
    if(!(distance < previous)) break;
    fit.fitted = fitted;
    fit.corresponded = on_surface;
    fit.coordinates = coordinates;
    fit.motion = motion;
    if(distance > previous * (1 - 1e-3)) break;
    previous = distance;
  }
}

// The labels to fit, checked against the mesh.
std::vector<int> labels_to_fit(const Labeled_mesh& mesh, const std::map<int, std::vector<int>>& faces_of_label,
                               const Model_fit_options& options)
{
  std::vector<int> labels = options.labels;
  if(labels.empty())
    for(const auto& entry : faces_of_label) labels.push_back(entry.first);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  for(int label : labels)
    if(!faces_of_label.count(label))
      throw Input_error(mesh.source, segment_element(label), "no face has this label");
  return labels;
}

} // namespace

Model_fit fit_morphable_part_model(const Morphable_part_model& model, const Labeled_mesh& mesh,
                                   const Annotation& annotation, const Model_fit_options& options)
{
  // Correspondence needs manifold, face-connected segments; say which
  // segment is not before anything is fitted.
  validate_labeled_mesh(mesh);
  validate_segmentation(mesh);
  if(model.types.empty()) throw Input_error(mesh.source, "", "the model has no part types to fit");
  const std::map<int, std::vector<int>> faces_of_label = internal::faces_by_label(mesh);
  const std::vector<int> labels = labels_to_fit(mesh, faces_of_label, options);
  const Model_templates templates = model_templates(model);

  // Every segment gets a type (when it can), fitted or not: neighbours'
  // types tag the seams of the fitted ones.
  std::map<int, Segment> segments;
  std::map<int, Type_choice> choices;
  std::map<int, int> type_of_label;
  for(const auto& [label, faces] : faces_of_label)
  {
    Segment s = extract_segment(mesh.mesh, faces, label);
    choices[label] = choose_type(model, templates, annotation, label, size_signature(s.mesh));
    if(choices[label].problem.empty()) type_of_label[label] = choices[label].type;
    segments.emplace(label, std::move(s));
  }

  Model_fit result;
  result.mesh_diagonal = internal::bounding_box_diagonal(mesh.mesh.points);
  double squared = 0.;
  Eigen::Index points = 0;
  for(std::size_t i = 0; i < labels.size(); ++i)
  {
    const int label = labels[i];
    const Type_choice& choice = choices.at(label);
    if(!choice.problem.empty())
    {
      if(!options.skip_unfittable) throw Input_error(mesh.source, segment_element(label), choice.problem);
      result.skipped.push_back({label, mesh.source + ": " + segment_element(label) + ": " + choice.problem});
      continue;
    }
    const Part_type& type = model.types[std::size_t(choice.type)];
    if(options.progress) options.progress("fitting segment " + std::to_string(label) + " (" + type.name + ")",
                                          double(i) / double(labels.size()));
    Segment_fit fit;
    fit.label = label;
    fit.type = choice.type;
    fit.type_source = choice.source;
    fit.seam_loops = templates.signatures[std::size_t(choice.type)].loops;
    fit.segment_diagonal = internal::bounding_box_diagonal(segments.at(label).mesh.points);
    correspond_segment(model, templates, mesh, segments.at(label), type_of_label, options, fit, result.warnings);
    type.space.fit(fit.corresponded, fit.coordinates, fit.motion);
    fit.fitted = fit.motion.apply(type.space.shape(fit.coordinates));
    if(!fit.known_correspondence && options.surface_iterations > 0)
      fit_on_surface(type, templates.meshes[std::size_t(choice.type)], segments.at(label), options.surface_iterations,
                     fit);
    measure_fit(type, segments.at(label), result.mesh_diagonal, fit);
    squared += (fit.fitted - fit.corresponded).squaredNorm();
    points += fit.corresponded.rows();
    result.segments.push_back(std::move(fit));
  }
  if(points > 0 && result.mesh_diagonal > 0)
    result.rms_over_mesh_diagonal = std::sqrt(squared / double(points)) / result.mesh_diagonal;
  if(options.progress) options.progress("fitting", 1.);
  return result;
}

Labeled_mesh Model_fit::fitted_surface(const Morphable_part_model& model) const
{
  Labeled_mesh out;
  out.source = "fitted surface";
  Eigen::Index rows = 0;
  for(const Segment_fit& s : segments) rows += s.fitted.rows();
  out.mesh.points.resize(rows, 3);
  Eigen::Index offset = 0;
  for(const Segment_fit& s : segments)
  {
    out.mesh.points.middleRows(offset, s.fitted.rows()) = s.fitted;
    for(const Triangle& t : model.types[std::size_t(s.type)].triangles)
    {
      const int o = static_cast<int>(offset);
      out.mesh.triangles.push_back({{t[0] + o, t[1] + o, t[2] + o}});
      out.face_labels.push_back(s.label);
    }
    offset += s.fitted.rows();
  }
  return out;
}

std::vector<Type_fit_error> Model_fit::errors_by_type(const Morphable_part_model& model) const
{
  std::map<int, Type_fit_error> by_type;
  for(const Segment_fit& s : segments)
  {
    Type_fit_error& e = by_type[s.type];
    e.type = s.type;
    e.name = model.types[std::size_t(s.type)].name;
    ++e.segments;
    // Sums of squares now, roots below: every segment of a type has the
    // template's vertex count, so the mean of squares is the RMS over vertices.
    e.rms_over_mesh_diagonal += s.rms_over_mesh_diagonal * s.rms_over_mesh_diagonal;
    e.rms_over_segment_diagonal += s.rms_over_segment_diagonal * s.rms_over_segment_diagonal;
    e.worst_over_mesh_diagonal = std::max(e.worst_over_mesh_diagonal, s.rms_over_mesh_diagonal);
    e.worst_coverage_residual = std::max(e.worst_coverage_residual, s.coverage_residual);
    e.segment_to_fit_over_mesh_diagonal += s.segment_to_fit_over_mesh_diagonal * s.segment_to_fit_over_mesh_diagonal;
    e.worst_segment_to_fit_over_mesh_diagonal =
        std::max(e.worst_segment_to_fit_over_mesh_diagonal, s.segment_to_fit_over_mesh_diagonal);
  }
  std::vector<Type_fit_error> errors;
  for(auto& [type, e] : by_type)
  {
    e.rms_over_mesh_diagonal = std::sqrt(e.rms_over_mesh_diagonal / e.segments);
    e.rms_over_segment_diagonal = std::sqrt(e.rms_over_segment_diagonal / e.segments);
    e.segment_to_fit_over_mesh_diagonal = std::sqrt(e.segment_to_fit_over_mesh_diagonal / e.segments);
    errors.push_back(e);
  }
  return errors;
}

std::vector<Type_fit_error> pool_type_fit_errors(const std::vector<std::vector<Type_fit_error>>& rounds)
{
  std::vector<Type_fit_error> pooled;
  for(const std::vector<Type_fit_error>& round : rounds)
    for(const Type_fit_error& e : round)
    {
      auto it = std::find_if(pooled.begin(), pooled.end(), [&](const Type_fit_error& p) { return p.name == e.name; });
      if(it == pooled.end())
      {
        pooled.push_back(Type_fit_error());
        it = pooled.end() - 1;
        it->name = e.name;
      }
      // Weighted by segment count: squares of RMS values are means of squares.
      it->rms_over_mesh_diagonal += e.segments * e.rms_over_mesh_diagonal * e.rms_over_mesh_diagonal;
      it->rms_over_segment_diagonal += e.segments * e.rms_over_segment_diagonal * e.rms_over_segment_diagonal;
      it->segment_to_fit_over_mesh_diagonal +=
          e.segments * e.segment_to_fit_over_mesh_diagonal * e.segment_to_fit_over_mesh_diagonal;
      it->segments += e.segments;
      it->worst_over_mesh_diagonal = std::max(it->worst_over_mesh_diagonal, e.worst_over_mesh_diagonal);
      it->worst_coverage_residual = std::max(it->worst_coverage_residual, e.worst_coverage_residual);
      it->worst_segment_to_fit_over_mesh_diagonal =
          std::max(it->worst_segment_to_fit_over_mesh_diagonal, e.worst_segment_to_fit_over_mesh_diagonal);
    }
  for(Type_fit_error& p : pooled)
    if(p.segments > 0)
    {
      p.rms_over_mesh_diagonal = std::sqrt(p.rms_over_mesh_diagonal / p.segments);
      p.rms_over_segment_diagonal = std::sqrt(p.rms_over_segment_diagonal / p.segments);
      p.segment_to_fit_over_mesh_diagonal = std::sqrt(p.segment_to_fit_over_mesh_diagonal / p.segments);
    }
  return pooled;
}

Leave_one_out_fit fit_held_out_input(const std::vector<Training_input>& inputs, int held_out,
                                     const Learning_options& learning, const Model_fit_options& fitting)
{
  if(inputs.size() < 2)
    throw Input_error("leave-one-out", "", "needs at least two meshes (one to hold out, one to learn from)");
  if(held_out < 0 || held_out >= int(inputs.size()))
    throw Input_error("leave-one-out", "mesh " + std::to_string(held_out),
                      "no such input (" + std::to_string(inputs.size()) + " meshes)");
  std::vector<Training_input> others;
  for(std::size_t i = 0; i < inputs.size(); ++i)
    if(int(i) != held_out) others.push_back(inputs[i]);
  Leave_one_out_fit r;
  r.held_out = held_out;
  const auto start = std::chrono::steady_clock::now();
  r.model = learn_morphable_part_model(others, learning);
  const auto learned = std::chrono::steady_clock::now();
  const Training_input& input = inputs[std::size_t(held_out)];
  r.fit = fit_morphable_part_model(r.model, input.mesh, input.annotation, fitting);
  r.errors = r.fit.errors_by_type(r.model);
  r.learning_seconds = std::chrono::duration<double>(learned - start).count();
  r.fitting_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - learned).count();
  return r;
}

} // namespace MPM
} // namespace CGAL
