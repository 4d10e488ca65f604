#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace CGAL::MPM;

namespace {

// A strip of square tiles, each a k x k grid bent by a bump that vanishes on
// its border (so the shared seams match), tile j by amplitude `bend[j]`.
// With `gap` > 0 the tiles are separate components `gap` apart.
Labeled_mesh tile_strip(const std::vector<double>& bend, int k, double gap)
{
  Labeled_mesh lm;
  lm.source = "strip";
  const int tiles = static_cast<int>(bend.size());
  std::vector<Eigen::RowVector3d> points;
  std::vector<std::vector<int>> index(tiles, std::vector<int>((k + 1) * (k + 1)));
  for(int t = 0; t < tiles; ++t)
    for(int j = 0; j <= k; ++j)
      for(int i = 0; i <= k; ++i)
      {
        if(gap == 0. && t > 0 && i == 0)
        {
          index[t][j * (k + 1)] = index[t - 1][j * (k + 1) + k];
          continue;
        }
        const double u = double(i) / k, v = double(j) / k;
        index[t][j * (k + 1) + i] = static_cast<int>(points.size());
        points.emplace_back(t * (1. + gap) + u, v, bend[t] * std::sin(M_PI * u) * std::sin(M_PI * v));
      }
  lm.mesh.points.resize(points.size(), 3);
  for(std::size_t i = 0; i < points.size(); ++i) lm.mesh.points.row(i) = points[i];
  for(int t = 0; t < tiles; ++t)
    for(int j = 0; j < k; ++j)
      for(int i = 0; i < k; ++i)
      {
        const int a = index[t][j * (k + 1) + i], b = index[t][j * (k + 1) + i + 1];
        const int c = index[t][(j + 1) * (k + 1) + i], d = index[t][(j + 1) * (k + 1) + i + 1];
        lm.mesh.triangles.push_back({a, b, d});
        lm.mesh.triangles.push_back({a, d, c});
        lm.face_labels.push_back(t);
        lm.face_labels.push_back(t);
      }
  return lm;
}

Annotation tiles_annotation(int tiles, double radius)
{
  Annotation a;
  for(int t = 0; t < tiles; ++t) a.part_type_of_label[t] = "tile";
  a.parameters.docking_radius = radius;
  a.source = "strip.json";
  return a;
}

template <class F>
std::string error_of(F f)
{
  try
  {
    f();
  }
  catch(const Input_error& e)
  {
    return e.what();
  }
  return "no error";
}

} // namespace

