// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <algorithm>
#include <limits>
#include <set>
#include <utility>

namespace CGAL {
namespace MPM {
namespace internal {

std::vector<double> edge_graph_distances(const Point_matrix& points, const std::vector<Cluster_edge>& edges,
                                         const std::vector<int>& sources)
{
  std::vector<double> lengths;
  lengths.reserve(edges.size());
  for(const Cluster_edge& e : edges) lengths.push_back((points.row(e.source) - points.row(e.target)).norm());
  return edge_graph_shortest_paths(static_cast<int>(points.rows()), edges, lengths, sources).distance;
}

Edge_graph_paths edge_graph_shortest_paths(int n, const std::vector<Cluster_edge>& edges,
                                           const std::vector<double>& weights, const std::vector<int>& sources)
{
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                      boost::property<boost::edge_weight_t, double>>;
  // One extra vertex joined to every source by a zero-length edge turns the
  // multi-source search into a single Dijkstra run.
  Graph g(n + 1);
  for(std::size_t e = 0; e < edges.size(); ++e) boost::add_edge(edges[e].source, edges[e].target, weights[e], g);
  for(int s : sources) boost::add_edge(n, s, 0., g);
  Edge_graph_paths paths;
  paths.distance.assign(std::size_t(n) + 1, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> predecessor(std::size_t(n) + 1);
  // Boost's default "unreached" distance is the largest finite double, which
  // std::isfinite() takes for a reached vertex: ask for +infinity.
  boost::dijkstra_shortest_paths(g, n,
                                 boost::distance_map(paths.distance.data())
                                   .predecessor_map(predecessor.data())
                                   .distance_inf(std::numeric_limits<double>::infinity()));
  paths.distance.pop_back();
  paths.predecessor.resize(std::size_t(n));
  for(int v = 0; v < n; ++v) {
    const std::size_t p = predecessor[std::size_t(v)];
    paths.predecessor[std::size_t(v)] = p == std::size_t(v) || p == std::size_t(n) ? -1 : static_cast<int>(p);
  }
  return paths;
}

std::vector<Cluster_edge> mesh_edges(const std::vector<Triangle>& triangles)
{
  std::set<std::pair<int, int>> seen;
  std::vector<Cluster_edge> edges;
  for(const Triangle& t : triangles)
    for(int k = 0; k < 3; ++k)
    {
      const int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      if(seen.insert({a, b}).second) edges.push_back({a, b, false});
    }
  return edges;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
