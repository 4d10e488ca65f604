// Part graphs: the JSON format, validation against the grammar (each
// rejection with its own test), and the editing operations.
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include "Learned_models.h"

#include "Part_graph_lookup.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <map>

using namespace CGAL::MPM;
using json = nlohmann::json;

namespace {

using mpm_test::edge_between;
using mpm_test::node_of_type;
using mpm_test::small_hand_model;

// The error's message for a JSON text, or "" when it parses.
std::string parse_error(const json& j, const Morphable_part_model& m = small_hand_model())
{
  try {
    parse_part_graph(j.dump(), m, "g.json");
  } catch(const Input_error& e) {
    EXPECT_EQ(e.source(), "g.json");
    return e.what();
  }
  return "";
}

json training_json(const Morphable_part_model& m = small_hand_model())
{
  return json::parse(part_graph_to_json(m, part_graph_of_example(m)));
}

} // namespace

TEST(Part_graph_format, training_graphs_are_valid_and_round_trip)
{
  for(Synthetic_family f : all_synthetic_families())
  {
    const Morphable_part_model& m = mpm_test::learned(f, 3000).model;
    const Part_graph g = part_graph_of_example(m);
    EXPECT_NO_THROW(validate_part_graph(m, g)) << family_name(f);
    const Part_graph back = parse_part_graph(part_graph_to_json(m, g), m);
    ASSERT_EQ(back.nodes.size(), g.nodes.size());
    ASSERT_EQ(back.edges.size(), g.edges.size());
    for(std::size_t i = 0; i < g.nodes.size(); ++i)
    {
      EXPECT_EQ(back.nodes[i].type, g.nodes[i].type);
      EXPECT_LT((back.nodes[i].coordinates - g.nodes[i].coordinates).norm(), 1e-12);
    }
    for(std::size_t k = 0; k < g.edges.size(); ++k)
    {
      EXPECT_EQ(back.edges[k].first, g.edges[k].first);
      EXPECT_EQ(back.edges[k].second, g.edges[k].second);
      EXPECT_EQ(back.edges[k].rule, g.edges[k].rule);
    }
  }
}

TEST(Part_graph_format, defaults_and_edges_by_sites)
{
  const Morphable_part_model& m = small_hand_model();
  json j = training_json();
  for(json& node : j["nodes"]) node.erase("coordinates");
  // Name the dockings by sites only, with first and second given reversed.
  for(json& e : j["edges"])
  {
    e.erase("rule");
    std::swap(e["first"], e["second"]);
    std::swap(e["first_site"], e["second_site"]);
  }
  const Part_graph g = parse_part_graph(j.dump(), m);
  const Part_graph t = part_graph_of_example(m);
  for(const Part_node& node : g.nodes) EXPECT_EQ(node.coordinates.norm(), 0.);
  for(std::size_t k = 0; k < g.edges.size(); ++k)
  {
    EXPECT_EQ(g.edges[k].rule, t.edges[k].rule);
    EXPECT_EQ(g.edges[k].first, t.edges[k].first); // oriented back to the rule's sides
  }
}

TEST(Part_graph_validation, rejects_an_empty_graph)
{
  EXPECT_NE(parse_error({{"format", "cgal-mpm-part-graph"}, {"version", 1}, {"nodes", json::array()}})
              .find("no node"), std::string::npos);
  EXPECT_THROW(validate_part_graph(small_hand_model(), Part_graph()), Input_error);
}

TEST(Part_graph_validation, rejects_an_unknown_part_type)
{
  json j = training_json();
  j["nodes"][2]["type"] = "wing";
  const std::string e = parse_error(j);
  EXPECT_NE(e.find("node 2"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown part type \"wing\""), std::string::npos) << e;
}