TEST(Learning, boundary_docked_strip)
{
  const std::vector<double> bend = {0.3, -0.2, 0.1, -0.2};
  const Labeled_mesh strip = tile_strip(bend, 8, 0.);
  const Morphable_part_model model = learn_morphable_part_model(strip, tiles_annotation(4, 0.3));

  ASSERT_EQ(model.types.size(), 1u);
  const Part_type& tile = model.types[0];
  EXPECT_EQ(tile.name, "tile");
  EXPECT_EQ(tile.number_of_vertices, 81);
  EXPECT_EQ(tile.triangles.size(), 128u);
  // Left and right seams are the two docking sites, nine vertices each.
  ASSERT_EQ(tile.sites.size(), 2u);
  for(const Docking_site& s : tile.sites)
  {
    EXPECT_EQ(s.kind, Docking_kind::boundary);
    EXPECT_EQ(s.vertices.size(), 9u);
  }
  // One bending mode, and the tiles lie in the learned space exactly.
  ASSERT_EQ(tile.space.number_of_modes(), 1);
  for(double r : tile.space.instance_residuals) EXPECT_LT(r, 1e-6);
  // One rule (right side to left side), observed three times.
  ASSERT_EQ(model.rules.size(), 1u);
  const Docking_rule& rule = model.rules[0];
  EXPECT_EQ(rule.kind, Docking_kind::boundary);
  EXPECT_EQ(rule.seam.size(), 9u);
  EXPECT_EQ(rule.space.number_of_instances(), 3);
  // Pair geometry: columns within 0.3 of the seam on both sides (3 columns
  // each side: distances 0, 1/8, 2/8), seam once.
  EXPECT_EQ(rule.points.size(), 9u * 5u);
  for(const Cluster_edge& e : rule.edges) EXPECT_FALSE(e.is_virtual);

  ASSERT_EQ(model.examples.size(), 1u);
  const Part_graph& graph = model.examples[0].graph;
  ASSERT_EQ(graph.nodes.size(), 4u);
  ASSERT_EQ(graph.edges.size(), 3u);
  for(const Part_edge& e : graph.edges)
  {
    EXPECT_EQ(e.rule, 0);
    // Part graph edges follow the strip.
    EXPECT_EQ(std::abs(graph.nodes[e.first].label - graph.nodes[e.second].label), 1);
    // Seam vertices really are shared.
    for(const auto& [l0, l1] : rule.seam)
      EXPECT_EQ(graph.nodes[e.first].vertices[l0], graph.nodes[e.second].vertices[l1]);
  }
  // Each node's coordinates and motion reproduce its instance.
  for(const Part_node& node : graph.nodes)
  {
    const Point_matrix x = node.motion.apply(tile.space.shape(node.coordinates));
    for(std::size_t v = 0; v < node.vertices.size(); ++v)
      EXPECT_LT((x.row(v) - strip.mesh.points.row(node.vertices[v])).norm(), 1e-8);
  }

  const Shape_grammar& grammar = model.grammar();
  EXPECT_EQ(grammar.number_of_sites(), 2u);
  EXPECT_EQ(grammar.number_of_rules(), 1u);
  EXPECT_TRUE(grammar.allows(rule.first, rule.second));
  EXPECT_TRUE(grammar.allows(rule.second, rule.first));
  EXPECT_FALSE(grammar.allows(rule.first, rule.first));
}

TEST(Learning, groups_parts_by_connectivity_without_annotation)
{
  const Labeled_mesh strip = tile_strip({0.3, -0.2, 0.1, -0.2}, 6, 0.);
  Annotation none;
  none.parameters.docking_radius = 0.2;
  const Morphable_part_model model = learn_morphable_part_model(strip, none);
  ASSERT_EQ(model.types.size(), 1u);
  EXPECT_EQ(model.types[0].space.number_of_instances(), 4);
}

TEST(Learning, generalized_docking_between_components)
{
  const Labeled_mesh strip = tile_strip({0.2, -0.1, -0.1}, 6, 0.1);
  const Morphable_part_model model = learn_morphable_part_model(strip, tiles_annotation(3, 0.15));
  ASSERT_EQ(model.types.size(), 1u);
  ASSERT_EQ(model.types[0].sites.size(), 2u);
  for(const Docking_site& s : model.types[0].sites)
  {
    EXPECT_EQ(s.kind, Docking_kind::generalized);
    EXPECT_EQ(s.vertices.size(), 7u); // the facing column only
  }
  ASSERT_EQ(model.rules.size(), 1u);
  const Docking_rule& rule = model.rules[0];
  EXPECT_EQ(rule.kind, Docking_kind::generalized);
  EXPECT_TRUE(rule.seam.empty());
  EXPECT_EQ(rule.points.size(), 14u);
  int virtual_edges = 0;
  for(const Cluster_edge& e : rule.edges)
  {
    virtual_edges += e.is_virtual;
    if(e.is_virtual) EXPECT_NE(rule.points[e.source].side, rule.points[e.target].side);
  }
  EXPECT_GE(virtual_edges, 7);
  EXPECT_EQ(model.examples[0].graph.edges.size(), 2u);
}

