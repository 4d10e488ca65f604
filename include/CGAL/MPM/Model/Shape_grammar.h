// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_SHAPE_GRAMMAR_H
#define CGAL_MPM_SHAPE_GRAMMAR_H

#include <CGAL/MPM/Model/Docking_site.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <boost/graph/adjacency_list.hpp>

#include <map>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// The discrete half of a morphable part model: a graph whose vertices are
/// docking sites and whose edges are the observed rules. Only observed
/// connections are allowed; a part graph is valid when each of its dockings
/// is an edge here.
class Shape_grammar
{
public:
  /// The Boost.Graph type: vertex property = site, edge property = rule index.
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, Site_ref, int>;
  /// Vertex descriptor of `Graph`.
  using vertex_descriptor = boost::graph_traits<Graph>::vertex_descriptor;

  /// Builds the grammar of `model` (one vertex per docking site of every
  /// type, one edge per rule).
  explicit Shape_grammar(const Morphable_part_model& model);

  /// The graph, for Boost.Graph algorithms.
  const Graph& graph() const { return graph_; }
  /// Graph vertex of a docking site.
  vertex_descriptor vertex(const Site_ref& site) const { return vertex_of_site_.at(site); }
  /// Indices of the rules docking `a` to `b` (in either order); empty when not allowed.
  std::vector<int> rules_between(const Site_ref& a, const Site_ref& b) const;
  /// True when some rule docks `a` to `b`.
  bool allows(const Site_ref& a, const Site_ref& b) const { return !rules_between(a, b).empty(); }
  /// Number of docking sites.
  std::size_t number_of_sites() const { return boost::num_vertices(graph_); }
  /// Number of rules.
  std::size_t number_of_rules() const { return boost::num_edges(graph_); }

private:
  Graph graph_;
  std::map<Site_ref, vertex_descriptor> vertex_of_site_;
};

} // namespace MPM
} // namespace CGAL

#endif
