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
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                      boost::property<boost::edge_weight_t, double>>;
  const int n = static_cast<int>(points.rows());
  // One extra vertex joined to every source by a zero-length edge turns the
  // multi-source search into a single Dijkstra run.
  Graph g(n + 1);
  for(const Cluster_edge& e : edges)
    boost::add_edge(e.source, e.target, (points.row(e.source) - points.row(e.target)).norm(), g);
  for(int s : sources) boost::add_edge(n, s, 0., g);
  std::vector<double> distance(n + 1, std::numeric_limits<double>::infinity());
  boost::dijkstra_shortest_paths(g, n, boost::distance_map(distance.data()));
  distance.pop_back();
  return distance;
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
