// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/internal/Message_text.h>
#include <CGAL/MPM/internal/Part_graph_problem.h>

#include <boost/graph/breadth_first_search.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace CGAL {
namespace MPM {

using internal::part_graph_source;
using internal::quoted;
using internal::site_text;

namespace {

std::string node_element(const Morphable_part_model& model, const Part_graph& graph, int n)
{
  return "node " + std::to_string(n) + " (" + model.types[graph.nodes[n].type].name + ")";
}

void check_node(const Part_graph& graph, int node, const char* what)
{
  if(node < 0 || node >= int(graph.nodes.size()))
    throw Input_error(part_graph_source, std::string(what) + " " + std::to_string(node),
                      "does not exist (the graph has " + std::to_string(graph.nodes.size()) + " nodes)");
}

// The site node `node` occupies on edge `e`.
Site_ref site_on_edge(const Morphable_part_model& model, const Part_edge& e, int node)
{
  return e.first == node ? model.rules[e.rule].first : model.rules[e.rule].second;
}

// An edge between `a` (at site `sa`) and `b` by `rule`, oriented so that
// the node at the rule's first site plays side 0.
Part_edge oriented_edge(const Morphable_part_model& model, int rule, int a, const Site_ref& sa, int b)
{
  Part_edge e;
  e.rule = rule;
  if(model.rules[rule].first == sa)
  {
    e.first = a;
    e.second = b;
  }
  else
  {
    e.first = b;
    e.second = a;
  }
  return e;
}

// The dockings by which the branch at `node` (`branch`, sorted) hangs from
// the rest of the graph: all lead from `node`, as the rest reaches every
// other node of the branch only through it.
std::vector<int> hanging_dockings(const Part_graph& graph, int node, const std::vector<int>& branch)
{
  const Part_adjacency_graph g = adjacency_graph(graph);
  std::vector<int> hanging;
  for(auto [e, end] = boost::out_edges(node, g); e != end; ++e)
    if(!std::binary_search(branch.begin(), branch.end(), int(boost::target(*e, g)))) hanging.push_back(g[*e]);
  return hanging;
}

} // namespace

std::vector<int> free_sites(const Morphable_part_model& model, const Part_graph& graph, int node)
{
  check_node(graph, node, "node");
  const std::map<Site_ref, int> capacity = observed_site_degrees(model);
  const int type = graph.nodes[node].type;
  std::vector<int> used(model.types[type].sites.size(), 0);
  for(int k : incident_dockings(adjacency_graph(graph), node)) ++used[site_on_edge(model, graph.edges[k], node).site];
  std::vector<int> free;
  for(std::size_t s = 0; s < used.size(); ++s)
    if(used[s] < capacity.at({type, int(s)})) free.push_back(int(s));
  return free;
}

std::vector<Docking_option> free_dockings(const Morphable_part_model& model, const Part_graph& graph,
                                          const Site_ref& other)
{
  const Shape_grammar& grammar = model.grammar();
  std::vector<Docking_option> options;
  for(int n = 0; n < int(graph.nodes.size()); ++n)
    for(int s : free_sites(model, graph, n))
      for(int r : grammar.rules_between({graph.nodes[n].type, s}, other))
        options.push_back({n, s, r});
  return options;
}

int root_node(const Part_graph& graph)
{
  const Part_adjacency_graph g = adjacency_graph(graph);
  int root = -1;
  for(int v = 0; v < int(graph.nodes.size()); ++v)
    if(root < 0 || boost::out_degree(v, g) > boost::out_degree(root, g)) root = v;
  return root;
}

int insert_segment(const Morphable_part_model& model, Part_graph& graph, int edge, int type)
{
  if(edge < 0 || edge >= int(graph.edges.size()))
    throw Input_error(part_graph_source, "edge " + std::to_string(edge),
                      "does not exist (the graph has " + std::to_string(graph.edges.size()) + " edges)");
  if(type >= int(model.types.size()))
    throw Input_error(part_graph_source, "part type " + std::to_string(type), "does not exist");
  const Part_edge old = graph.edges[edge];
  const int a = old.first, b = old.second;
  const Site_ref sa = model.rules[old.rule].first, sb = model.rules[old.rule].second;
  const Shape_grammar& grammar = model.grammar();
  std::vector<int> candidates;
  if(type >= 0) candidates.push_back(type);
  else
  {
    candidates.push_back(sa.type);
    if(sb.type != sa.type) candidates.push_back(sb.type);
    for(int t = 0; t < int(model.types.size()); ++t)
      if(t != sa.type && t != sb.type) candidates.push_back(t);
  }
  std::string why;
  for(int t : candidates)
  {
    const int sites = static_cast<int>(model.types[t].sites.size());
    for(int ta = 0; ta < sites; ++ta)
      for(int tb = 0; tb < sites; ++tb)
      {
        if(ta == tb) continue;
        const std::vector<int> r1 = grammar.rules_between(sa, {t, ta});
        const std::vector<int> r2 = grammar.rules_between({t, tb}, sb);
        if(r1.empty() || r2.empty()) continue;
        Part_node node;
        node.type = t;
        node.coordinates = graph.nodes[a].type == t   ? graph.nodes[a].coordinates
                           : graph.nodes[b].type == t ? graph.nodes[b].coordinates
                                                      : Eigen::VectorXd::Zero(model.types[t].space.number_of_modes());
        const int n = static_cast<int>(graph.nodes.size());
        Part_graph trial = graph;
        trial.nodes.push_back(node);
        trial.edges[edge] = oriented_edge(model, r1.front(), a, sa, n);
        trial.edges.push_back(oriented_edge(model, r2.front(), n, {t, tb}, b));
        try {
          validate_part_graph(model, trial); // e.g. a tile inserted into a grid: its seams do not meet
        } catch(const Input_error& e) {
          if(why.empty()) why = e.what();
          continue;
        }
        graph = std::move(trial);
        return n;
      }
  }
  if(!why.empty())
    throw Input_error(part_graph_source, "edge " + std::to_string(edge),
                      "no inserted segment gives a valid graph: " + why);
  throw Input_error(part_graph_source, "edge " + std::to_string(edge),
                    "no part type docks to both " + site_text(model, sa) + " and " + site_text(model, sb) +
                      (type >= 0 ? " among type " + quoted(model.types[type].name) : std::string()));
}

std::vector<int> remove_nodes(Part_graph& graph, const std::vector<int>& nodes)
{
  std::vector<int> map(graph.nodes.size(), 0);
  for(int n : nodes)
  {
    check_node(graph, n, "node");
    map[n] = -1;
  }
  Part_graph result;
  for(std::size_t i = 0; i < graph.nodes.size(); ++i)
    if(map[i] >= 0)
    {
      map[i] = static_cast<int>(result.nodes.size());
      result.nodes.push_back(graph.nodes[i]);
    }
  for(Part_edge e : graph.edges)
    if(map[e.first] >= 0 && map[e.second] >= 0)
    {
      e.first = map[e.first];
      e.second = map[e.second];
      result.edges.push_back(e);
    }
  graph = std::move(result);
  return map;
}

std::vector<int> remove_segment(const Morphable_part_model& model, Part_graph& graph, int node)
{
  check_node(graph, node, "node");
  const std::vector<int> incident = incident_dockings(adjacency_graph(graph), node);
  if(incident.size() != 2)
    throw Input_error(part_graph_source, node_element(model, graph, node),
                      "has " + std::to_string(incident.size()) +
                        " dockings; only a segment with two can be removed (remove the branch instead)");
  const Part_edge& e1 = graph.edges[incident[0]];
  const Part_edge& e2 = graph.edges[incident[1]];
  const int p = e1.first == node ? e1.second : e1.first;
  const int q = e2.first == node ? e2.second : e2.first;
  if(p == q)
    throw Input_error(part_graph_source, node_element(model, graph, node),
                      "both its dockings lead to node " + std::to_string(p));
  const Site_ref sp = site_on_edge(model, e1, p), sq = site_on_edge(model, e2, q);
  const std::vector<int> rules = model.grammar().rules_between(sp, sq);
  if(rules.empty())
    throw Input_error(part_graph_source, node_element(model, graph, node),
                      "its neighbours cannot be reconnected: no rule docks " + site_text(model, sp) + " to " +
                        site_text(model, sq) + " (remove the branch instead)");
  graph.edges.push_back(oriented_edge(model, rules.front(), p, sp, q));
  return remove_nodes(graph, {node});
}

std::vector<int> branch_nodes(const Part_graph& graph, int node, int root)
{
  check_node(graph, node, "node");
  check_node(graph, root, "root");
  if(node == root) throw Input_error(part_graph_source, "node " + std::to_string(node), "is the root: its branch is the whole graph");
  const Part_adjacency_graph g = adjacency_graph(graph);
  std::vector<boost::default_color_type> colour(graph.nodes.size(), boost::white_color);
  colour[node] = boost::black_color; // `node` blocks the way
  boost::breadth_first_visit(
    g, root, boost::color_map(boost::make_iterator_property_map(colour.begin(), boost::get(boost::vertex_index, g))));
  std::vector<int> branch;
  for(std::size_t i = 0; i < graph.nodes.size(); ++i)
    if(colour[i] == boost::white_color || int(i) == node) branch.push_back(int(i));
  return branch;
}

std::vector<int> remove_branch(const Morphable_part_model&, Part_graph& graph, int node, int root)
{
  return remove_nodes(graph, branch_nodes(graph, node, root));
}

int duplicate_branch(const Morphable_part_model& model, Part_graph& graph, int node, int root, int target,
                     int target_site)
{
  check_node(graph, target, "target");
  const std::vector<int> branch = branch_nodes(graph, node, root);
  std::vector<int> copy_of(graph.nodes.size(), -1);
  for(int v : branch) copy_of[v] = 0;
  const std::vector<int> attaching = hanging_dockings(graph, node, branch);
  if(attaching.size() != 1)
    throw Input_error(part_graph_source, node_element(model, graph, node),
                      "its branch hangs by " + std::to_string(attaching.size()) + " dockings; a duplicated branch needs one");
  const Site_ref hanging = site_on_edge(model, graph.edges[attaching[0]], node);
  std::vector<int> sites = free_sites(model, graph, target);
  if(target_site >= 0)
  {
    if(std::find(sites.begin(), sites.end(), target_site) == sites.end())
      throw Input_error(part_graph_source, node_element(model, graph, target),
                        "site " + std::to_string(target_site) + " is not a free site of it");
    sites = {target_site};
  }
  const Shape_grammar& grammar = model.grammar();
  for(int s : sites)
  {
    const std::vector<int> rules = grammar.rules_between({graph.nodes[target].type, s}, hanging);
    if(rules.empty()) continue;
    const std::size_t first_copy = graph.nodes.size();
    for(int v : branch)
    {
      copy_of[v] = static_cast<int>(graph.nodes.size());
      graph.nodes.push_back(graph.nodes[v]);
    }
    const std::size_t edges = graph.edges.size();
    for(std::size_t k = 0; k < edges; ++k)
    {
      const Part_edge e = graph.edges[k];
      if(copy_of[e.first] >= int(first_copy) && copy_of[e.second] >= int(first_copy) &&
         std::binary_search(branch.begin(), branch.end(), e.first) &&
         std::binary_search(branch.begin(), branch.end(), e.second))
      {
        Part_edge c = e;
        c.first = copy_of[e.first];
        c.second = copy_of[e.second];
        graph.edges.push_back(c);
      }
    }
    graph.edges.push_back(oriented_edge(model, rules.front(), target, {graph.nodes[target].type, s}, copy_of[node]));
    return copy_of[node];
  }
  throw Input_error(part_graph_source, node_element(model, graph, target),
                    "no free site of it docks to " + site_text(model, hanging));
}

int close_cycle(const Morphable_part_model& model, Part_graph& graph, int a, int b)
{
  check_node(graph, a, "node");
  check_node(graph, b, "node");
  if(a == b) throw Input_error(part_graph_source, node_element(model, graph, a), "cannot dock to itself");
  const Shape_grammar& grammar = model.grammar();
  std::vector<Part_edge> candidates;
  for(int sa : free_sites(model, graph, a))
    for(int sb : free_sites(model, graph, b))
    {
      const Site_ref ra{graph.nodes[a].type, sa}, rb{graph.nodes[b].type, sb};
      for(int r : grammar.rules_between(ra, rb))
      {
        Part_graph trial = graph;
        trial.edges.push_back(oriented_edge(model, r, a, ra, b));
        try {
          validate_part_graph(model, trial); // the seams must close consistently
        } catch(const Input_error&) {
          continue;
        }
        candidates.push_back(trial.edges.back());
      }
    }
  if(candidates.empty())
    throw Input_error(part_graph_source, node_element(model, graph, a),
                      "no free site of it docks to a free site of " + node_element(model, graph, b));
  std::size_t best = 0;
  if(candidates.size() > 1)
  {
    // The docking whose sites are nearest in the rigid placement of the
    // graph as it is (when it is one valid assembly already).
    try {
      Assembly_options o;
      o.solve = false;
      const Assembly placed = assemble(model, graph, o);
      double nearest = std::numeric_limits<double>::infinity();
      for(std::size_t c = 0; c < candidates.size(); ++c)
      {
        const Docking_rule& rule = model.rules[candidates[c].rule];
        const auto centroid = [&](int node, const Site_ref& site) {
          Eigen::RowVector3d p = Eigen::RowVector3d::Zero();
          const std::vector<int>& v = model.types[site.type].sites[site.site].vertices;
          for(int l : v) p += placed.initial_positions.row(placed.vertex(node, l));
          return Eigen::RowVector3d(p / double(std::max<std::size_t>(1, v.size())));
        };
        double d = 0.;
        if(!rule.seam.empty())
        {
          for(const auto& [l0, l1] : rule.seam)
            d += (placed.initial_positions.row(placed.vertex(candidates[c].first, l0)) -
                  placed.initial_positions.row(placed.vertex(candidates[c].second, l1))).norm();
          d /= double(rule.seam.size());
        }
        else
          d = (centroid(candidates[c].first, rule.first) - centroid(candidates[c].second, rule.second)).norm();
        if(d < nearest)
        {
          nearest = d;
          best = c;
        }
      }
    } catch(const Input_error&) {
      // in pieces: the first candidate
    }
  }
  graph.edges.push_back(candidates[best]);
  return static_cast<int>(graph.edges.size()) - 1;
}

int uniform_index(std::mt19937& rng, int n)
{
  if(n <= 1) return 0;
  const std::uint64_t range = std::uint64_t(std::mt19937::max()) + 1;
  const std::uint64_t limit = range - range % std::uint64_t(n);
  std::uint64_t r;
  do r = rng(); while(r >= limit);
  return static_cast<int>(r % std::uint64_t(n));
}

Part_graph random_part_graph(const Morphable_part_model& model, const Part_graph& start, std::mt19937& rng,
                             const Random_edit_options& options, std::vector<std::string>* log)
{
  Part_graph graph = start;
  const int lo = std::max(0, options.min_edits), hi = std::max(lo, options.max_edits);
  const int edits = lo + uniform_index(rng, hi - lo + 1);
  std::vector<int> kinds;
  if(options.insert) kinds.push_back(0);
  if(options.remove_segment) kinds.push_back(1);
  if(options.remove_branch) kinds.push_back(2);
  if(options.duplicate_branch) kinds.push_back(3);
  if(kinds.empty()) return graph;
  int done = 0;
  for(int attempt = 0; done < edits && attempt < 100 * (edits + 1); ++attempt)
  {
    Part_graph next = graph;
    const int n = static_cast<int>(next.nodes.size());
    const int root = root_node(next);
    std::string what;
    try {
      switch(kinds[uniform_index(rng, int(kinds.size()))])
      {
      case 0: {
        if(next.edges.empty()) continue;
        const int e = uniform_index(rng, int(next.edges.size()));
        const int a = next.edges[e].first, b = next.edges[e].second;
        const int added = insert_segment(model, next, e);
        what = "insert a " + model.types[next.nodes[added].type].name + " between nodes " + std::to_string(a) +
               " and " + std::to_string(b);
        break;
      }
      case 1: {
        const int v = uniform_index(rng, n);
        if(v == root || n - 1 < options.min_nodes) continue;
        what = "remove segment " + std::to_string(v) + " (" + model.types[next.nodes[v].type].name + ")";
        remove_segment(model, next, v);
        break;
      }
      case 2: {
        const int v = uniform_index(rng, n);
        if(v == root) continue;
        if(n - int(branch_nodes(next, v, root).size()) < options.min_nodes) continue;
        what = "remove the branch at " + std::to_string(v) + " (" + model.types[next.nodes[v].type].name + ")";
        remove_branch(model, next, v, root);
        break;
      }
      default: {
        const int v = uniform_index(rng, n);
        if(v == root) continue;
        const std::vector<int> branch = branch_nodes(next, v, root);
        const std::vector<int> attaching = hanging_dockings(next, v, branch);
        if(attaching.size() != 1) continue;
        const Site_ref hanging = site_on_edge(model, next.edges[attaching[0]], v);
        std::vector<Docking_option> where = free_dockings(model, next, hanging);
        if(where.empty()) continue;
        const Docking_option& o = where[uniform_index(rng, int(where.size()))];
        duplicate_branch(model, next, v, root, o.node, o.site);
        what = "duplicate the branch at " + std::to_string(v) + " (" + std::to_string(branch.size()) +
               " parts) onto node " + std::to_string(o.node) + " site " + std::to_string(o.site);
        break;
      }
      }
      validate_part_graph(model, next);
    } catch(const Input_error&) {
      continue; // not applicable here: draw another edit
    }
    graph = std::move(next);
    ++done;
    if(log) log->push_back(what);
  }
  return graph;
}

void scale_coordinates(Part_graph& graph, double factor)
{
  for(Part_node& node : graph.nodes) node.coordinates *= factor;
  for(Part_edge& edge : graph.edges) edge.coordinates *= factor;
}

} // namespace MPM
} // namespace CGAL