TEST(Learning, pools_instances_and_rules_across_examples)
{
  Training_input a{tile_strip({0.3, -0.3}, 6, 0.), tiles_annotation(2, 0.2)};
  Training_input b{tile_strip({0.1, 0.2, -0.3}, 6, 0.), tiles_annotation(3, 0.2)};
  const Morphable_part_model model = learn_morphable_part_model(std::vector<Training_input>{a, b});
  ASSERT_EQ(model.types.size(), 1u);
  EXPECT_EQ(model.types[0].space.number_of_instances(), 5);
  ASSERT_EQ(model.rules.size(), 1u);
  EXPECT_EQ(model.rules[0].space.number_of_instances(), 3);
  ASSERT_EQ(model.examples.size(), 2u);
  EXPECT_EQ(model.examples[1].graph.nodes.size(), 3u);
}

TEST(Learning, corresponds_instances_with_different_connectivity)
{
  // One tile listed with a different corner order: no longer an error, the
  // type goes through dense correspondence and every tile gets the first
  // tile's connectivity. The corners are rotated, not swapped: a swapped
  // face would face against its neighbours, which learning turns back
  // before anything else (BadInput.AFaceFlippedAgainstItsNeighboursIsTurnedBack).
  Labeled_mesh strip = tile_strip({0.3, -0.2, 0.1}, 4, 0.);
  for(std::size_t f = 0; f < strip.face_labels.size(); ++f)
    if(strip.face_labels[f] == 2)
    {
      Triangle& t = strip.mesh.triangles[f];
      std::rotate(t.begin(), t.begin() + 1, t.end());
      break;
    }
  std::vector<std::string> stages;
  Learning_options options;
  options.progress = [&](const std::string& stage, double) { stages.push_back(stage); };
  const Morphable_part_model model = learn_morphable_part_model(strip, tiles_annotation(3, 0.3), options);
  ASSERT_EQ(model.types.size(), 1u);
  EXPECT_EQ(model.types[0].space.number_of_instances(), 3);
  EXPECT_NE(std::find(stages.begin(), stages.end(), "correspondence of " + model.types[0].name), stages.end());
  for(const Part_node& node : model.examples[0].graph.nodes)
    EXPECT_GE(static_cast<int>(node.vertices.size()), model.types[0].number_of_vertices);
  EXPECT_TRUE(to_labeled_mesh(model.examples[0]).mesh.points.allFinite());
  // The rebuilt tiles are stitched back to their former seam neighbours
  // (boundary dockings with merged seams), never to the tile after next:
  // the example is one piece again, open only where the strip was.
  const Part_graph& graph = model.examples[0].graph;
  EXPECT_EQ(graph.edges.size(), 2u);
  for(const Part_edge& e : graph.edges)
  {
    EXPECT_EQ(model.rules[e.rule].kind, Docking_kind::boundary);
    EXPECT_FALSE(e.merged_seam.empty());
    EXPECT_EQ(std::abs(graph.nodes[e.first].label - graph.nodes[e.second].label), 1);
  }
  const Surface_soundness input = check_surface(strip.mesh), example = check_surface(to_labeled_mesh(model.examples[0]).mesh);
  EXPECT_EQ(example.components, 1);
  EXPECT_EQ(example.border_edges, input.border_edges);
  EXPECT_EQ(example.non_manifold_edges, 0);
  // The flipped face makes this tile's correspondence coarse (2% off the
  // input before stitching); stitching must not add much to that.
  const Corresponded_training rebuilt = correspond_training_inputs({{strip, tiles_annotation(3, 0.3)}});
  EXPECT_LT(relative_hausdorff_distance(to_labeled_mesh(model.examples[0]).mesh, strip.mesh),
            relative_hausdorff_distance(rebuilt.inputs[0].mesh.mesh, strip.mesh) + 0.015);
}

