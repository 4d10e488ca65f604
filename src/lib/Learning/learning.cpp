// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/internal/Surface_mesh_repair.h>
#include <CGAL/MPM/internal/Edge_faces.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>
#include <CGAL/MPM/internal/Part_graph_problem.h>
#include <CGAL/MPM/internal/Training_parts.h>
#include <CGAL/MPM/internal/Example_untangling.h>
#include <CGAL/MPM/internal/Seam_smoothing.h>
#include <CGAL/MPM/internal/Training_segments.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <sstream>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

namespace CGAL {
namespace MPM {

using internal::faces_by_label;
using internal::label_element;
using internal::local_part;
using internal::quoted;
using internal::Observation;
using internal::Part_instance;
using internal::find_dockings;
using internal::find_or_add_site;

namespace {

struct Oriented_observation
{
  int observation = 0;
  bool flipped = false; // rule side 0 is the observation's part b
};

Model_parameters resolve_parameters(const Training_input& first)
{
  Model_parameters p = first.annotation.parameters;
  const std::string source = first.annotation.source.empty() ? "annotation" : first.annotation.source;
  const auto check_positive = [&](double value, const char* name) {
    // Negative values mean "automatic"; zero or non-finite ones are mistakes.
    if(value == 0. || !std::isfinite(value))
      throw Input_error(source, "parameters", std::string(name) + " must be positive (got " + std::to_string(value) + ")");
  };
  check_positive(p.sigma_sub, "sigma_sub");
  check_positive(p.sigma_bound, "sigma_bound");
  check_positive(p.docking_radius, "docking_radius");
  if(!(p.explained_variance > 0. && p.explained_variance <= 1.))
    throw Input_error(source, "parameters", "explained_variance must be in (0, 1]");
  if(p.modes < 0)
    throw Input_error(source, "parameters", "modes must not be negative");
  const double diagonal = internal::bounding_box_diagonal(first.mesh.mesh.points);
  if(p.docking_radius < 0) p.docking_radius = 0.05 * diagonal;
  return p;
}

// Leaving the subspace must cost more than moving within it, at every mesh
// resolution: half the typical per-vertex deviation of the types' strongest
// modes (the median over types) does that; 0.2% of the bounding-box diagonal
// when no type varies.
double automatic_sigma_sub(const Morphable_part_model& model, const Training_input& first)
{
  // A mode whose deviation is rounding (instances identical up to it: the
  // two halves of a cut tube gave 3.7e-15) is no variation.
  const double diagonal = internal::bounding_box_diagonal(first.mesh.mesh.points);
  std::vector<double> per_vertex;
  for(const Part_type& t : model.types)
    if(t.space.number_of_modes() > 0 && t.space.sigmas[0] / std::sqrt(double(t.number_of_vertices)) > 1e-9 * diagonal)
      per_vertex.push_back(t.space.sigmas[0] / std::sqrt(double(t.number_of_vertices)));
  if(per_vertex.empty()) return 0.002 * diagonal;
  std::nth_element(per_vertex.begin(), per_vertex.begin() + per_vertex.size() / 2, per_vertex.end());
  return 0.5 * per_vertex[per_vertex.size() / 2];
}

// A model every edit would refuse is refused here, where the mesh can be
// named: lengths whose squares underflow (a mesh scaled by 1e-200) or
// overflow leave a zero or infinite stiffness.
void check_editable(const Model_parameters& p, const Training_input& first)
{
  const std::string source = first.mesh.source.empty() ? "training mesh" : first.mesh.source;
  const double diagonal = internal::bounding_box_diagonal(first.mesh.mesh.points);
  for(const auto& [name, value] : {std::make_pair("sigma_sub", p.sigma_sub), std::make_pair("docking_radius", p.docking_radius)})
    if(!(value > 0.) || !std::isnormal(1. / (value * value)))
    {
      std::ostringstream message;
      message << "the mesh spans " << diagonal << " (diagonal), so " << name << " would be " << value
              << ": too small or too large to edit with; scale the mesh";
      throw Input_error(source, "bounding box", message.str());
    }
}

// Local numbering by first appearance in the part's faces (the known
// correspondence convention), local triangles, and the part's type.
void extract_parts(const std::vector<Training_input>& inputs, Morphable_part_model& model,
                   std::vector<Part_instance>& parts, std::vector<std::vector<int>>& instances_of_type)
{
  for(std::size_t e = 0; e < inputs.size(); ++e)
  {
    const Labeled_mesh& lm = inputs[e].mesh;
    const Annotation& annotation = inputs[e].annotation;
    const std::string annotation_source = annotation.source.empty() ? lm.source + " annotation" : annotation.source;
    const std::map<int, std::vector<int>> faces_of_label = faces_by_label(lm);

    if(!annotation.part_type_of_label.empty())
    {
      for(const auto& [label, type] : annotation.part_type_of_label)
        if(!faces_of_label.count(label))
          throw Input_error(annotation_source, label_element(label, type),
                            "no face of " + lm.source + " has this label (empty part)");
      for(const auto& [label, faces] : faces_of_label)
        if(!annotation.part_type_of_label.count(label))
          throw Input_error(lm.source, label_element(label, ""),
                            "label of " + std::to_string(faces.size()) + " faces is not listed in the annotation's parts");
    }

    std::vector<int> local_of(lm.mesh.number_of_vertices(), -1);
    for(const auto& [label, faces] : faces_of_label)
    {
      Part_instance part;
      part.example = static_cast<int>(e);
      part.label = label;
      std::vector<Triangle> triangles;
      local_part(lm.mesh, faces, local_of, part.vertices, triangles);

      int type = -1;
      if(!annotation.part_type_of_label.empty())
      {
        const std::string& name = annotation.part_type_of_label.at(label);
        type = model.find_type(name);
        if(type < 0)
        {
          type = static_cast<int>(model.types.size());
          model.types.push_back(Part_type());
          model.types.back().name = name;
          model.types.back().number_of_vertices = static_cast<int>(part.vertices.size());
          model.types.back().triangles = triangles;
        }
      }
      else
      {
        // Without an annotation, parts with identical connectivity are alike.
        for(std::size_t t = 0; t < model.types.size() && type < 0; ++t)
          if(model.types[t].triangles == triangles) type = static_cast<int>(t);
        if(type < 0)
        {
          type = static_cast<int>(model.types.size());
          model.types.push_back(Part_type());
          model.types.back().name = "type" + std::to_string(type);
          model.types.back().number_of_vertices = static_cast<int>(part.vertices.size());
          model.types.back().triangles = triangles;
        }
      }
      const Part_type& pt = model.types[type];
      if(pt.triangles != triangles)
      {
        const Part_instance& reference = parts[instances_of_type[type].front()];
        std::string detail;
        if(pt.triangles.size() != triangles.size())
          detail = std::to_string(triangles.size()) + " faces against " + std::to_string(pt.triangles.size());
        else
        {
          std::size_t k = 0;
          while(pt.triangles[k] == triangles[k]) ++k;
          detail = "its local face " + std::to_string(k) + " (mesh face " + std::to_string(faces[k]) +
                   ") differs";
        }
        throw Input_error(lm.source, label_element(label, pt.name),
                          "connectivity differs from label " + std::to_string(reference.label) + " of " +
                            inputs[reference.example].mesh.source + " (" + detail +
                            "); instances of a type must list their faces in the same local order");
      }
      const auto landmarks = annotation.landmarks_of_label.find(label);
      if(landmarks != annotation.landmarks_of_label.end())
        for(std::size_t k = 0; k < landmarks->second.size(); ++k)
        {
          const int v = landmarks->second[k];
          if(v < 0 || v >= lm.mesh.number_of_vertices() ||
             std::find(part.vertices.begin(), part.vertices.end(), v) == part.vertices.end())
            throw Input_error(annotation_source, label_element(label, pt.name) + ": landmark " + std::to_string(k),
                              "vertex " + std::to_string(v) + " is not a vertex of this part");
        }
      part.type = type;
      if(instances_of_type.size() <= std::size_t(type)) instances_of_type.resize(type + 1);
      part.instance = static_cast<int>(instances_of_type[type].size());
      instances_of_type[type].push_back(static_cast<int>(parts.size()));
      parts.push_back(std::move(part));
    }
    for(const auto& [name, modes] : annotation.modes_of_type)
      if(model.find_type(name) < 0)
        throw Input_error(annotation_source, "part type " + quoted(name), "named in the annotation but has no instance");
  }
}

// Mesh edges plus, for a part made of several pieces (a polygon soup), a
// virtual edge from every vertex of the other pieces to the vertex nearest
// to the centroid, so that no piece drifts away.
void build_type_edges(Part_type& type, const Point_matrix& first_instance)
{
  type.edges = internal::mesh_edges(type.triangles);
  const int n = type.number_of_vertices;
  std::vector<int> rank(n), parent(n);
  boost::disjoint_sets<int*, int*> components(rank.data(), parent.data());
  for(int v = 0; v < n; ++v) components.make_set(v);
  for(const Cluster_edge& e : type.edges) components.union_set(e.source, e.target);
  int center = 0;
  const Eigen::RowVector3d centroid = first_instance.colwise().mean();
  for(int v = 1; v < n; ++v)
    if((first_instance.row(v) - centroid).squaredNorm() < (first_instance.row(center) - centroid).squaredNorm())
      center = v;
  const int center_set = components.find_set(center);
  for(int v = 0; v < n; ++v)
    if(components.find_set(v) != center_set)
      type.edges.push_back({std::min(v, center), std::max(v, center), true});
}

Point_matrix instance_points(const Part_instance& part, const Indexed_mesh& mesh)
{
  Point_matrix p(part.vertices.size(), 3);
  for(std::size_t i = 0; i < part.vertices.size(); ++i) p.row(i) = mesh.points.row(part.vertices[i]);
  return p;
}

std::vector<std::pair<int, int>> swapped(const std::vector<std::pair<int, int>>& seam)
{
  std::vector<std::pair<int, int>> r;
  for(const auto& [a, b] : seam) r.push_back({b, a});
  std::sort(r.begin(), r.end());
  return r;
}

// The same merged seam seen from the other side, whose loop runs the other way.
std::vector<Seam_vertex> swapped(const std::vector<Seam_vertex>& seam)
{
  std::vector<Seam_vertex> r(seam.rbegin(), seam.rend());
  for(Seam_vertex& v : r)
  {
    std::swap(v.local[0], v.local[1]);
    std::swap(v.from[0], v.from[1]);
    std::swap(v.to[0], v.to[1]);
    std::swap(v.weight[0], v.weight[1]);
    v.parameter = v.parameter > 0. ? 1. - v.parameter : 0.;
  }
  return r;
}

// Near neighbours for the virtual edges of a generalized docking: each site
// vertex is tied to its few closest vertices of the other site.
constexpr int virtual_neighbours = 3;

void add_virtual_edges(const Point_matrix& from, const std::vector<int>& from_points, const Point_matrix& to,
                       const std::vector<int>& to_points, std::set<std::pair<int, int>>& edges)
{
  std::vector<int> order(to.rows());
  for(Eigen::Index i = 0; i < from.rows(); ++i)
  {
    std::iota(order.begin(), order.end(), 0);
    const int k = std::min<int>(virtual_neighbours, static_cast<int>(order.size()));
    std::partial_sort(order.begin(), order.begin() + k, order.end(), [&](int x, int y) {
      return (to.row(x) - from.row(i)).squaredNorm() < (to.row(y) - from.row(i)).squaredNorm();
    });
    for(int j = 0; j < k; ++j)
    {
      const int a = from_points[i], b = to_points[order[j]];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
}

// An example with merged seams becomes one mesh: its parts' border edges
// split at the other side's seam vertices, identified vertices shared, the
// seams straightened on `input`, the surface the example approximates.
void stitch_example(const Morphable_part_model& model, Part_graph& graph, Labeled_mesh& surface,
                    const Indexed_mesh& input)
{
  if(std::all_of(graph.edges.begin(), graph.edges.end(), [](const Part_edge& e) { return e.merged_seam.empty(); }))
    return;
  const internal::Graph_refinement refined = internal::refine_part_graph(model, graph);
  std::vector<Point_matrix> placed;
  for(std::size_t i = 0; i < graph.nodes.size(); ++i)
    placed.push_back(internal::refine_points(internal::gather_rows(surface.mesh.points, graph.nodes[i].vertices),
                                             refined.nodes[i].inserted));
  std::vector<int> face_nodes;
  surface.mesh = internal::stitch_part_graph(model, graph, refined, placed, &face_nodes);
  surface.face_labels.clear();
  for(int node : face_nodes) surface.face_labels.push_back(graph.nodes[node].label);
  std::set<std::pair<int, int>> merged;
  for(const Part_edge& e : graph.edges)
    if(!e.merged_seam.empty()) {
      const int a = graph.nodes[std::size_t(e.first)].label, b = graph.nodes[std::size_t(e.second)].label;
      merged.insert({std::min(a, b), std::max(a, b)});
    }
  surface.mesh.points = internal::smoothed_seams(surface.mesh, surface.face_labels, merged, input);
}

// The labels of the faces on edges of one face (open seams, holes).
std::set<int> labels_at_open_edges(const Indexed_mesh& mesh, const std::vector<int>& face_labels)
{
  std::set<int> labels;
  for(const auto& [edge, faces] : internal::faces_of_edges(mesh))
    if(faces.size() == 1) labels.insert(face_labels[std::size_t(faces.front())]);
  return labels;
}

// The learner proper, on inputs whose same-type parts share connectivity
// (`corresponded`: how they were made so, or null).
Morphable_part_model learn_corresponded(const std::vector<Training_input>& inputs, const Learning_options& options,
                                        const Corresponded_training* corresponded,
                                        const std::vector<Training_input>* originals)
{
  const auto progress = [&](const std::string& stage, double fraction) {
    internal::throw_if_cancelled(options.cancel, "learning");
    if(options.progress) options.progress(stage, fraction);
  };
  const auto warn = [&](const std::string& w) {
    if(options.warning) options.warning(w);
  };

  Morphable_part_model model;
  model.parameters = resolve_parameters(inputs.front());
  const Model_parameters& parameters = model.parameters;

  progress("parts", 0.);
  std::vector<Part_instance> parts;
  std::vector<std::vector<int>> instances_of_type;
  extract_parts(inputs, model, parts, instances_of_type);
  for(std::size_t t = 0; t < model.types.size(); ++t)
  {
    const Part_instance& first = parts[instances_of_type[t].front()];
    build_type_edges(model.types[t], instance_points(first, inputs[first.example].mesh.mesh));
  }

  progress("dockings", 0.1);
  std::vector<Observation> observations = find_dockings(inputs, parts, parameters.docking_radius, corresponded, originals);
  for(Observation& o : observations)
  {
    o.ref_a = {parts[o.a].type, find_or_add_site(model.types[parts[o.a].type], o.kind, o.site_a)};
    o.ref_b = {parts[o.b].type, find_or_add_site(model.types[parts[o.b].type], o.kind, o.site_b)};
  }
  {
    std::vector<bool> docked(parts.size(), false);
    for(const Observation& o : observations) docked[o.a] = docked[o.b] = true;
    for(std::size_t p = 0; p < parts.size(); ++p)
      if(!docked[p] && parts.size() > 1)
        warn(inputs[parts[p].example].mesh.source + ": " +
             label_element(parts[p].label, model.types[parts[p].type].name) +
             ": docks to no other part (no shared seam, nothing within the docking radius)");
  }

  // Rules: one per distinct (site, site, seam mapping); observations are
  // oriented so that the smaller site reference plays side 0.
  using Rule_key = std::tuple<Site_ref, Site_ref, int, std::vector<std::pair<int, int>>>;
  std::map<Rule_key, int> rule_of_key;
  std::vector<std::vector<Oriented_observation>> rule_observations;
  std::vector<int> rule_of_observation(observations.size());
  for(std::size_t i = 0; i < observations.size(); ++i)
  {
    const Observation& o = observations[i];
    bool flip = o.ref_b < o.ref_a;
    if(o.ref_a == o.ref_b) flip = swapped(o.seam) < o.seam;
    const Rule_key key = flip ? Rule_key(o.ref_b, o.ref_a, int(o.kind), swapped(o.seam))
                              : Rule_key(o.ref_a, o.ref_b, int(o.kind), o.seam);
    auto [it, inserted] = rule_of_key.insert({key, static_cast<int>(model.rules.size())});
    if(inserted)
    {
      Docking_rule rule;
      rule.first = std::get<0>(key);
      rule.second = std::get<1>(key);
      rule.kind = o.kind;
      rule.seam = std::get<3>(key);
      rule.merged_seam = flip ? swapped(o.merged) : o.merged;
      model.rules.push_back(std::move(rule));
      rule_observations.emplace_back();
    }
    rule_of_observation[i] = it->second;
    rule_observations[it->second].push_back({static_cast<int>(i), flip});
  }

  const int total_spaces = static_cast<int>(model.types.size() + model.rules.size());
  int spaces_done = 0;
  const auto space_options = [&](const std::string& type_name) {
    Shape_space_options so;
    so.modes = parameters.modes;
    so.explained_variance = parameters.explained_variance;
    for(const Training_input& input : inputs)
    {
      const auto it = input.annotation.modes_of_type.find(type_name);
      if(it != input.annotation.modes_of_type.end() && it->second > 0) so.modes = it->second;
    }
    return so;
  };

  for(std::size_t t = 0; t < model.types.size(); ++t)
  {
    progress("shape space of " + model.types[t].name, 0.2 + 0.8 * spaces_done++ / total_spaces);
    std::vector<Point_matrix> instances;
    for(int p : instances_of_type[t]) instances.push_back(instance_points(parts[p], inputs[parts[p].example].mesh.mesh));
    model.types[t].space = learn_shape_space(instances, space_options(model.types[t].name));
  }

  if(model.parameters.sigma_sub < 0) model.parameters.sigma_sub = automatic_sigma_sub(model, inputs.front());
  check_editable(model.parameters, inputs.front());

  std::vector<int> instance_in_rule(observations.size(), -1);
  for(std::size_t r = 0; r < model.rules.size(); ++r)
  {
    Docking_rule& rule = model.rules[r];
    progress("pair geometry of rule " + std::to_string(r), 0.2 + 0.8 * spaces_done++ / total_spaces);
    const Part_type& type0 = model.types[rule.first.type];
    const Part_type& type1 = model.types[rule.second.type];
    const auto side_parts = [&](const Oriented_observation& oo) {
      const Observation& o = observations[oo.observation];
      return oo.flipped ? std::make_pair(o.b, o.a) : std::make_pair(o.a, o.b);
    };
    const auto side_sites = [&](const Oriented_observation& oo) {
      const Observation& o = observations[oo.observation];
      return oo.flipped ? std::make_pair(&o.site_b, &o.site_a) : std::make_pair(&o.site_a, &o.site_b);
    };

    // Points of each side: within r of the seam along the part's edges
    // (boundary), or the docking site itself (generalized); united over the
    // observations so that every observation has the same points.
    std::set<int> set0, set1;
    for(const Oriented_observation& oo : rule_observations[r])
    {
      const auto [p0, p1] = side_parts(oo);
      const auto [s0, s1] = side_sites(oo);
      if(rule.kind == Docking_kind::boundary)
      {
        const auto collect = [&](int p, const Part_type& type, const std::vector<int>& seam, std::set<int>& out) {
          const std::vector<double> d = internal::edge_graph_distances(
            instance_points(parts[p], inputs[parts[p].example].mesh.mesh), type.edges, seam);
          for(std::size_t v = 0; v < d.size(); ++v)
            if(d[v] <= parameters.docking_radius) out.insert(static_cast<int>(v));
        };
        collect(p0, type0, *s0, set0);
        collect(p1, type1, *s1, set1);
      }
      else
      {
        set0.insert(s0->begin(), s0->end());
        set1.insert(s1->begin(), s1->end());
      }
    }
    std::map<int, int> seam_of_second;
    for(const auto& [l0, l1] : rule.seam) seam_of_second[l1] = l0;
    std::map<int, int> index0, index1;
    for(int v : set0)
    {
      index0[v] = static_cast<int>(rule.points.size());
      rule.points.push_back({0, v});
    }
    for(int v : set1)
    {
      const auto it = seam_of_second.find(v);
      if(it != seam_of_second.end())
      {
        if(!index0.count(it->second))
        {
          index0[it->second] = static_cast<int>(rule.points.size());
          rule.points.push_back({0, it->second});
        }
        index1[v] = index0[it->second];
      }
      else
      {
        index1[v] = static_cast<int>(rule.points.size());
        rule.points.push_back({1, v});
      }
    }
    std::map<std::pair<int, int>, bool> edge_is_virtual;
    const auto add_type_edges = [&](const Part_type& type, const std::map<int, int>& index) {
      for(const Cluster_edge& e : type.edges)
      {
        const auto a = index.find(e.source), b = index.find(e.target);
        if(a == index.end() || b == index.end()) continue;
        const std::pair<int, int> key(std::min(a->second, b->second), std::max(a->second, b->second));
        const auto it = edge_is_virtual.find(key);
        if(it == edge_is_virtual.end()) edge_is_virtual[key] = e.is_virtual;
        else it->second = it->second && e.is_virtual;
      }
    };
    add_type_edges(type0, index0);
    add_type_edges(type1, index1);
    // Across a merged seam, which each observation samples differently,
    // virtual edges tie the two sides as in a generalized docking.
    if(rule.kind == Docking_kind::generalized || !rule.merged_seam.empty())
    {
      std::set<std::pair<int, int>> virtual_edges;
      for(const Oriented_observation& oo : rule_observations[r])
      {
        const auto [p0, p1] = side_parts(oo);
        const auto [s0, s1] = side_sites(oo);
        const Point_matrix x0 = instance_points(parts[p0], inputs[parts[p0].example].mesh.mesh);
        const Point_matrix x1 = instance_points(parts[p1], inputs[parts[p1].example].mesh.mesh);
        Point_matrix y0(s0->size(), 3), y1(s1->size(), 3);
        std::vector<int> i0, i1;
        for(std::size_t k = 0; k < s0->size(); ++k)
        {
          y0.row(k) = x0.row((*s0)[k]);
          i0.push_back(index0.at((*s0)[k]));
        }
        for(std::size_t k = 0; k < s1->size(); ++k)
        {
          y1.row(k) = x1.row((*s1)[k]);
          i1.push_back(index1.at((*s1)[k]));
        }
        add_virtual_edges(y0, i0, y1, i1, virtual_edges);
        add_virtual_edges(y1, i1, y0, i0, virtual_edges);
      }
      for(const auto& key : virtual_edges)
        if(!edge_is_virtual.count(key)) edge_is_virtual[key] = true;
    }
    for(const auto& [key, is_virtual] : edge_is_virtual) rule.edges.push_back({key.first, key.second, is_virtual});

    std::vector<Point_matrix> instances;
    for(const Oriented_observation& oo : rule_observations[r])
    {
      const auto [p0, p1] = side_parts(oo);
      const Indexed_mesh& mesh = inputs[parts[p0].example].mesh.mesh;
      Point_matrix x(rule.points.size(), 3);
      for(std::size_t k = 0; k < rule.points.size(); ++k)
      {
        const Pair_point& q = rule.points[k];
        x.row(k) = mesh.points.row(parts[q.side == 0 ? p0 : p1].vertices[q.local]);
      }
      instance_in_rule[oo.observation] = static_cast<int>(instances.size());
      instances.push_back(std::move(x));
    }
    rule.space = learn_shape_space(instances, space_options(""));
  }

  for(std::size_t e = 0; e < inputs.size(); ++e)
  {
    Part_graph graph;
    std::map<int, int> node_of_part;
    for(std::size_t p = 0; p < parts.size(); ++p)
    {
      if(parts[p].example != int(e)) continue;
      const Shape_space& space = model.types[parts[p].type].space;
      Part_node node;
      node.type = parts[p].type;
      node.label = parts[p].label;
      node.vertices = parts[p].vertices;
      node.coordinates = space.instance_coordinates.col(parts[p].instance);
      node.motion = space.instance_motions[parts[p].instance];
      node_of_part[static_cast<int>(p)] = static_cast<int>(graph.nodes.size());
      graph.nodes.push_back(std::move(node));
    }
    for(std::size_t r = 0; r < model.rules.size(); ++r)
      for(const Oriented_observation& oo : rule_observations[r])
      {
        const Observation& o = observations[oo.observation];
        if(o.example != int(e)) continue;
        const Shape_space& space = model.rules[r].space;
        Part_edge edge;
        edge.first = node_of_part.at(oo.flipped ? o.b : o.a);
        edge.second = node_of_part.at(oo.flipped ? o.a : o.b);
        edge.rule = static_cast<int>(r);
        edge.coordinates = space.instance_coordinates.col(instance_in_rule[oo.observation]);
        edge.motion = space.instance_motions[instance_in_rule[oo.observation]];
        edge.merged_seam = oo.flipped ? swapped(o.merged) : o.merged;
        graph.edges.push_back(std::move(edge));
      }
    const Training_input& input = originals ? (*originals)[e] : inputs[e];
    Labeled_mesh surface = inputs[e].mesh;
    stitch_example(model, graph, surface, input.mesh.mesh);
    // Stitching corresponded parts back together can fail where a
    // template's border folds along its seam; say so rather than hand edits
    // a surface with a gap the input did not have.
    if(labels_at_open_edges(input.mesh.mesh, input.mesh.face_labels).empty())
    {
      const std::set<int> open = labels_at_open_edges(surface.mesh, surface.face_labels);
      if(!open.empty())
      {
        std::string labels;
        for(int l : open) labels += (labels.empty() ? "" : ", ") + std::to_string(l);
        warn(input.mesh.source + ": the learned example is open at the seams of labels " + labels +
             " although the input is closed: stitching the corresponded parts failed there (their templates fold "
             "along the seam); edits will show a gap. Give those segments types of their own, or landmarks");
      }
    }
    model.examples.push_back(make_training_example(inputs[e].mesh.source, surface, std::move(graph)));
  }
  model.update_grammar();
  progress("done", 1.);
  return model;
}

// Writes back into the rebuilt inputs what untangled_positions() moved in
// the learned examples: a vertex of a part moved in the stitched example
// is that part's own vertex in its rebuilt input (stitching identifies
// seam vertices only, which stay). Returns whether anything moved.
bool untangle_rebuilt_inputs(const Morphable_part_model& model, const std::vector<Training_input>& originals,
                             Corresponded_training& corresponded)
{
  bool moved = false;
  for(std::size_t e = 0; e < model.examples.size(); ++e)
  {
    const Training_example& example = model.examples[e];
    const Labeled_mesh surface = to_labeled_mesh(example);
    const Point_matrix untangled = internal::untangled_positions(surface.mesh, surface.face_labels, originals[e].mesh);
    if(untangled.rows() == 0) continue;
    Labeled_mesh& rebuilt = corresponded.inputs[e].mesh;
    const std::map<int, std::vector<int>> faces_of_label = faces_by_label(rebuilt);
    std::vector<int> local_of(rebuilt.mesh.number_of_vertices(), -1);
    for(const Part_node& node : example.graph.nodes)
    {
      std::vector<int> vertices;
      std::vector<Triangle> triangles;
      local_part(rebuilt.mesh, faces_of_label.at(node.label), local_of, vertices, triangles);
      for(std::size_t l = 0; l < vertices.size(); ++l)
      {
        const int v = node.vertices[l];
        if(untangled.row(v) == surface.mesh.points.row(v)) continue;
        rebuilt.mesh.points.row(vertices[l]) = untangled.row(v);
        moved = true;
      }
    }
  }
  return moved;
}

} // namespace

Morphable_part_model learn_morphable_part_model(const std::vector<Training_input>& given,
                                                const Learning_options& options)
{
  if(given.empty()) throw Input_error("", "", "no training mesh given");
  for(const Training_input& input : given) validate_labeled_mesh(input.mesh);
  std::vector<Training_input> inputs = given;
  for(Training_input& input : inputs) {
    const std::string repaired = internal::make_surface_mesh_compatible(input.mesh.mesh, input.mesh.source);
    if(!repaired.empty() && options.warning) options.warning(input.mesh.source + ": " + repaired);
  }
  validate_seam_counts(inputs);
  Corresponded_training corresponded = correspond_training_inputs(inputs, options);
  // With no type corresponded, the inputs are the user's, but segments that
  // could not be corresponded still got types of their own.
  if(corresponded.types.empty()) return learn_corresponded(corresponded.inputs, options, nullptr, nullptr);
  // Where the stitched example crosses itself and its input does not, the
  // corresponded parts are moved apart on the input's surface and learned
  // again: the shape spaces must hold the example as it is. Seam vertices
  // stay, so learning again stitches the same seams and gives the moved
  // example back as it is. The first pass's warnings are said once.
  std::vector<std::string> warnings;
  Learning_options quiet = options;
  quiet.warning = [&warnings](const std::string& w) { warnings.push_back(w); };
  Morphable_part_model model = learn_corresponded(corresponded.inputs, quiet, &corresponded, &inputs);
  if(untangle_rebuilt_inputs(model, inputs, corresponded))
    return learn_corresponded(corresponded.inputs, options, &corresponded, &inputs);
  if(options.warning)
    for(const std::string& w : warnings) options.warning(w);
  return model;
}

Morphable_part_model learn_morphable_part_model(const Labeled_mesh& mesh, const Annotation& annotation,
                                                const Learning_options& options)
{
  return learn_morphable_part_model(std::vector<Training_input>{{mesh, annotation}}, options);
}

} // namespace MPM
} // namespace CGAL
