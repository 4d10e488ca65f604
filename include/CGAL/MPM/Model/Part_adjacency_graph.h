// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_PART_ADJACENCY_GRAPH_H
#define CGAL_MPM_PART_ADJACENCY_GRAPH_H

#include <CGAL/MPM/Model/Part_graph.h>

#include <boost/graph/adjacency_list.hpp>

#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// A part graph as a Boost.Graph, for its algorithms (breadth-first search,
/// connected components): vertex `i` is node `i`, and the bundled property
/// of an edge is the index of its docking in `Part_graph::edges`. The
/// out-edges of a vertex follow the order of `Part_graph::edges`, so that a
/// traversal meets the dockings of a node in the order the graph lists them.
/// A docking of a node to itself is twice an out-edge of it.
using Part_adjacency_graph =
  boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property, int>;

/// \ingroup PkgMPMRef
/// The adjacency of `graph`'s nodes by its dockings (see `Part_adjacency_graph`).
/// \pre every docking joins two existing nodes
inline Part_adjacency_graph adjacency_graph(const Part_graph& graph)
{
  Part_adjacency_graph g(graph.nodes.size());
  for(std::size_t k = 0; k < graph.edges.size(); ++k)
    boost::add_edge(graph.edges[k].first, graph.edges[k].second, static_cast<int>(k), g);
  return g;
}

/// \ingroup PkgMPMRef
/// The indices in `Part_graph::edges` of the dockings at `node` of the graph
/// `g` was made from, in increasing order.
inline std::vector<int> incident_dockings(const Part_adjacency_graph& g, int node)
{
  std::vector<int> dockings;
  for(auto [e, end] = boost::out_edges(node, g); e != end; ++e) dockings.push_back(g[*e]);
  return dockings;
}

} // namespace MPM
} // namespace CGAL

#endif
