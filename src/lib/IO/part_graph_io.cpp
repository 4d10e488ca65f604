// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/internal/Json_reader.h>
#include <CGAL/MPM/internal/Message_text.h>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace CGAL {
namespace MPM {

using internal::quoted;
using internal::site_text;

namespace {

using json = nlohmann::json;
using internal::Json_reader;

const char* const part_graph_format = "cgal-mpm-part-graph";
constexpr int part_graph_version = 1;

std::string node_text(const Morphable_part_model& model, const Part_graph& graph, int n)
{
  return "node " + std::to_string(n) + " (" + model.types[graph.nodes[n].type].name + ")";
}

} // namespace

std::map<Site_ref, int> observed_site_degrees(const Morphable_part_model& model)
{
  std::map<Site_ref, int> degrees;
  for(std::size_t t = 0; t < model.types.size(); ++t)
    for(std::size_t s = 0; s < model.types[t].sites.size(); ++s) degrees[{int(t), int(s)}] = 1;
  for(const Training_example& ex : model.examples)
  {
    std::map<std::pair<int, Site_ref>, int> used;
    for(const Part_edge& e : ex.graph.edges)
    {
      if(e.rule < 0 || e.rule >= int(model.rules.size())) continue;
      ++used[{e.first, model.rules[e.rule].first}];
      ++used[{e.second, model.rules[e.rule].second}];
    }
    for(const auto& [key, count] : used) degrees[key.second] = std::max(degrees[key.second], count);
  }
  return degrees;
}

namespace {

// The first coordinate more than 1000 standard deviations of its mode from
// the mean (-1 if none): a node at 1e300 overflowed the embedding, and the
// error named neither the file nor the node.
int absurd_coordinate(const Eigen::VectorXd& coordinates, const Shape_space& space)
{
  for(Eigen::Index k = 0; k < coordinates.size() && k < space.sigmas.size(); ++k)
    if(std::abs(coordinates[k]) > 1000. * space.sigmas[k]) return int(k);
  return -1;
}

// Each node has a type of the model and finite, plausible coordinates for
// its type's modes.
void validate_nodes(const Morphable_part_model& model, const Part_graph& graph, const std::string& source)
{
  for(std::size_t i = 0; i < graph.nodes.size(); ++i)
  {
    const Part_node& node = graph.nodes[i];
    const std::string element = "node " + std::to_string(i);
    if(node.type < 0 || node.type >= int(model.types.size()))
      throw Input_error(source, element, "part type " + std::to_string(node.type) + " does not exist (the model has " +
                                           std::to_string(model.types.size()) + " types)");
    const std::string typed = element + " (" + model.types[node.type].name + ")";
    const int modes = model.types[node.type].space.number_of_modes();
    if(node.coordinates.size() != modes)
      throw Input_error(source, typed,
                        "has " + std::to_string(node.coordinates.size()) + " shape coordinates, its type has " +
                          std::to_string(modes) + " modes");
    if(!node.coordinates.allFinite()) throw Input_error(source, typed, "has non-finite shape coordinates");
    const int absurd = absurd_coordinate(node.coordinates, model.types[node.type].space);
    if(absurd >= 0)
      throw Input_error(source, typed,
                        "shape coordinate " + std::to_string(absurd) +
                          " is more than 1000 standard deviations of its mode from the mean: no shape of its type");
  }
}

// Edge `k` joins two existing, distinct nodes by a rule of the grammar that
// docks their types, with finite, plausible pair coordinates or none.
void validate_edge(const Morphable_part_model& model, const Part_graph& graph, std::size_t k,
                   const std::string& source)
{
  const int n = static_cast<int>(graph.nodes.size());
  const Part_edge& e = graph.edges[k];
  const std::string element = "edge " + std::to_string(k);
  for(int end : {e.first, e.second})
    if(end < 0 || end >= n)
      throw Input_error(source, element,
                        "node " + std::to_string(end) + " does not exist (the graph has " + std::to_string(n) +
                          " nodes)");
  if(e.first == e.second)
    throw Input_error(source, element,
                      "docks " + node_text(model, graph, e.first) +
                        " to itself (a part docks to other instances, even of its own type)");
  if(e.rule < 0 || e.rule >= int(model.rules.size()))
    throw Input_error(source, element,
                      "rule " + std::to_string(e.rule) + " does not exist (the model has " +
                        std::to_string(model.rules.size()) + " rules)");
  const Docking_rule& rule = model.rules[e.rule];
  if(graph.nodes[e.first].type != rule.first.type || graph.nodes[e.second].type != rule.second.type)
    throw Input_error(source, element,
                      "is not a docking of the grammar: rule " + std::to_string(e.rule) + " docks " +
                        site_text(model, rule.first) + " to " + site_text(model, rule.second) + ", not " +
                        node_text(model, graph, e.first) + " to " + node_text(model, graph, e.second));
  if(e.coordinates.size() != 0 && (e.coordinates.size() != rule.space.number_of_modes() || !e.coordinates.allFinite()))
    throw Input_error(source, element,
                      "needs " + std::to_string(rule.space.number_of_modes()) +
                        " finite pair coordinates (or none: the pair's mean)");
  const int absurd = absurd_coordinate(e.coordinates, rule.space);
  if(absurd >= 0)
    throw Input_error(source, element,
                      "pair coordinate " + std::to_string(absurd) +
                        " is more than 1000 standard deviations of its mode: no pair geometry of its rule");
}

// Each edge is valid and no docking site of a node carries more dockings
// than the training examples show at that site.
void validate_edges(const Morphable_part_model& model, const Part_graph& graph, const std::string& source)
{
  const std::map<Site_ref, int> capacity = observed_site_degrees(model);
  std::map<std::pair<int, int>, std::vector<int>> edges_at_site; // (node, site) -> edges
  for(std::size_t k = 0; k < graph.edges.size(); ++k)
  {
    validate_edge(model, graph, k, source);
    const Part_edge& e = graph.edges[k];
    const Docking_rule& rule = model.rules[e.rule];
    for(const auto& [node, site] : {std::make_pair(e.first, rule.first), std::make_pair(e.second, rule.second)})
    {
      std::vector<int>& at = edges_at_site[{node, site.site}];
      at.push_back(static_cast<int>(k));
      const int limit = capacity.count(site) ? capacity.at(site) : 1;
      if(int(at.size()) > limit)
        throw Input_error(source, "edge " + std::to_string(k),
                          "uses " + site_text(model, site) + " of " + node_text(model, graph, node) +
                            ", already used by edge " + std::to_string(at.front()) +
                            (limit == 1 ? std::string(" (a docking site carries one docking)")
                                        : " (at most " + std::to_string(limit) + " were observed)"));
    }
  }
}

// Seams close consistently: the shared-vertex classes never identify two
// local vertices of one node (a cycle of boundary dockings whose seams do
// not meet, as a tile inserted into a grid).
void validate_seams(const Morphable_part_model& model, const Part_graph& graph, const std::string& source)
{
  const int n = static_cast<int>(graph.nodes.size());
  std::vector<int> offset(n + 1, 0);
  for(int i = 0; i < n; ++i) offset[i + 1] = offset[i] + model.types[graph.nodes[i].type].number_of_vertices;
  std::vector<int> parent(offset[n]);
  for(int v = 0; v < offset[n]; ++v) parent[v] = v;
  std::vector<std::map<int, int>> members(offset[n]); // class root -> node -> local
  for(int i = 0; i < n; ++i)
    for(int l = 0; l < offset[i + 1] - offset[i]; ++l) members[offset[i] + l][i] = l;
  const auto find = [&](int v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for(std::size_t k = 0; k < graph.edges.size(); ++k)
  {
    const Part_edge& e = graph.edges[k];
    for(const auto& [l0, l1] : model.rules[e.rule].seam)
    {
      int a = find(offset[e.first] + l0), b = find(offset[e.second] + l1);
      if(a == b) continue;
      if(members[a].size() < members[b].size()) std::swap(a, b);
      for(const auto& [node, local] : members[b])
      {
        const auto it = members[a].find(node);
        if(it != members[a].end() && it->second != local)
          throw Input_error(source, "edge " + std::to_string(k),
                            "its seam identifies local vertices " + std::to_string(it->second) + " and " +
                              std::to_string(local) + " of " + node_text(model, graph, node) +
                              " (a cycle of dockings whose seams do not meet)");
        members[a][node] = local;
      }
      members[b].clear();
      parent[b] = a;
    }
  }
}

// Every node is reachable from node 0 along the edges.
void validate_connected(const Morphable_part_model& model, const Part_graph& graph, const std::string& source)
{
  std::vector<int> component(graph.nodes.size());
  boost::connected_components(adjacency_graph(graph), component.data());
  for(std::size_t i = 0; i < component.size(); ++i)
    if(component[i] != component[0])
      throw Input_error(source, node_text(model, graph, int(i)),
                        "is not connected to node 0 (a part graph is one assembly)");
}

} // namespace

void validate_part_graph(const Morphable_part_model& model, const Part_graph& graph, const std::string& source)
{
  if(graph.nodes.empty()) throw Input_error(source, "", "the part graph has no node");
  validate_nodes(model, graph, source);
  validate_edges(model, graph, source);
  validate_seams(model, graph, source);
  validate_connected(model, graph, source);
}

Part_graph part_graph_of_example(const Morphable_part_model& model, int example)
{
  if(example < 0 || example >= int(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  return model.examples[example].graph;
}

namespace {

class Part_graph_parser
{
public:
  Part_graph_parser(const Morphable_part_model& model, const std::string& source) : model_(model), reader_(source) {}

  Part_graph parse(const std::string& text) const
  {
    const json root = reader_.parse_document(text, part_graph_format, part_graph_version, "part graph");
    reader_.check_keys(root, "", {"format", "version", "nodes", "edges"});
    if(!root.contains("nodes")) reader_.fail("", "lacks \"nodes\"");
    Part_graph graph;
    const json& nodes = reader_.array_of(root["nodes"], "nodes");
    if(nodes.empty()) reader_.fail("nodes", "the part graph has no node");
    for(std::size_t i = 0; i < nodes.size(); ++i) graph.nodes.push_back(parse_node(nodes[i], i));
    if(root.contains("edges"))
    {
      const json& edges = reader_.array_of(root["edges"], "edges");
      for(std::size_t i = 0; i < edges.size(); ++i) graph.edges.push_back(parse_edge(edges[i], i, graph));
    }
    validate_part_graph(model_, graph, reader_.source());
    return graph;
  }

private:
  Eigen::VectorXd coordinates(const json& j, const std::string& element, int expected) const
  {
    const json& a = reader_.array_of(j, element);
    if(int(a.size()) != expected)
      reader_.fail(element, "has " + std::to_string(a.size()) + " values, expected " + std::to_string(expected));
    Eigen::VectorXd c(expected);
    for(int k = 0; k < expected; ++k)
    {
      c[k] = reader_.number_of(a[k], element + "[" + std::to_string(k) + "]");
      if(!std::isfinite(c[k])) reader_.fail(element + "[" + std::to_string(k) + "]", "must be finite");
    }
    return c;
  }

  Part_node parse_node(const json& j, std::size_t i) const
  {
    const std::string element = "node " + std::to_string(i);
    if(!j.is_object()) reader_.fail(element, "must be an object with \"type\"");
    reader_.check_keys(j, element, {"type", "coordinates"});
    if(!j.contains("type")) reader_.fail(element, "lacks \"type\"");
    const std::string name = reader_.string_of(j["type"], element + ".type");
    Part_node node;
    node.type = model_.find_type(name);
    if(node.type < 0)
    {
      std::string list;
      for(const Part_type& t : model_.types) list += (list.empty() ? "" : ", ") + t.name;
      reader_.fail(element, "unknown part type " + quoted(name) + " (the model's types: " + list + ")");
    }
    const int modes = model_.types[node.type].space.number_of_modes();
    node.coordinates = j.contains("coordinates") ? coordinates(j["coordinates"], element + ".coordinates", modes)
                                                 : Eigen::VectorXd::Zero(modes);
    return node;
  }

  Part_edge parse_edge(const json& j, std::size_t i, const Part_graph& graph) const
  {
    const std::string element = "edge " + std::to_string(i);
    if(!j.is_object()) reader_.fail(element, "must be an object with \"first\", \"second\" and \"rule\"");
    reader_.check_keys(j, element, {"first", "second", "rule", "first_site", "second_site", "coordinates"});
    for(const char* required : {"first", "second"})
      if(!j.contains(required)) reader_.fail(element, std::string("lacks \"") + required + "\"");
    Part_edge e;
    e.first = reader_.non_negative(j["first"], element + ".first");
    e.second = reader_.non_negative(j["second"], element + ".second");
    const int n = static_cast<int>(graph.nodes.size());
    for(int end : {e.first, e.second})
      if(end >= n)
        reader_.fail(element, "node " + std::to_string(end) + " does not exist (the graph has " +
                                std::to_string(n) + " nodes)");
    if(e.first == e.second)
      reader_.fail(element, "docks node " + std::to_string(e.first) +
                              " to itself (a part docks to other instances, even of its own type)");
    const bool sites = j.contains("first_site") || j.contains("second_site");
    if(sites && !(j.contains("first_site") && j.contains("second_site")))
      reader_.fail(element, "needs both \"first_site\" and \"second_site\"");
    if(!j.contains("rule") && !sites)
      reader_.fail(element, "needs \"rule\" or \"first_site\" and \"second_site\"");
    if(j.contains("rule"))
    {
      e.rule = reader_.non_negative(j["rule"], element + ".rule");
      if(e.rule >= int(model_.rules.size()))
        reader_.fail(element, "rule " + std::to_string(e.rule) + " does not exist (the model has " +
                                std::to_string(model_.rules.size()) + " rules)");
    }
    if(sites)
    {
      const Site_ref a{graph.nodes[e.first].type, reader_.non_negative(j["first_site"], element + ".first_site")};
      const Site_ref b{graph.nodes[e.second].type, reader_.non_negative(j["second_site"], element + ".second_site")};
      for(const Site_ref& s : {a, b})
        if(s.site >= int(model_.types[s.type].sites.size()))
          reader_.fail(element, "part type " + quoted(model_.types[s.type].name) + " has no site " +
                                  std::to_string(s.site) + " (it has " +
                                  std::to_string(model_.types[s.type].sites.size()) + ")");
      const std::vector<int> rules = model_.grammar().rules_between(a, b);
      if(rules.empty())
        reader_.fail(element, "is not a docking of the grammar: no rule docks " + site_text(model_, a) + " to " +
                                site_text(model_, b));
      if(rules.size() > 1 && !j.contains("rule"))
      {
        std::string list;
        for(int r : rules) list += (list.empty() ? "" : ", ") + std::to_string(r);
        reader_.fail(element, "is ambiguous: rules " + list + " all dock " + site_text(model_, a) + " to " +
                                site_text(model_, b) + "; name one with \"rule\"");
      }
      if(j.contains("rule"))
      {
        if(std::find(rules.begin(), rules.end(), e.rule) == rules.end())
          reader_.fail(element, "rule " + std::to_string(e.rule) + " does not dock " + site_text(model_, a) +
                                  " to " + site_text(model_, b));
      }
      else
        e.rule = rules.front();
      // The node at the rule's first site plays side 0.
      const Docking_rule& rule = model_.rules[e.rule];
      if(!(rule.first == a && rule.second == b)) std::swap(e.first, e.second);
    }
    const Docking_rule& rule = model_.rules[e.rule];
    if(graph.nodes[e.first].type != rule.first.type || graph.nodes[e.second].type != rule.second.type)
      reader_.fail(element, "is not a docking of the grammar: rule " + std::to_string(e.rule) + " docks " +
                              site_text(model_, rule.first) + " to " + site_text(model_, rule.second) + ", not node " +
                              std::to_string(e.first) + " (" + model_.types[graph.nodes[e.first].type].name +
                              ") to node " + std::to_string(e.second) + " (" +
                              model_.types[graph.nodes[e.second].type].name + ")");
    if(j.contains("coordinates"))
      e.coordinates = coordinates(j["coordinates"], element + ".coordinates",
                                  model_.rules[e.rule].space.number_of_modes());
    return e;
  }

  const Morphable_part_model& model_;
  Json_reader reader_;
};

} // namespace

Part_graph parse_part_graph(const std::string& text, const Morphable_part_model& model, const std::string& source)
{
  return Part_graph_parser(model, source).parse(text);
}

Part_graph read_part_graph(const std::string& path, const Morphable_part_model& model)
{
  return parse_part_graph(internal::read_file(path), model, path);
}

std::string part_graph_to_json(const Morphable_part_model& model, const Part_graph& graph)
{
  validate_part_graph(model, graph);
  using ordered = nlohmann::ordered_json;
  ordered root;
  root["format"] = part_graph_format;
  root["version"] = part_graph_version;
  ordered nodes = ordered::array();
  for(const Part_node& node : graph.nodes)
  {
    ordered j = {{"type", model.types[node.type].name}};
    if(node.coordinates.size() > 0)
      j["coordinates"] = std::vector<double>(node.coordinates.data(), node.coordinates.data() + node.coordinates.size());
    nodes.push_back(j);
  }
  root["nodes"] = nodes;
  ordered edges = ordered::array();
  for(const Part_edge& e : graph.edges)
  {
    const Docking_rule& rule = model.rules[e.rule];
    ordered j = {{"first", e.first}, {"second", e.second}, {"rule", e.rule},
              {"first_site", rule.first.site}, {"second_site", rule.second.site}};
    if(e.coordinates.size() > 0)
      j["coordinates"] = std::vector<double>(e.coordinates.data(), e.coordinates.data() + e.coordinates.size());
    edges.push_back(j);
  }
  root["edges"] = edges;
  return root.dump(2) + "\n";
}

void write_part_graph(const Morphable_part_model& model, const Part_graph& graph, const std::string& path)
{
  const std::string text = part_graph_to_json(model, graph);
  internal::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

} // namespace MPM
} // namespace CGAL