TEST(Part_graph_validation, rejects_coordinates_of_the_wrong_length_or_not_finite)
{
  json j = training_json();
  j["nodes"][1]["coordinates"].push_back(0.5);
  EXPECT_NE(parse_error(j).find("node 1.coordinates"), std::string::npos) << parse_error(j);
  Part_graph g = part_graph_of_example(small_hand_model());
  g.nodes[1].coordinates[0] = std::nan("");
  try {
    validate_part_graph(small_hand_model(), g);
    FAIL();
  } catch(const Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("node 1"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos);
  }
  // 1e300 overflowed the embedding, and the error named neither file nor node.
  j = training_json();
  j["nodes"][1]["coordinates"][0] = 1e300;
  EXPECT_NE(parse_error(j).find("node 1 (proximal): shape coordinate 0 is more than 1000 standard deviations"),
            std::string::npos)
    << parse_error(j);
}

TEST(Part_graph_validation, rejects_a_node_index_out_of_range)
{
  json j = training_json();
  j["edges"][3]["second"] = 99;
  const std::string e = parse_error(j);
  EXPECT_NE(e.find("edge 3"), std::string::npos) << e;
  EXPECT_NE(e.find("node 99 does not exist"), std::string::npos) << e;
}

TEST(Part_graph_validation, rejects_a_node_docked_to_itself)
{
  json j = training_json();
  j["edges"][0]["second"] = j["edges"][0]["first"];
  const std::string e = parse_error(j);
  EXPECT_NE(e.find("edge 0"), std::string::npos) << e;
  EXPECT_NE(e.find("to itself"), std::string::npos) << e;
}

TEST(Part_graph_validation, rejects_a_docking_that_is_not_a_rule)
{
  const Morphable_part_model& m = small_hand_model();
  const Part_graph t = part_graph_of_example(m);
  // A palm-proximal rule used between a middle and a distal.
  json j = training_json();
  const int middle = node_of_type(m, t, "middle"), distal = node_of_type(m, t, "distal");
  const int k = edge_between(t, middle, distal);
  ASSERT_GE(k, 0);
  j["edges"][k]["rule"] = t.edges[edge_between(t, node_of_type(m, t, "palm"), node_of_type(m, t, "proximal"))].rule;
  j["edges"][k].erase("first_site");
  j["edges"][k].erase("second_site");
  std::string e = parse_error(j);
  EXPECT_NE(e.find("edge " + std::to_string(k)), std::string::npos) << e;
  EXPECT_NE(e.find("is not a docking of the grammar"), std::string::npos) << e;
  // By sites: a distal docked to a palm.
  j = training_json();
  j["edges"][k] = {{"first", node_of_type(m, t, "palm")}, {"second", distal}, {"first_site", 0}, {"second_site", 0}};
  e = parse_error(j);
  EXPECT_NE(e.find("no rule docks"), std::string::npos) << e;
  // A rule index out of range.
  j = training_json();
  j["edges"][k]["rule"] = 1000;
  EXPECT_NE(parse_error(j).find("rule 1000 does not exist"), std::string::npos);
}

TEST(Part_graph_validation, rejects_a_docking_site_used_twice)
{
  const Morphable_part_model& m = small_hand_model();
  Part_graph g = part_graph_of_example(m);
  // A second distal docked at the same site of a middle.
  const int middle = node_of_type(m, g, "middle"), distal = node_of_type(m, g, "distal");
  Part_node extra = g.nodes[distal];
  g.nodes.push_back(extra);
  Part_edge e = g.edges[edge_between(g, middle, distal)];
  (e.first == middle ? e.second : e.first) = int(g.nodes.size()) - 1;
  g.edges.push_back(e);
  try {
    validate_part_graph(m, g, "g");
    FAIL();
  } catch(const Input_error& x) {
    const std::string w = x.what();
    EXPECT_NE(w.find("edge " + std::to_string(g.edges.size() - 1)), std::string::npos) << w;
    EXPECT_NE(w.find("already used by edge"), std::string::npos) << w;
    EXPECT_NE(w.find("node " + std::to_string(middle)), std::string::npos) << w;
  }
}

