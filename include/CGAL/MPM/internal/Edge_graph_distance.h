// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_EDGE_GRAPH_DISTANCE_H
#define CGAL_MPM_INTERNAL_EDGE_GRAPH_DISTANCE_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Part_type.h>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// Shortest-path distance along `edges` (lengths measured on `points`) from
// the nearest of `sources`; unreachable points get +infinity. Pair geometry
// (within r of a seam) and blend weights (distance to a cluster's border)
// both measure distance this way, so that a point across a narrow gap of the
// same part is not mistaken for a near one.
std::vector<double> edge_graph_distances(const Point_matrix& points, const std::vector<Cluster_edge>& edges,
                                         const std::vector<int>& sources);

// Shortest paths from the nearest of `sources` over vertices 0 .. n-1
// joined by `edges`, edge e costing `weights[e]` (positive). Cutting lines
// need the paths themselves, with costs other than lengths.
struct Edge_graph_paths
{
  std::vector<double> distance; // +infinity where unreachable
  std::vector<int> predecessor; // previous vertex on a shortest path; -1 at sources and unreachable vertices
};
Edge_graph_paths edge_graph_shortest_paths(int n, const std::vector<Cluster_edge>& edges,
                                           const std::vector<double>& weights, const std::vector<int>& sources);

// Mesh edges of `triangles` (each once, source < target), in first-seen order.
std::vector<Cluster_edge> mesh_edges(const std::vector<Triangle>& triangles);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
