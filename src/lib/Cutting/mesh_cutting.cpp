// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/internal/Crease_weights.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>
#include <CGAL/MPM/internal/Vertex_components.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace CGAL {
namespace MPM {

namespace {

using Mesh = internal::Indexed_surface_mesh;
using vertex_descriptor = Mesh::Vertex_index;
using edge_descriptor = Mesh::Edge_index;
using face_descriptor = Mesh::Face_index;

std::string cut_name(const Cut_specification& spec, std::size_t i)
{
  const std::string& name = spec.cuts[i].name;
  return "cuts[" + std::to_string(i) + "]" + (name.empty() ? "" : " \"" + name + "\"");
}

Eigen::Vector3d position(const Indexed_mesh& m, vertex_descriptor v) { return m.points.row(int(v)).transpose(); }

class Cutter
{
public:
  Cutter(const Indexed_mesh& m, const Cut_specification& spec, const Cutting_options& options,
         const std::string& mesh_source)
    : m_(m), spec_(spec), source_(spec.source.empty() ? "cut specification" : spec.source),
      // The halfedge structure gives each edge its two faces (dihedral
      // angles) and is what CGAL's connected_components walks.
      mesh_(internal::to_surface_mesh(m, mesh_source, "cutting"))
  {
    weight_ = internal::crease_edge_weights(mesh_, m_, options.feature_weight);
    for(edge_descriptor e : mesh_.edges())
      edges_.push_back({int(mesh_.vertex(e, 0)), int(mesh_.vertex(e, 1)), false});
    component_ = internal::vertex_component_labels(m_);
  }

  std::vector<int> trace(std::size_t i, bool closed) const
  {
    const Cut_line& cut = spec_.cuts[i];
    const std::string element = cut_name(spec_, i);
    if(cut.vertices.size() < 2)
      fail(element, "has " + std::to_string(cut.vertices.size()) + " vertex" +
                      (cut.vertices.size() == 1 ? "" : "es") + "; a cut needs at least two");
    const int n = m_.number_of_vertices();
    std::vector<bool> is_point(std::size_t(n), false);
    for(int v : cut.vertices) {
      if(v < 0 || v >= n)
        fail(element, "vertex " + std::to_string(v) + " is out of range (the mesh has " + std::to_string(n) +
                        " vertices)");
      if(component_[std::size_t(v)] < 0) fail(element, "vertex " + std::to_string(v) + " belongs to no face");
      if(is_point[std::size_t(v)]) fail(element, "vertex " + std::to_string(v) + " is listed twice");
      is_point[std::size_t(v)] = true;
    }

    std::vector<bool> used(std::size_t(n), false);
    std::vector<int> path{cut.vertices.front()};
    used[std::size_t(path.front())] = true;
    const std::size_t segments = cut.vertices.size() - (closed ? 0 : 1);
    for(std::size_t s = 0; s < segments; ++s) {
      const int a = cut.vertices[s], b = cut.vertices[(s + 1) % cut.vertices.size()];
      if(component_[std::size_t(a)] != component_[std::size_t(b)])
        fail(element, "vertices " + std::to_string(a) + " and " + std::to_string(b) +
                        " lie on different connected components of the mesh: no path joins them");
      // The path may not touch the cut so far nor its later points, so that
      // the cut stays a simple line or loop through its points in order.
      auto open = [&](int v) { return v == a || v == b || (!used[std::size_t(v)] && !is_point[std::size_t(v)]); };
      std::vector<Cluster_edge> edges;
      std::vector<double> weights;
      for(std::size_t e = 0; e < edges_.size(); ++e)
        if(open(edges_[e].source) && open(edges_[e].target)) {
          edges.push_back(edges_[e]);
          weights.push_back(weight_[e]);
        }
      const internal::Edge_graph_paths paths = internal::edge_graph_shortest_paths(n, edges, weights, {a});
      if(!std::isfinite(paths.distance[std::size_t(b)]))
        fail(element, "no path from vertex " + std::to_string(a) + " to vertex " + std::to_string(b) +
                        " avoids the cut's other points and segments (are the points in order along the cut?)");
      std::vector<int> segment;
      for(int v = b; v != a; v = paths.predecessor[std::size_t(v)]) segment.push_back(v);
      for(auto v = segment.rbegin(); v != segment.rend(); ++v) {
        used[std::size_t(*v)] = true;
        path.push_back(*v);
      }
    }
    return path;
  }

  // Edges of a vertex path (consecutive vertices are joined by mesh edges).
  std::vector<edge_descriptor> path_edges(const std::vector<int>& path) const
  {
    std::vector<edge_descriptor> r;
    for(std::size_t k = 0; k + 1 < path.size(); ++k)
      r.push_back(mesh_.edge(mesh_.halfedge(vertex_descriptor(path[k]), vertex_descriptor(path[k + 1]))));
    return r;
  }

