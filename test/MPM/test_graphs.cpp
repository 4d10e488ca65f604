// The grammar a model keeps, and part graphs as Boost.Graph graphs.
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Model/Shape_grammar.h>

#include "Learned_models.h"

#include <boost/graph/connected_components.hpp>

#include <gtest/gtest.h>

#include <stdexcept>

using namespace CGAL::MPM;

namespace {

using mpm_test::small_hand_model;

} // namespace

TEST(Model_grammar, built_by_learning_and_reading_and_kept_by_copies)
{
  const Morphable_part_model& model = small_hand_model();
  const Shape_grammar& grammar = model.grammar();
  EXPECT_EQ(grammar.number_of_rules(), model.rules.size());
  EXPECT_TRUE(grammar.describes(model));
  const Morphable_part_model copy = model;
  EXPECT_EQ(&copy.grammar(), &grammar);
  const Morphable_part_model read = deserialize_model(serialize_model(model), "hand");
  EXPECT_EQ(read.grammar().number_of_rules(), model.rules.size());
  EXPECT_EQ(read.grammar().number_of_sites(), grammar.number_of_sites());
  EXPECT_TRUE(Morphable_part_model().grammar().describes(Morphable_part_model()));
}

TEST(Model_grammar, changed_rules_need_an_update)
{
  Morphable_part_model model = small_hand_model();
  const Docking_rule rule = model.rules.front();
  model.rules.push_back(rule);
  EXPECT_THROW(model.grammar(), std::logic_error);
  model.update_grammar();
  EXPECT_EQ(model.grammar().rules_between(rule.first, rule.second).size(), 2u);
  model.rules.back().second = model.rules.back().first;
  EXPECT_THROW(model.grammar(), std::logic_error);
  EXPECT_EQ(small_hand_model().grammar().rules_between(rule.first, rule.second).size(), 1u); // the copy's grammar
}

TEST(Model_grammar, sites_by_index)
{
  const Morphable_part_model& model = small_hand_model();
  const Shape_grammar& grammar = model.grammar();
  std::size_t v = 0;
  for(int t = 0; t < int(model.types.size()); ++t)
    for(int s = 0; s < int(model.types[t].sites.size()); ++s, ++v)
    {
      EXPECT_EQ(grammar.vertex({t, s}), v);
      EXPECT_EQ(grammar.graph()[grammar.vertex({t, s})], (Site_ref{t, s}));
    }
  EXPECT_THROW(grammar.vertex({0, int(model.types[0].sites.size())}), std::out_of_range);
  EXPECT_TRUE(grammar.rules_between({0, int(model.types[0].sites.size())}, {0, 0}).empty());
}

TEST(Part_adjacency_graph, nodes_and_dockings_in_order)
{
  const Part_graph graph = part_graph_of_example(small_hand_model(), 0);
  const Part_adjacency_graph g = adjacency_graph(graph);
  ASSERT_EQ(boost::num_vertices(g), graph.nodes.size());
  ASSERT_EQ(boost::num_edges(g), graph.edges.size());
  std::vector<int> component(graph.nodes.size());
  EXPECT_EQ(boost::connected_components(g, component.data()), 1);
  for(int n = 0; n < int(graph.nodes.size()); ++n)
  {
    std::vector<int> expected;
    for(int k = 0; k < int(graph.edges.size()); ++k)
      if(graph.edges[k].first == n || graph.edges[k].second == n) expected.push_back(k);
    EXPECT_EQ(incident_dockings(g, n), expected);
  }
}
