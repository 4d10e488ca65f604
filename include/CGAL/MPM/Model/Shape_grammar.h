// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_SHAPE_GRAMMAR_H
#define CGAL_MPM_SHAPE_GRAMMAR_H

#include <CGAL/MPM/Model/Docking_site.h>

#include <boost/graph/adjacency_list.hpp>

#include <vector>

namespace CGAL {
namespace MPM {

struct Morphable_part_model;

/// \ingroup PkgMPMRef
/// The discrete half of a morphable part model: a graph whose vertices are
/// docking sites and whose edges are the observed rules. Only observed
/// connections are allowed; a part graph is valid when each of its dockings
/// is an edge here. A model keeps its grammar (`Morphable_part_model::grammar()`),
/// so that editing and reading part graphs do not rebuild it.
class Shape_grammar
{
public:
  /// The Boost.Graph type: vertex property = site, edge property = rule index.
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, Site_ref, int>;
  /// Vertex descriptor of `Graph`.
  using vertex_descriptor = boost::graph_traits<Graph>::vertex_descriptor;

  /// The grammar of no sites and no rules.
  Shape_grammar() = default;
  /// Builds the grammar of `model` (one vertex per docking site of every
  /// type, one edge per rule).
  explicit Shape_grammar(const Morphable_part_model& model);

  /// The graph, for Boost.Graph algorithms.
  const Graph& graph() const { return graph_; }
  /// Graph vertex of a docking site: the sites of type 0 first, then type 1's,
  /// and so on. Throws `std::out_of_range` when the site does not exist.
  vertex_descriptor vertex(const Site_ref& site) const;
  /// Indices of the rules docking `a` to `b` (in either order), increasing
  /// and without repeats; empty when not allowed or when a site does not exist.
  std::vector<int> rules_between(const Site_ref& a, const Site_ref& b) const;
  /// True when some rule docks `a` to `b`.
  bool allows(const Site_ref& a, const Site_ref& b) const { return !rules_between(a, b).empty(); }
  /// Number of docking sites.
  std::size_t number_of_sites() const { return boost::num_vertices(graph_); }
  /// Number of rules.
  std::size_t number_of_rules() const { return boost::num_edges(graph_); }
  /// True when this is the grammar of `model`'s current sites and rules.
  bool describes(const Morphable_part_model& model) const;

private:
  bool has_site(const Site_ref& site) const;

  Graph graph_;
  std::vector<std::size_t> first_vertex_{0}; // of each type's sites, then their number
  std::vector<std::pair<Site_ref, Site_ref>> rule_sites_;
};

} // namespace MPM
} // namespace CGAL

#endif