  // Face-connected regions when the edges of the cuts with `active` set are constrained.
  int regions(const std::vector<std::vector<edge_descriptor>>& cut_edges, const std::vector<bool>& active,
              std::vector<std::size_t>* region_of_face = nullptr) const
  {
    std::vector<char> constrained(mesh_.number_of_edges(), 0);
    for(std::size_t c = 0; c < cut_edges.size(); ++c)
      if(active[c])
        for(edge_descriptor e : cut_edges[c]) constrained[e] = 1;
    std::vector<std::size_t> region(mesh_.number_of_faces());
    const auto count = CGAL::Polygon_mesh_processing::connected_components(
      mesh_, CGAL::make_property_map(region),
      CGAL::parameters::edge_is_constrained_map(CGAL::make_property_map(constrained)));
    if(region_of_face) *region_of_face = std::move(region);
    return static_cast<int>(count);
  }

  // Regions that `v` belongs to (several when it lies on a cut).
  std::set<std::size_t> regions_of(int v, const std::vector<std::size_t>& region_of_face) const
  {
    std::set<std::size_t> r;
    const auto h = mesh_.halfedge(vertex_descriptor(v));
    if(h == Mesh::null_halfedge()) return r;
    for(face_descriptor f : CGAL::faces_around_target(h, mesh_))
      if(f != Mesh::null_face()) r.insert(region_of_face[f]);
    return r;
  }

  [[noreturn]] void fail(const std::string& element, const std::string& problem) const
  {
    throw Input_error(source_, element, problem);
  }

private:
  const Indexed_mesh& m_;
  const Cut_specification& spec_;
  std::string source_;
  Mesh mesh_;
  std::vector<double> weight_;
  std::vector<Cluster_edge> edges_; // edge e of mesh_ as a vertex pair
  std::vector<int> component_;      // connected component of each vertex, -1 for isolated vertices
};

} // namespace

Cutting_result cut_mesh(const Indexed_mesh& mesh, const Cut_specification& spec, const Cutting_options& options,
                        const std::string& mesh_source)
{
  if(!(options.feature_weight >= 0) || !std::isfinite(options.feature_weight))
    throw Input_error("cutting options", "feature_weight",
                      "must be finite and non-negative (got " + std::to_string(options.feature_weight) + ")");
  Cutting_result result;
  result.mesh.mesh = mesh;
  result.mesh.source = mesh_source;
  result.mesh.face_labels.assign(mesh.triangles.size(), 0);
  validate_labeled_mesh(result.mesh);

  const Cutter cutter(mesh, spec, options, mesh_source);
  std::vector<std::vector<edge_descriptor>> cut_edges;
  for(std::size_t i = 0; i < spec.cuts.size(); ++i) {
    result.paths.push_back(cutter.trace(i, spec.cuts[i].closed.value_or(options.closed)));
    cut_edges.push_back(cutter.path_edges(result.paths.back()));
    double length = 0.;
    const std::vector<int>& path = result.paths.back();
    for(std::size_t k = 0; k + 1 < path.size(); ++k)
      length += (mesh.points.row(path[k + 1]) - mesh.points.row(path[k])).norm();
    result.lengths.push_back(length);
  }

  std::vector<std::size_t> region_of_face;
  std::vector<bool> active(spec.cuts.size(), true);
  result.regions = cutter.regions(cut_edges, active, &region_of_face);
  // Each cut must be needed: with all the others in place, it must still
  // split something off (two open cuts may only separate together).
  for(std::size_t i = 0; i < spec.cuts.size(); ++i) {
    active[i] = false;
    const int without = cutter.regions(cut_edges, active);
    active[i] = true;
    if(without >= result.regions)
      cutter.fail(cut_name(spec, i),
                  "does not separate the mesh (region count " + std::to_string(result.regions) + " with it, " +
                    std::to_string(without) +
                    " without): a closed cut must go all around a part, an open one must run from border to border");
  }

  // Seeds name their regions; the others are numbered in order of their lowest face.
  std::vector<int> label_of_region(std::size_t(result.regions), -1);
  std::map<int, std::size_t> part_of_label;
  std::map<std::size_t, std::size_t> part_of_region;
  for(std::size_t p = 0; p < spec.parts.size(); ++p) {
    const Part_seed& part = spec.parts[p];
    const std::string element = "parts[" + std::to_string(p) + "]";
    if(part.label < 0) cutter.fail(element, "negative label " + std::to_string(part.label));
    if(!part_of_label.emplace(part.label, p).second)
      cutter.fail(element, "label " + std::to_string(part.label) + " appears twice (also in parts[" +
                             std::to_string(part_of_label[part.label]) + "])");
    if(part.seed < 0 || part.seed >= mesh.number_of_vertices())
      cutter.fail(element, "seed vertex " + std::to_string(part.seed) + " is out of range (the mesh has " +
                             std::to_string(mesh.number_of_vertices()) + " vertices)");
    const std::set<std::size_t> regions = cutter.regions_of(part.seed, region_of_face);
    if(regions.empty())
      cutter.fail(element, "seed vertex " + std::to_string(part.seed) + " belongs to no face, so to no region");
    if(regions.size() > 1) {
      std::string on;
      for(std::size_t c = 0; c < result.paths.size(); ++c)
        if(std::find(result.paths[c].begin(), result.paths[c].end(), part.seed) != result.paths[c].end())
          on += (on.empty() ? "" : ", ") + cut_name(spec, c);
      cutter.fail(element, "seed vertex " + std::to_string(part.seed) + " lies on " + on +
                             ", between regions; choose a vertex inside the part");
    }
    const std::size_t region = *regions.begin();
    const auto seen = part_of_region.emplace(region, p);
    if(!seen.second)
      cutter.fail(element, "seed vertex " + std::to_string(part.seed) + " is in the same region as parts[" +
                             std::to_string(seen.first->second) + "]'s seed (vertex " +
                             std::to_string(spec.parts[seen.first->second].seed) + ")");
    label_of_region[region] = part.label;
  }
  std::vector<std::size_t> first_face(std::size_t(result.regions), std::numeric_limits<std::size_t>::max());
  for(std::size_t f = region_of_face.size(); f-- > 0;) first_face[region_of_face[f]] = f;
  std::vector<std::size_t> order(std::size_t(result.regions));
  for(std::size_t r = 0; r < order.size(); ++r) order[r] = r;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return first_face[x] < first_face[y]; });
  int next = 0;
  for(std::size_t r : order) {
    if(label_of_region[r] >= 0) continue;
    while(part_of_label.count(next) != 0) ++next;
    label_of_region[r] = next++;
  }
  for(std::size_t f = 0; f < region_of_face.size(); ++f)
    result.mesh.face_labels[f] = label_of_region[region_of_face[f]];
  return result;
}