TEST(Part_graph_validation, rejects_a_graph_in_pieces_and_malformed_json)
{
  json j = training_json();
  j["edges"].erase(0);
  EXPECT_NE(parse_error(j).find("not connected"), std::string::npos) << parse_error(j);
  j = training_json();
  j["edges"][0]["rules"] = 1;
  EXPECT_NE(parse_error(j).find("unknown key \"rules\""), std::string::npos);
  j = training_json();
  j["format"] = "cgal-mpm-handles";
  EXPECT_NE(parse_error(j).find("format"), std::string::npos);
  EXPECT_THROW(parse_part_graph("{\"nodes\": [", small_hand_model(), "g"), Input_error);
  j = training_json();
  j["edges"][0].erase("rule");
  j["edges"][0].erase("second_site");
  EXPECT_NE(parse_error(j).find("both \"first_site\" and \"second_site\""), std::string::npos);
}

TEST(Part_graph_editing, repetition_rules_lengthen_chains)
{
  Morphable_part_model m = small_hand_model();
  const std::size_t learned = m.rules.size();
  const std::vector<int> added = add_repetition_rules(m);
  // proximal and middle have two sites each; distal and palm do not qualify.
  ASSERT_EQ(added.size(), 2u);
  EXPECT_TRUE(add_repetition_rules(m).empty());
  for(int r : added)
  {
    const Docking_rule& rule = m.rules[r];
    EXPECT_EQ(rule.first.type, rule.second.type);
    EXPECT_EQ(rule.seam.size(), m.types[rule.first.type].sites[0].vertices.size());
    EXPECT_EQ(rule.space.number_of_modes(), 0);
  }
  EXPECT_EQ(m.rules.size(), learned + 2);

  Part_graph g = part_graph_of_example(m);
  const int middle = node_of_type(m, g, "middle"), distal = node_of_type(m, g, "distal");
  const int k = edge_between(g, middle, distal);
  // Without the derived rules nothing docks between a middle and a distal.
  Part_graph h = g;
  EXPECT_THROW(insert_segment(small_hand_model(), h, k), Input_error);
  const int n = insert_segment(m, g, k);
  EXPECT_EQ(m.types[g.nodes[n].type].name, "middle");
  EXPECT_EQ(g.nodes[n].coordinates, g.nodes[middle].coordinates);
  EXPECT_NO_THROW(validate_part_graph(m, g));
  EXPECT_GE(edge_between(g, middle, n), 0);
  EXPECT_GE(edge_between(g, n, distal), 0);
  EXPECT_LT(edge_between(g, middle, distal), 0);
  // And the segment comes out again.
  remove_segment(m, g, n);
  EXPECT_NO_THROW(validate_part_graph(m, g));
  EXPECT_EQ(g.nodes.size(), part_graph_of_example(m).nodes.size());
  // A middle between a proximal and a distal cannot be removed: no rule.
  EXPECT_THROW(remove_segment(m, g, middle), Input_error);
}

TEST(Part_graph_editing, remove_and_duplicate_branches_and_close_cycles)
{
  const Morphable_part_model& m = mpm_test::learned(Synthetic_family::spider, 3000).model;
  Part_graph g = part_graph_of_example(m);
  const int root = root_node(g);
  EXPECT_EQ(m.types[g.nodes[root].type].name, "body");
  const std::size_t nodes = g.nodes.size();
  const int coxa = node_of_type(m, g, "coxa");
  EXPECT_EQ(branch_nodes(g, coxa, root).size(), 4u);
  // No free site: a ninth leg does not fit.
  EXPECT_THROW(duplicate_branch(m, g, coxa, root, root), Input_error);
  std::vector<int> map = remove_branch(m, g, coxa, root);
  EXPECT_EQ(g.nodes.size(), nodes - 4);
  EXPECT_NO_THROW(validate_part_graph(m, g));
  const int body = map[root];
  EXPECT_EQ(free_sites(m, g, body).size(), 1u);
  const int other = node_of_type(m, g, "coxa", 2);
  const int copy = duplicate_branch(m, g, other, body, body);
  EXPECT_EQ(g.nodes.size(), nodes);
  EXPECT_EQ(g.nodes[copy].type, g.nodes[other].type);
  EXPECT_NO_THROW(validate_part_graph(m, g));
  EXPECT_TRUE(free_sites(m, g, body).empty());

  // Hexa grid: drop one docking of a cycle and close it again.
  const Morphable_part_model& hexa = mpm_test::learned(Synthetic_family::hexa_grid, 3000).model;
  Part_graph h = part_graph_of_example(hexa);
  const Part_edge dropped = h.edges.back();
  h.edges.pop_back();
  const int e = close_cycle(hexa, h, dropped.first, dropped.second);
  EXPECT_EQ(h.edges[e].rule, dropped.rule);
  EXPECT_NO_THROW(validate_part_graph(hexa, h));
  EXPECT_THROW(close_cycle(hexa, h, 0, 0), Input_error);
}

