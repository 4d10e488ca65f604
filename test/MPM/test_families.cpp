// Learning on every synthetic family, checked against the generator's truth.
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace CGAL::MPM;

namespace {

class Family_learning : public ::testing::TestWithParam<Synthetic_family>
{
protected:
  static Synthetic_options small()
  {
    Synthetic_options o;
    o.vertices = 4000;
    return o;
  }
};

// Fixes each type's mode count to the generator's truth, as a user who knows
// the family would.
Annotation with_true_modes(const Synthetic_model& s)
{
  Annotation a = s.annotation;
  for(const Synthetic_type& t : s.types)
    if(t.modes > 0) a.modes_of_type[t.name] = t.modes;
  return a;
}

} // namespace

TEST_P(Family_learning, subspaces_modes_grammar_and_round_trip)
{
  const Synthetic_model truth = make_synthetic_model(GetParam(), small());
  const Morphable_part_model model = learn_morphable_part_model(truth.mesh, with_true_modes(truth));
  SCOPED_TRACE(family_name(GetParam()));

  // Types and instance counts.
  ASSERT_EQ(model.types.size(), truth.types.size());
  std::map<std::string, int> instances_of_type;
  for(const Synthetic_instance& i : truth.instances) ++instances_of_type[i.type];
  for(const Synthetic_type& t : truth.types)
  {
    const int ti = model.find_type(t.name);
    ASSERT_GE(ti, 0) << t.name;
    const Shape_space& space = model.types[ti].space;
    EXPECT_EQ(space.number_of_instances(), instances_of_type[t.name]) << t.name;
    EXPECT_EQ(space.number_of_modes(), std::min(t.modes, instances_of_type[t.name] - 1)) << t.name;
    // The true number of modes explains at least 99% of the variance.
    EXPECT_GE(space.explained_variance(t.modes), 0.99) << t.name;
    // Linear variation: every instance lies in the learned subspace.
    if(t.linear)
      for(double r : space.instance_residuals) EXPECT_LT(r, 1e-6) << t.name;
  }

  // The learned correspondence is the generator's.
  const Part_graph& graph = model.examples.at(0).graph;
  std::map<int, const Part_node*> node_of_label;
  for(const Part_node& n : graph.nodes) node_of_label[n.label] = &n;
  for(const Synthetic_instance& i : truth.instances)
  {
    ASSERT_TRUE(node_of_label.count(i.label));
    EXPECT_EQ(node_of_label[i.label]->vertices, i.vertices) << "label " << i.label;
    EXPECT_EQ(model.types[node_of_label[i.label]->type].name, i.type);
  }

  // The part graph holds exactly the generator's dockings, of the right kind.
  std::set<std::tuple<int, int, bool>> learned, expected;
  for(const Part_edge& e : graph.edges)
  {
    const int a = graph.nodes[e.first].label, b = graph.nodes[e.second].label;
    learned.insert({std::min(a, b), std::max(a, b), model.rules[e.rule].kind == Docking_kind::boundary});
  }
  for(const Synthetic_connection& c : truth.connections)
    expected.insert({std::min(c.first, c.second), std::max(c.first, c.second), c.boundary});
  EXPECT_EQ(learned, expected);
  // And the grammar exactly the generator's rules.
  const Shape_grammar& grammar = model.grammar();
  EXPECT_EQ(static_cast<int>(grammar.number_of_rules()), truth.expected_rules);
  for(const Part_edge& e : graph.edges)
  {
    const Docking_rule& r = model.rules[e.rule];
    EXPECT_EQ(graph.nodes[e.first].type, r.first.type);
    EXPECT_EQ(graph.nodes[e.second].type, r.second.type);
    EXPECT_TRUE(grammar.allows(r.first, r.second));
  }

  // Save then load gives an identical model.
  const std::string bytes = serialize_model(model);
  EXPECT_EQ(serialize_model(deserialize_model(bytes, "memory")), bytes);
}

INSTANTIATE_TEST_SUITE_P(All, Family_learning, ::testing::ValuesIn(all_synthetic_families()),
                         [](const ::testing::TestParamInfo<Synthetic_family>& info) {
                           std::string name = family_name(info.param);
                           for(char& c : name)
                             if(c == '-') c = '_';
                           return name;
                         });
