// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Cutting/Segmentation_measures.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Edge_faces.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace CGAL {
namespace MPM {

namespace {

std::vector<double> face_areas(const Indexed_mesh& mesh)
{
  std::vector<double> area;
  area.reserve(mesh.triangles.size());
  for(const Triangle& t : mesh.triangles) {
    const Eigen::RowVector3d a = mesh.points.row(t[0]), b = mesh.points.row(t[1]), c = mesh.points.row(t[2]);
    area.push_back(0.5 * (b - a).cross(c - a).norm());
  }
  return area;
}

void check_sizes(const Indexed_mesh& mesh, const std::vector<int>& labels, const std::vector<int>& reference)
{
  for(const auto* l : {&labels, &reference})
    if(l->size() != mesh.triangles.size())
      throw Input_error("segmentation measures", l == &labels ? "labels" : "reference",
                        "has " + std::to_string(l->size()) + " labels for " + std::to_string(mesh.triangles.size()) +
                          " faces");
}

// Area of each pair (segment of `labels`, segment of `reference`) and of
// each segment: every area-based measure is a function of this table.
struct Overlap
{
  std::map<std::pair<int, int>, double> both;
  std::map<int, double> first, second;
  double total = 0.;
  double sum_of_squared_faces = 0.;
};

Overlap overlap(const Indexed_mesh& mesh, const std::vector<int>& labels, const std::vector<int>& reference)
{
  check_sizes(mesh, labels, reference);
  const std::vector<double> area = face_areas(mesh);
  Overlap o;
  for(std::size_t f = 0; f < area.size(); ++f) {
    o.both[{labels[f], reference[f]}] += area[f];
    o.first[labels[f]] += area[f];
    o.second[reference[f]] += area[f];
    o.total += area[f];
    o.sum_of_squared_faces += area[f] * area[f];
  }
  return o;
}

// Cut vertices of a segmentation, each weighted by half the length of its
// cut edges, so that the sampling density does not depend on the tessellation.
using Edge = std::pair<int, int>;

// Edges between faces of different labels, with the two labels (the
// smaller first; of the first two faces on a non-manifold edge).
std::map<Edge, std::pair<int, int>> cut_edges(const Indexed_mesh& mesh, const std::vector<int>& labels)
{
  std::map<Edge, std::pair<int, int>> cuts;
  for(const auto& [edge, faces] : internal::faces_of_edges(mesh)) {
    const int first = labels[faces[0]];
    const auto other = std::find_if(faces.begin(), faces.end(), [&labels, first](int f) { return labels[f] != first; });
    if(other != faces.end())
      cuts[edge] = std::minmax(labels[faces[0]], labels[*other]);
  }
  return cuts;
}

std::vector<double> cut_vertex_weights(const Indexed_mesh& mesh, const std::vector<int>& labels)
{
  std::vector<double> weight(std::size_t(mesh.number_of_vertices()), 0.);
  for(const auto& entry : cut_edges(mesh, labels)) {
    const Edge& edge = entry.first;
    const double half = 0.5 * (mesh.points.row(edge.first) - mesh.points.row(edge.second)).norm();
    weight[std::size_t(edge.first)] += half;
    weight[std::size_t(edge.second)] += half;
  }
  return weight;
}

// Weighted mean of the distance from the cut of `from` to the cut of `to`.
double directional_cut_distance(const Indexed_mesh& mesh, const std::vector<Cluster_edge>& edges,
                                const std::vector<double>& from, const std::vector<double>& to)
{
  std::vector<int> sources;
  for(std::size_t v = 0; v < to.size(); ++v)
    if(to[v] > 0) sources.push_back(int(v));
  const std::vector<double> distance = internal::edge_graph_distances(mesh.points, edges, sources);
  double sum = 0., weight = 0.;
  for(std::size_t v = 0; v < from.size(); ++v)
    if(from[v] > 0 && std::isfinite(distance[v])) {
      sum += from[v] * distance[v];
      weight += from[v];
    }
  return weight > 0 ? sum / weight : 0.;
}

// Mean Euclidean distance from the surface to its centroid (area weighted,
// each face represented by its centroid).
double mean_radius(const Indexed_mesh& mesh)
{
  const std::vector<double> area = face_areas(mesh);
  std::vector<Eigen::RowVector3d> centre;
  Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
  double total = 0.;
  for(std::size_t f = 0; f < area.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    centre.push_back((mesh.points.row(t[0]) + mesh.points.row(t[1]) + mesh.points.row(t[2])) / 3.);
    centroid += area[f] * centre.back();
    total += area[f];
  }
  if(total <= 0) return 0.;
  centroid /= total;
  double sum = 0.;
  for(std::size_t f = 0; f < area.size(); ++f) sum += area[f] * (centre[f] - centroid).norm();
  return sum / total;
}

} // namespace

double cut_discrepancy(const Indexed_mesh& mesh, const std::vector<int>& labels, const std::vector<int>& reference)
{
  check_sizes(mesh, labels, reference);
  const std::vector<double> cut = cut_vertex_weights(mesh, labels), truth = cut_vertex_weights(mesh, reference);
  const auto has_cut = [](const std::vector<double>& w) {
    return std::any_of(w.begin(), w.end(), [](double x) { return x > 0; });
  };
  if(!has_cut(cut) && !has_cut(truth)) return 0.;
  if(!has_cut(cut) || !has_cut(truth)) return std::numeric_limits<double>::quiet_NaN();
  const std::vector<Cluster_edge> edges = internal::mesh_edges(mesh.triangles);
  const double sum = directional_cut_distance(mesh, edges, cut, truth) + directional_cut_distance(mesh, edges, truth, cut);
  return sum / mean_radius(mesh);
}

std::vector<Segmentation_cut> segmentation_cuts(const Indexed_mesh& mesh, const std::vector<int>& labels)
{
  check_sizes(mesh, labels, labels);
  // Union-find over the vertices of the cut edges of each label pair.
  const std::map<Edge, std::pair<int, int>> edges = cut_edges(mesh, labels);
  std::map<std::pair<int, int>, std::map<int, int>> parent;
  const auto root = [](std::map<int, int>& p, int v) {
    while(p[v] != v) v = p[v] = p[p[v]];
    return v;
  };
  for(const auto& [edge, pair] : edges) {
    std::map<int, int>& p = parent[pair];
    for(int v : {edge.first, edge.second}) p.emplace(v, v);
    p[root(p, edge.first)] = root(p, edge.second);
  }
  std::vector<Segmentation_cut> cuts;
  for(auto& [pair, p] : parent) {
    std::map<int, std::size_t> cut_of_root;
    for(const auto& entry : p) {
      const auto [it, added] = cut_of_root.emplace(root(p, entry.first), cuts.size());
      if(added) cuts.push_back({pair.first, pair.second, {}, 0});
      cuts[it->second].vertices.push_back(entry.first);
    }
    for(const auto& [edge, edge_pair] : edges)
      if(edge_pair == pair) ++cuts[cut_of_root.at(root(p, edge.first))].edges;
  }
  return cuts;
}

std::vector<Segmentation_cut> joint_cuts(const std::vector<Segmentation_cut>& cuts)
{
  std::map<int, std::size_t> longest_open;
  for(const Segmentation_cut& c : cuts)
    if(c.edges < int(c.vertices.size()))
      for(int label : {c.first_label, c.second_label})
        longest_open[label] = std::max(longest_open[label], c.vertices.size());
  std::vector<Segmentation_cut> joints;
  for(const Segmentation_cut& c : cuts)
    if(c.edges == int(c.vertices.size()) || longest_open[c.first_label] == c.vertices.size() ||
       longest_open[c.second_label] == c.vertices.size())
      joints.push_back(c);
  return joints;
}

int central_cut_vertex(const Indexed_mesh& mesh, const std::vector<int>& cut)
{
  Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
  for(int v : cut) centre += mesh.points.row(v);
  centre /= double(cut.size());
  return *std::min_element(cut.begin(), cut.end(), [&](int a, int b) {
    return (mesh.points.row(a) - centre).squaredNorm() < (mesh.points.row(b) - centre).squaredNorm();
  });
}

double cut_distance(const Indexed_mesh& mesh, const std::vector<int>& path, const std::vector<int>& cut)
{
  double sum = 0.;
  for(int u : path) {
    double nearest = std::numeric_limits<double>::infinity();
    for(int w : cut) nearest = std::min(nearest, (mesh.points.row(u) - mesh.points.row(w)).norm());
    sum += nearest;
  }
  return sum / double(path.size());
}

Hamming_distance hamming_distance(const Indexed_mesh& mesh, const std::vector<int>& labels,
                                  const std::vector<int>& reference)
{
  const Overlap o = overlap(mesh, labels, reference);
  // Largest overlap of each segment with a segment of the other segmentation.
  std::map<int, double> best_first, best_second;
  for(const auto& [pair, area] : o.both) {
    best_first[pair.first] = std::max(best_first[pair.first], area);
    best_second[pair.second] = std::max(best_second[pair.second], area);
  }
  Hamming_distance h;
  if(o.total <= 0) return h;
  for(const auto& [label, area] : o.second) h.missing += area - best_second[label];
  for(const auto& [label, area] : o.first) h.false_alarm += area - best_first[label];
  h.missing /= o.total;
  h.false_alarm /= o.total;
  h.average = 0.5 * (h.missing + h.false_alarm);
  return h;
}

double rand_index_error(const Indexed_mesh& mesh, const std::vector<int>& labels, const std::vector<int>& reference)
{
  const Overlap o = overlap(mesh, labels, reference);
  // Over ordered pairs of faces weighted by the product of their areas:
  // pairs together in one segmentation minus pairs together in both, twice.
  double together_first = 0., together_second = 0., together_both = 0.;
  for(const auto& entry : o.first) together_first += entry.second * entry.second;
  for(const auto& entry : o.second) together_second += entry.second * entry.second;
  for(const auto& entry : o.both) together_both += entry.second * entry.second;
  const double pairs = o.total * o.total - o.sum_of_squared_faces; // distinct faces only
  return pairs > 0 ? (together_first + together_second - 2. * together_both) / pairs : 0.;
}

Consistency_error consistency_error(const Indexed_mesh& mesh, const std::vector<int>& labels,
                                    const std::vector<int>& reference)
{
  const Overlap o = overlap(mesh, labels, reference);
  Consistency_error c;
  if(o.total <= 0) return c;
  // A face in both segment k and reference segment l has refinement errors
  // (|k| - |k and l|) / |k| one way and (|l| - |k and l|) / |l| the other.
  double one_way = 0., other_way = 0., local = 0.;
  for(const auto& [pair, area] : o.both) {
    const double e1 = 1. - area / o.first.at(pair.first), e2 = 1. - area / o.second.at(pair.second);
    one_way += area * e1;
    other_way += area * e2;
    local += area * std::min(e1, e2);
  }
  c.global = std::min(one_way, other_way) / o.total;
  c.local = local / o.total;
  return c;
}

Segmentation_comparison compare_segmentations(const Indexed_mesh& mesh, const std::vector<int>& labels,
                                              const std::vector<int>& reference)
{
  Segmentation_comparison s;
  s.cut_discrepancy = cut_discrepancy(mesh, labels, reference);
  s.hamming = hamming_distance(mesh, labels, reference);
  s.rand_index_error = rand_index_error(mesh, labels, reference);
  s.consistency = consistency_error(mesh, labels, reference);
  return s;
}

} // namespace MPM
} // namespace CGAL