namespace internal {

// Edge weights: length / (1 + w * concave bending angle / mean absolute
// bending angle). Measuring angles against the mesh's own mean makes the
// weight mean the same on coarse and fine triangulations.
std::vector<double> crease_edge_weights(const Indexed_surface_mesh& mesh, const Indexed_mesh& m, double feature_weight)
{
  // Concave means folding towards the outside: for a closed mesh the sign
  // of the enclosed volume says which side that is; an open mesh has no
  // inside, so its normals point out.
  double volume = 0.;
  for(const Triangle& t : m.triangles)
    volume += m.points.row(t[0]).dot(m.points.row(t[1]).cross(m.points.row(t[2])));
  const bool closed = std::none_of(mesh.edges().begin(), mesh.edges().end(),
                                   [&](edge_descriptor e) { return mesh.is_border(e); });
  const double outside = closed && volume < 0 ? -1. : 1.;

  std::vector<double> bend(mesh.number_of_edges(), 0.), length(mesh.number_of_edges(), 0.);
  std::vector<bool> concave(mesh.number_of_edges(), false);
  double sum = 0.;
  int interior = 0;
  for(edge_descriptor e : mesh.edges()) {
    const auto h = mesh.halfedge(e), o = mesh.opposite(h);
    const Eigen::Vector3d a = position(m, mesh.source(h)), b = position(m, mesh.target(h));
    length[e] = (b - a).norm();
    if(mesh.is_border(e)) continue;
    const Eigen::Vector3d c = position(m, mesh.target(mesh.next(h))), d = position(m, mesh.target(mesh.next(o)));
    const Eigen::Vector3d n1 = (b - a).cross(c - a).normalized(), n2 = (a - b).cross(d - b).normalized();
    bend[e] = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
    concave[e] = outside * (d - a).dot(n1) > 0;
    sum += bend[e];
    ++interior;
  }
  const double mean = interior > 0 ? sum / interior : 0.;
  std::vector<double> weight(mesh.number_of_edges());
  for(std::size_t e = 0; e < weight.size(); ++e) {
    const double feature = concave[e] && mean > 0 ? bend[e] / mean : 0.;
    weight[e] = length[e] / (1. + feature_weight * feature);
  }
  return weight;
}

} // namespace internal

} // namespace MPM
} // namespace CGAL