TEST(Learning, rejects_annotated_type_without_instance)
{
  const Labeled_mesh strip = tile_strip({0.3, -0.2}, 4, 0.);
  Annotation a = tiles_annotation(2, 0.3);
  a.part_type_of_label[5] = "finger";
  const std::string e = error_of([&] { learn_morphable_part_model(strip, a); });
  EXPECT_NE(e.find("strip.json"), std::string::npos) << e;
  EXPECT_NE(e.find("label 5"), std::string::npos) << e;
  EXPECT_NE(e.find("finger"), std::string::npos) << e;

  Annotation b = tiles_annotation(2, 0.3);
  b.modes_of_type["wing"] = 2;
  const std::string f = error_of([&] { learn_morphable_part_model(strip, b); });
  EXPECT_NE(f.find("\"wing\""), std::string::npos) << f;
  EXPECT_NE(f.find("no instance"), std::string::npos) << f;
}

TEST(Learning, rejects_unlisted_label_and_bad_landmark)
{
  const Labeled_mesh strip = tile_strip({0.3, -0.2, 0.1}, 4, 0.);
  Annotation a = tiles_annotation(2, 0.3);
  const std::string e = error_of([&] { learn_morphable_part_model(strip, a); });
  EXPECT_NE(e.find("label 2"), std::string::npos) << e;

  Annotation b = tiles_annotation(3, 0.3);
  b.landmarks_of_label[1] = {30, 100000};
  const std::string f = error_of([&] { learn_morphable_part_model(strip, b); });
  EXPECT_NE(f.find("landmark 1"), std::string::npos) << f;
  EXPECT_NE(f.find("label 1"), std::string::npos) << f;
}

TEST(Learning, rejects_zero_docking_radius)
{
  const Labeled_mesh strip = tile_strip({0.3, -0.2}, 4, 0.);
  const std::string e = error_of([&] { learn_morphable_part_model(strip, tiles_annotation(2, 0.)); });
  EXPECT_NE(e.find("docking_radius"), std::string::npos) << e;
  EXPECT_NE(e.find("strip.json"), std::string::npos) << e;
}

TEST(Learning, rejects_non_finite_coordinates_and_label_count)
{
  Labeled_mesh strip = tile_strip({0.3, -0.2}, 4, 0.);
  strip.mesh.points(7, 2) = std::numeric_limits<double>::infinity();
  const std::string e = error_of([&] { learn_morphable_part_model(strip, tiles_annotation(2, 0.3)); });
  EXPECT_NE(e.find("vertex 7"), std::string::npos) << e;

  Labeled_mesh short_labels = tile_strip({0.3, -0.2}, 4, 0.);
  short_labels.face_labels.pop_back();
  const std::string f = error_of([&] { learn_morphable_part_model(short_labels, tiles_annotation(2, 0.3)); });
  EXPECT_NE(f.find("strip"), std::string::npos) << f;
}

// Identical instances vary by rounding only: that is no variation to set
// the automatic sigma_sub from (it was 3.7e-15, and every edit blew up).
TEST(Learning, identical_instances_give_a_usable_sigma_sub)
{
  const Labeled_mesh strip = tile_strip({0.3, 0.3}, 4, 0.);
  const Morphable_part_model model = learn_morphable_part_model(strip, tiles_annotation(2, 0.3));
  const double diagonal = (strip.mesh.points.colwise().maxCoeff() - strip.mesh.points.colwise().minCoeff()).norm();
  EXPECT_NEAR(model.parameters.sigma_sub, 0.002 * diagonal, 1e-12 * diagonal);
}

// A mesh so small that squared lengths underflow is refused at learn time,
// naming it, instead of giving a model every edit refuses.
TEST(Learning, rejects_a_mesh_too_small_to_edit)
{
  Labeled_mesh strip = tile_strip({0.3, -0.2}, 4, 0.);
  strip.mesh.points *= 1e-200;
  const std::string e = error_of([&] { learn_morphable_part_model(strip, tiles_annotation(2, -1.)); });
  EXPECT_NE(e.find("strip"), std::string::npos) << e;
  EXPECT_NE(e.find("scale the mesh"), std::string::npos) << e;
}