TEST(Part_graph_editing, random_graphs_are_valid_and_reproducible)
{
  for(Synthetic_family f : {Synthetic_family::hand, Synthetic_family::spider, Synthetic_family::hexa_grid})
  {
    Morphable_part_model m = mpm_test::learned(f, 3000).model;
    add_repetition_rules(m);
    const Part_graph start = part_graph_of_example(m);
    std::mt19937 a(7), b(7);
    for(int k = 0; k < 10; ++k)
    {
      std::vector<std::string> la, lb;
      const Part_graph ga = random_part_graph(m, start, a, Random_edit_options(), &la);
      const Part_graph gb = random_part_graph(m, start, b, Random_edit_options(), &lb);
      EXPECT_NO_THROW(validate_part_graph(m, ga)) << family_name(f);
      EXPECT_FALSE(la.empty());
      EXPECT_EQ(la, lb);
      EXPECT_EQ(part_graph_to_json(m, ga), part_graph_to_json(m, gb));
    }
  }
}

TEST(Part_graph_editing, uniform_index_is_uniform_enough)
{
  std::mt19937 rng(3);
  std::vector<int> count(6, 0);
  for(int k = 0; k < 60000; ++k) ++count[uniform_index(rng, 6)];
  for(int c : count) EXPECT_NEAR(c, 10000, 400);
}

TEST(Part_graph_validation, rejects_a_cycle_whose_seams_do_not_meet)
{
  // A tile inserted into a docking of the grid: its corners would have to be
  // the corners its two neighbours already share with their other neighbours.
  const Morphable_part_model& m = mpm_test::learned(Synthetic_family::hexa_grid, 3000).model;
  Part_graph g = part_graph_of_example(m);
  std::vector<int> degree(g.nodes.size(), 0);
  for(const Part_edge& e : g.edges) ++degree[e.first], ++degree[e.second];
  int inner = -1;
  for(std::size_t k = 0; k < g.edges.size() && inner < 0; ++k)
    if(degree[g.edges[k].first] == 6 && degree[g.edges[k].second] >= 4) inner = int(k);
  ASSERT_GE(inner, 0);
  try {
    insert_segment(m, g, inner);
    FAIL() << "inserted a tile into the grid";
  } catch(const Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("seams do not meet"), std::string::npos) << e.what();
  }
}

// Symmetrizing an assembly puts every instance at its type's mean; a
// caricature doubles each instance's distance from it.
TEST(Part_graph_editing, scaled_coordinates_move_instances_about_their_mean)
{
  const Part_graph example = part_graph_of_example(small_hand_model(), 0);
  double largest = 0.;
  for(const Part_node& node : example.nodes) largest = std::max(largest, node.coordinates.norm());
  ASSERT_GT(largest, 0.) << "the hand's instances are not all at their type's mean";

  Part_graph symmetric = example;
  scale_coordinates(symmetric, 0.);
  for(const Part_node& node : symmetric.nodes) EXPECT_EQ(node.coordinates.norm(), 0.);
  for(const Part_edge& edge : symmetric.edges) EXPECT_EQ(edge.coordinates.norm(), 0.);

  Part_graph caricature = example;
  scale_coordinates(caricature, 2.);
  for(std::size_t n = 0; n < example.nodes.size(); ++n)
    EXPECT_LT((caricature.nodes[n].coordinates - 2. * example.nodes[n].coordinates).norm(), 1e-12);
  for(std::size_t e = 0; e < example.edges.size(); ++e)
    EXPECT_LT((caricature.edges[e].coordinates - 2. * example.edges[e].coordinates).norm(), 1e-12);
  EXPECT_EQ(caricature.nodes.size(), example.nodes.size());
  EXPECT_EQ(caricature.edges.size(), example.edges.size());
}
