// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Real segmented meshes (Princeton Segmentation Benchmark, found through
// MPM_PSB_DIR at run time or the define of the same name; skipped with a
// message when absent): learned with proposed part types, the learned
// example must be the user's closed surface again, and the edits must keep
// it closed and sound. The bounds are the measured figures with a margin
// (doc/MPM/Real_meshes.md).
#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Assembly/Free_site_capping.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Editing/Limb_bending.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include "Psb_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

namespace {

using namespace CGAL::MPM;

using mpm_test::psb_file;

struct Learned
{
  Training_input input;
  Morphable_part_model model;
};

Learned learn(const std::string& name)
{
  Learned l;
  l.input.mesh = read_labeled_mesh(psb_file(name + ".off"), psb_file(name + ".seg"));
  l.input.annotation = propose_part_types(l.input.mesh).annotation;
  l.model = learn_morphable_part_model({l.input});
  return l;
}

class Segmented_meshes : public ::testing::TestWithParam<const char*>
{
};

// The learned example of a closed one-piece mesh is one closed surface
// again (its corresponded parts stitched back along their seams), close to
// the input, and symmetrize, caricature and a bend of every limb keep it
// closed, converge, meet their targets, and turn no face inside out.
TEST_P(Segmented_meshes, learned_example_and_edits_stay_one_closed_surface)
{
  const std::string name = GetParam();
  MPM_REQUIRE_PSB(name);
  const Learned l = learn(name);
  const Training_example& ex = l.model.examples.front();
  const Labeled_mesh labeled = to_labeled_mesh(ex);
  int corresponded_types = 0;
  for(const Part_type& t : l.model.types) corresponded_types += t.space.number_of_instances() >= 2;
  EXPECT_GE(corresponded_types, 2) << name;

  const Surface_soundness rest = check_surface(labeled.mesh);
  EXPECT_EQ(rest.components, 1) << name;
  EXPECT_EQ(rest.border_edges, 0) << name;
  EXPECT_EQ(rest.non_manifold_edges, 0) << name;
  EXPECT_EQ(rest.degenerate_faces, 0) << name;
  // The input has none, nor has the example since its merged seams are
  // straightened on the input (octopus_137 had 4, at a seam, before).
  EXPECT_EQ(rest.self_intersections, 0) << name;
  // Below the 0.5% aimed at: measured 0.20% (ant_81), 0.34% (hand_181),
  // 0.38% (octopus_137; 0.55% while a move onto its curled arm tip turned
  // triangles and was undone); 0.55-0.69% before extremities were covered
  // (cover_missed_points()).
  EXPECT_LT(relative_hausdorff_distance(labeled.mesh, l.input.mesh.mesh), 0.005) << name;

  // Faces the edits may turn without turning anything inside out: folds
  // of the correspondence and spikes or slivers creased along two edges at
  // rest, which an edit flattens (octopus_137's symmetrize flattens a seam
  // sliver folded by 132 and 81 degrees at rest).
  const std::vector<int> folded = folded_faces(labeled.mesh, l.input.mesh.mesh),
                         spikes = spike_faces(labeled.mesh, CGAL_PI / 3., 2);
  // Seam moves that fold a face are not made, and seam vertices of faces
  // the correspondence folded move to unfold them (a sliver whose three
  // corners are on one seam all together): octopus_137 had 6 folded faces
  // at its thin rings' seams; it, ant_81 and hand_181 have none.
  EXPECT_EQ(folded.size(), 0u) << name;
  std::vector<int> rest_faults;
  std::set_union(folded.begin(), folded.end(), spikes.begin(), spikes.end(), std::back_inserter(rest_faults));
  for(int edit = 0; edit < 3; ++edit)
  {
    const Embedding_problem problem = edit == 0   ? make_symmetrization_problem(l.model)
                                      : edit == 1 ? make_caricature_problem(l.model, 2.)
                                                  : make_deformation_problem(l.model);
    Embedding_solver solver(problem);
    const Handle_set handles = edit == 2 ? limb_bending_handles(l.model) : Handle_set();
    if(edit == 2) solver.set_handles(handles.vertices, handles.targets);
    const Solve_report report = solver.solve();
    // Neighbours meet halfway on their seams, so the edit's targets can be
    // met: the energy falls to 2-9% of its first value (it stayed at 87%
    // when one side of every seam took the whole disagreement).
    if(edit < 2) EXPECT_LT(report.energy(), 0.15 * report.energies.front()) << name << " edit " << edit;
    // Converged in 5-7 iterations (measured); limbs bent about their
    // attachment reach their handles by bending their joints.
    EXPECT_TRUE(report.converged) << name << " edit " << edit;
    Indexed_mesh after = problem.mesh;
    after.points = solver.positions();
    ASSERT_TRUE(after.points.allFinite());
    const double diagonal = CGAL::MPM::internal::bounding_box_diagonal(problem.mesh.points);
    for(int k = 0; k < handles.size(); ++k)
      EXPECT_LT((after.points.row(handles.vertices[std::size_t(k)]) - handles.targets.row(k)).norm(), 0.01 * diagonal)
        << name << " handle " << k;
    const int solved_inverted = static_cast<int>(inverted_faces(after, problem.mesh, &labeled.face_labels).size());
    after.points = unfold_faces(problem.mesh, solver.positions(), handles.vertices); // what mpm writes
    const Surface_soundness s = check_surface(after, &problem.mesh, &labeled.face_labels);
    EXPECT_EQ(s.components, 1) << name << " edit " << edit;
    EXPECT_EQ(s.border_edges, 0) << name << " edit " << edit;
    // The edit's targets are unfolded (unfold_target(): folds and creases)
    // and so is the result: no face turns inside out within its part but
    // rest folds and spikes the edit flattens (the solver's result has 0-3;
    // before creases were unfolded, caricature left 1-4 in what mpm wrote).
    EXPECT_LE(s.inverted_faces, solved_inverted) << name << " edit " << edit;
    for(int f : inverted_faces(after, problem.mesh, &labeled.face_labels))
      EXPECT_TRUE(std::binary_search(rest_faults.begin(), rest_faults.end(), f)) << name << " edit " << edit << " face " << f;
  }
}

// Handles held where they rest leave the stitched example at rest: its
// inserted seam vertices lie off the other side's chords, and that
// disagreement must not count as one the targets added.
TEST_P(Segmented_meshes, the_rest_pose_is_a_solution)
{
  const std::string name = GetParam();
  MPM_REQUIRE_PSB(name);
  const Learned l = learn(name);
  const Embedding_problem problem = make_deformation_problem(l.model);
  Embedding_solver solver(problem);
  const Point_matrix& rest = problem.mesh.points;
  // Extreme vertices, far apart, so that they hold every rigid motion.
  std::vector<int> handles(4);
  rest.col(0).minCoeff(&handles[0]);
  rest.col(0).maxCoeff(&handles[1]);
  rest.col(1).minCoeff(&handles[2]);
  rest.col(2).maxCoeff(&handles[3]);
  Point_matrix held(4, 3);
  for(int k = 0; k < 4; ++k) held.row(k) = rest.row(handles[k]);
  solver.set_handles(handles, held);
  solver.solve();
  const double diagonal = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
  // Before the rest tilt of merged seams was taken back: 0.12% (hand_181),
  // 0.67% (ant_81).
  EXPECT_LT((solver.positions() - rest).rowwise().norm().maxCoeff(), 1e-9 * diagonal) << name;
}

// The training graph assembled from its own instances, placed where they
// were, gives the learned example back: the same vertices and faces, one
// closed surface, every vertex near where it was. Not exactly: the seam
// vertices inserted into a stitched part's edges are interpolated on the
// edge, where the example straightened them on the input (0.18% of the
// diagonal at most on hand_181, 0.60% on octopus_137, 0.41% on ant_81).
// Such a node lists its inserted vertices after its own, which the options
// took for part of its target ("needs 7178 finite points").
TEST_P(Segmented_meshes, the_training_graph_is_reassembled_from_its_instances)
{
  const std::string name = GetParam();
  MPM_REQUIRE_PSB(name);
  const Learned l = learn(name);
  const Training_example& ex = l.model.examples.front();
  const Labeled_mesh labeled = to_labeled_mesh(ex);
  const Assembly a = assemble(l.model, part_graph_of_example(l.model), training_assembly_options(l.model));
  EXPECT_EQ(a.mesh.number_of_vertices(), labeled.mesh.number_of_vertices()) << name;
  EXPECT_EQ(a.mesh.number_of_faces(), labeled.mesh.number_of_faces()) << name;
  const Surface_soundness s = check_surface(a.mesh);
  EXPECT_EQ(s.components, 1) << name;
  EXPECT_EQ(s.border_edges, 0) << name;
  double worst = 0.;
  for(std::size_t i = 0; i < ex.graph.nodes.size(); ++i)
    for(std::size_t k = 0; k < ex.graph.nodes[i].vertices.size(); ++k)
      worst = std::max(worst, (a.mesh.points.row(a.vertex(int(i), int(k))) -
                               labeled.mesh.points.row(ex.graph.nodes[i].vertices[k])).norm());
  EXPECT_LT(worst, 0.01 * CGAL::MPM::internal::bounding_box_diagonal(labeled.mesh.points)) << name;
}

// One more segment before the last of the first chain that has three
// segments: the result is one closed surface with one more part.
TEST_P(Segmented_meshes, a_segment_inserted_into_a_chain_keeps_the_surface_closed)
{
  const std::string name = GetParam();
  MPM_REQUIRE_PSB(name);
  Learned l = learn(name);
  add_repetition_rules(l.model);
  Part_graph graph = part_graph_of_example(l.model, 0);
  std::vector<int> degree(graph.nodes.size(), 0);
  for(const Part_edge& e : graph.edges) ++degree[e.first], ++degree[e.second];
  int edge = -1;
  for(std::size_t k = 0; k < graph.edges.size() && edge < 0; ++k)
  {
    const Part_edge& e = graph.edges[k];
    for(const auto& [segment, tip] : {std::make_pair(e.first, e.second), std::make_pair(e.second, e.first)})
      if(degree[segment] == 2 && degree[tip] == 1 && l.model.types[graph.nodes[segment].type].space.number_of_instances() >= 2)
        edge = int(k);
  }
  ASSERT_GE(edge, 0) << name << ": no chain ends in a segment of a learned type";
  const std::size_t parts = graph.nodes.size();
  insert_segment(l.model, graph, edge);
  const Assembly a = assemble(l.model, graph);
  EXPECT_EQ(a.graph.nodes.size(), parts + 1);
  const Surface_soundness s = check_surface(a.mesh);
  EXPECT_EQ(s.components, 1) << name;
  EXPECT_EQ(s.border_edges, 0) << name;
  EXPECT_EQ(s.non_manifold_edges, 0) << name;
  EXPECT_TRUE(std::isfinite(a.residual_energy));
  // It was 9, 24 and 5.6e8 when one side of each seam took the targets'
  // whole disagreement and the rest tilt of merged seams was kept.
  EXPECT_LT(a.energy_per_part(), 1.) << name; // measured 0.04-0.2
}

// Chains shrink as they grow: every segment of every finger, leg and arm
// can be removed (its neighbours docked by a bridging rule; without it no
// learned rule docks a proximal phalanx to a tip), and every limb with the
// hole it leaves capped; a limb copied onto the freed site closes it
// again. Each result is one closed surface.
TEST_P(Segmented_meshes, every_segment_and_limb_can_be_removed_and_a_limb_copied)
{
  const std::string name = GetParam();
  MPM_REQUIRE_PSB(name);
  Learned l = learn(name);
  add_repetition_rules(l.model);
  EXPECT_FALSE(add_bridging_rules(l.model).empty()) << name;
  EXPECT_TRUE(add_bridging_rules(l.model).empty()) << name;
  const Part_graph example = part_graph_of_example(l.model, 0);
  const int root = root_node(example);
  std::vector<int> dockings(example.nodes.size(), 0);
  std::vector<int> limbs;
  for(const Part_edge& e : example.edges)
  {
    ++dockings[std::size_t(e.first)], ++dockings[std::size_t(e.second)];
    if(e.first == root || e.second == root) limbs.push_back(e.first == root ? e.second : e.first);
  }
  const auto expect_closed = [&](Assembly a, const std::string& what, int holes) {
    EXPECT_EQ(cap_free_sites(l.model, a), holes) << name << ": " << what;
    const Surface_soundness s = check_surface(a.mesh);
    EXPECT_EQ(s.components, 1) << name << ": " << what;
    EXPECT_EQ(s.border_edges, 0) << name << ": " << what;
    EXPECT_EQ(s.non_manifold_edges, 0) << name << ": " << what;
    EXPECT_TRUE(a.mesh.points.allFinite()) << name << ": " << what;
  };
  int segments = 0;
  for(int node = 0; node < int(example.nodes.size()); ++node)
  {
    if(node == root || dockings[std::size_t(node)] != 2) continue;
    Part_graph g = example;
    ASSERT_NO_THROW(remove_segment(l.model, g, node)) << name << ": segment " << node;
    expect_closed(assemble(l.model, g), "segment " + std::to_string(node) + " removed", 0);
    ++segments;
  }
  EXPECT_GE(segments, 5) << name;
  for(int limb : limbs)
  {
    Part_graph g = example;
    remove_branch(l.model, g, limb, root);
    expect_closed(assemble(l.model, g), "limb " + std::to_string(limb) + " removed", 1);
  }
  // A limb replaced by a copy of another of its type (the freed site docks
  // that type: each site of a real body has its own rule).
  int gone = -1, copied = -1;
  for(int a : limbs)
    for(int b : limbs)
      if(gone < 0 && a != b && example.nodes[std::size_t(a)].type == example.nodes[std::size_t(b)].type) gone = a, copied = b;
  ASSERT_GE(gone, 0) << name << ": no two limbs of one type";
  Part_graph g = example;
  const std::vector<int> renumbered = remove_branch(l.model, g, gone, root);
  const int body = renumbered[std::size_t(root)];
  ASSERT_NO_THROW(duplicate_branch(l.model, g, renumbered[std::size_t(copied)], body, body)) << name;
  expect_closed(assemble(l.model, g), "a limb copied onto the freed site", 0);
}

INSTANTIATE_TEST_SUITE_P(Psb, Segmented_meshes, ::testing::Values("hand_181", "octopus_137", "ant_81"));

// hand_196's fourth and fifth fingers are curled against the palm: a middle
// segment copied from its neighbour continued the curl, and the inserted
// segment ran through the palm and the next finger (89 and 48 crossing
// face pairs when placed, 131 in all after the embedding). A straighter
// instance of the type crosses nothing.
TEST(Segmented_meshes_insertion, an_inserted_segment_does_not_continue_a_curl_into_the_palm)
{
  MPM_REQUIRE_PSB(std::string("hand_196"));
  Learned l = learn("hand_196");
  add_repetition_rules(l.model);
  const Part_graph example = part_graph_of_example(l.model, 0);
  std::vector<int> degree(example.nodes.size(), 0);
  for(const Part_edge& e : example.edges) ++degree[e.first], ++degree[e.second];
  Assembly_options placement;
  placement.solve = false;
  int copied_crossings = 0, chosen_crossings = 0, embedded_crossings = 0;
  for(std::size_t k = 0; k < example.edges.size(); ++k)
  {
    const Part_edge& e = example.edges[k];
    if(!((degree[e.first] == 1 && degree[e.second] == 2) || (degree[e.second] == 1 && degree[e.first] == 2))) continue;
    Part_graph graph = example;
    const int added = insert_segment(l.model, graph, int(k));
    copied_crossings += crossings_of_node(assemble(l.model, graph, placement), added);
    choose_segment_shape(l.model, graph, added);
    chosen_crossings += crossings_of_node(assemble(l.model, graph, placement), added);
    const Assembly a = assemble(l.model, graph);
    embedded_crossings += crossings_of_node(a, added);
    EXPECT_EQ(check_surface(a.mesh).border_edges, 0) << "edge " << k;
  }
  EXPECT_GT(copied_crossings, 100); // measured 137
  EXPECT_EQ(chosen_crossings, 0);
  EXPECT_LT(embedded_crossings, 20); // measured 4 (131 before the choice)
}

// Two octopuses learned together: segments that keep their own shape (the
// thin rings where arms were cut twice, arms no template covers) become
// types of their own in each mesh. Both meshes have such a segment 3 with
// other connectivity; the types were both named "tip2_label3" and learning
// failed ("connectivity differs from label 3 of octopus_124.off").
TEST(Segmented_meshes_together, own_shapes_of_two_meshes_are_two_types)
{
  MPM_REQUIRE_PSB(std::string("octopus_124"));
  MPM_REQUIRE_PSB(std::string("octopus_126"));
  std::vector<Training_input> inputs(2);
  for(std::size_t i = 0; i < 2; ++i)
  {
    const std::string name = i == 0 ? "octopus_124" : "octopus_126";
    inputs[i].mesh = read_labeled_mesh(psb_file(name + ".off"), psb_file(name + ".seg"));
    inputs[i].annotation = propose_part_types(inputs[i].mesh).annotation;
  }
  const Morphable_part_model model = learn_morphable_part_model(inputs);
  ASSERT_EQ(model.examples.size(), 2u);
  int own_per_mesh[2] = {0, 0};
  for(const Part_type& t : model.types)
    for(int m = 0; m < 2; ++m) own_per_mesh[m] += t.name.find("_mesh" + std::to_string(m) + "_label") != std::string::npos;
  EXPECT_GT(own_per_mesh[0], 0);
  EXPECT_GT(own_per_mesh[1], 0);
  for(const Training_example& ex : model.examples)
    EXPECT_EQ(check_surface(to_labeled_mesh(ex).mesh).border_edges, 0) << ex.name;
}

// octopus_124's arm tips: every template tried covers the other thin arms
// to 1-3% of their diagonal but twisted around them, 34-46% of its
// triangles facing against the arm. Those correspondences are refused (the
// arms keep their own shapes, with a warning naming each), so the learned
// example is the input again; accepted, it carried 424 folded faces, 808
// self-intersecting face pairs and missed the input by 1.1% of the diagonal.
// Where stitched templates cross at a seam, the learned example is moved
// apart on the input's surface and learned again: hand_194's crossed itself
// in 6 face pairs (0 once untangled, as octopus_126's 7), within 0.3% of
// its input.
TEST(Segmented_meshes_untangled, stitched_templates_crossing_at_seams_are_moved_apart)
{
  const std::string name = "hand_194";
  MPM_REQUIRE_PSB(name);
  const Learned l = learn(name);
  const Surface_soundness s = check_surface(to_labeled_mesh(l.model.examples.front()).mesh);
  EXPECT_EQ(s.self_intersections, 0);
  EXPECT_EQ(s.border_edges, 0);
  EXPECT_EQ(s.components, 1);
  EXPECT_LT(relative_hausdorff_distance(to_labeled_mesh(l.model.examples.front()).mesh, l.input.mesh.mesh), 0.003);
}

// Stitching splits the triangles along a seam into fans, so a vertex beside
// a seam has many seam neighbours close together. Untangling moved such
// vertices to the mean of their neighbours, which lay on the seam, and the
// fans' slivers folded there: ant_90's example kept 7 crossing face pairs
// and octopus_126's 21. With the fan counted as one neighbour and each
// crossing moved apart on its own, ant_90's has none and octopus_126's 8.
TEST(Segmented_meshes_untangled, vertices_beside_a_seam_are_not_pulled_onto_it)
{
  for(const auto& [name, most] : {std::pair<std::string, int>{"ant_90", 0}, {"octopus_126", 10}})
  {
    MPM_REQUIRE_PSB(name);
    const Learned l = learn(name);
    const Indexed_mesh example = to_labeled_mesh(l.model.examples.front()).mesh;
    const Surface_soundness s = check_surface(example);
    EXPECT_LE(s.self_intersections, most) << name;
    EXPECT_EQ(s.border_edges, 0) << name;
    // None on either since seam moves that fold are not made (2 on
    // octopus_126 before).
    EXPECT_EQ(folded_faces(example, l.input.mesh.mesh).size(), 0u) << name;
    EXPECT_LT(relative_hausdorff_distance(example, l.input.mesh.mesh), 0.003) << name;
  }
}

// A template's first row squeezed against its seam left a sliver of
// ant_97's antenna folded over the input, crossing nothing; relaxed onto
// the part's own faces it stayed pinned to the part's border. Relaxed onto
// the whole input it turns back, and the example keeps to the input.
TEST(Segmented_meshes_untangled, a_sliver_folded_by_a_seam_is_turned_back)
{
  MPM_REQUIRE_PSB(std::string("ant_97"));
  const Learned l = learn("ant_97");
  const Indexed_mesh example = to_labeled_mesh(l.model.examples.front()).mesh;
  EXPECT_EQ(folded_faces(example, l.input.mesh.mesh).size(), 0u); // 1 before
  const Surface_soundness s = check_surface(example);
  EXPECT_EQ(s.self_intersections, 0);
  EXPECT_EQ(s.border_edges, 0);
  EXPECT_EQ(s.degenerate_faces, 0);
  EXPECT_LT(relative_hausdorff_distance(example, l.input.mesh.mesh), 0.005); // measured 0.35%
}

TEST(Segmented_meshes_tubes, thin_arms_are_corresponded_along_the_tube)
{
  // octopus_124's arm tips are ten times longer than wide and curl each
  // its own way: a template placed rigidly and bent by a spline lay twisted
  // around them (40% of its triangles turned) and every tip kept its own
  // shape. Placed along the tube (position along the axis, angle about it)
  // half of them are corresponded (the others crumple it at their tips
  // and keep their own shapes), and the example still reproduces the input.
  MPM_REQUIRE_PSB(std::string("octopus_124"));
  const Learned l = learn("octopus_124");
  const Morphable_part_model& model = l.model;
  const Indexed_mesh example = to_labeled_mesh(model.examples.front()).mesh;
  EXPECT_LT(relative_hausdorff_distance(example, l.input.mesh.mesh), 0.005);
  EXPECT_EQ(check_surface(example).self_intersections, 0);
  EXPECT_EQ(folded_faces(example, l.input.mesh.mesh).size(), 0u);
  const int tip = model.find_type("tip2");
  ASSERT_GE(tip, 0);
  int tips = 0;
  for(const Part_node& n : model.examples.front().graph.nodes) tips += n.type == tip;
  EXPECT_GE(tips, 4);
  EXPECT_GE(model.types[std::size_t(tip)].space.number_of_modes(), 3);
}

TEST(Segmented_meshes_tubes, arms_in_different_poses_are_corresponded)
{
  // octopus_126's eight arms, two pieces each, curl each its own way: every
  // piece but the templates was refused (6-19% of the template's triangles
  // turned), and the model had one type with modes. Along the tube all
  // sixteen pieces are corresponded.
  MPM_REQUIRE_PSB(std::string("octopus_126"));
  const Learned l = learn("octopus_126");
  const Morphable_part_model& model = l.model;
  const Training_example& example = model.examples.front();
  const Labeled_mesh labeled = to_labeled_mesh(example);
  EXPECT_LT(relative_hausdorff_distance(labeled.mesh, l.input.mesh.mesh), 0.005);
  EXPECT_EQ(check_surface(labeled.mesh).components, 1);
  std::map<std::string, int> instances;
  for(const Part_node& n : example.graph.nodes) ++instances[model.types[std::size_t(n.type)].name];
  for(const std::string& arm : {"chain1", "tip2"})
  {
    EXPECT_EQ(instances[arm], 8) << arm;
    const int type = model.find_type(arm);
    ASSERT_GE(type, 0) << arm;
    EXPECT_GE(model.types[std::size_t(type)].space.number_of_modes(), 3) << arm;
  }
}

} // namespace

// Each triangle split into four at its edge midpoints, labels kept: the
// same surface, finely triangulated, as a user's finer scan would be.
Labeled_mesh split_in_four(const Labeled_mesh& in)
{
  Labeled_mesh out;
  out.source = in.source + " (split in four)";
  std::map<std::pair<int, int>, int> midpoint;
  std::vector<Eigen::RowVector3d> points;
  for(Eigen::Index v = 0; v < in.mesh.points.rows(); ++v) points.push_back(in.mesh.points.row(v));
  const auto middle = [&](int a, int b) {
    const auto [it, added] = midpoint.insert({{std::min(a, b), std::max(a, b)}, int(points.size())});
    if(added) points.push_back(0.5 * (in.mesh.points.row(a) + in.mesh.points.row(b)));
    return it->second;
  };
  for(std::size_t f = 0; f < in.mesh.triangles.size(); ++f)
  {
    const auto [a, b, c] = in.mesh.triangles[f];
    const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    for(const Triangle& t : {Triangle{a, ab, ca}, Triangle{ab, b, bc}, Triangle{ca, bc, c}, Triangle{ab, bc, ca}})
    {
      out.mesh.triangles.push_back(t);
      out.face_labels.push_back(in.face_labels[f]);
    }
  }
  out.mesh.points.resize(Eigen::Index(points.size()), 3);
  for(std::size_t v = 0; v < points.size(); ++v) out.mesh.points.row(Eigen::Index(v)) = points[v];
  return out;
}

// ant_97 split in four: a corresponded leg segment's template border has
// two vertices almost on one spot whose projections onto the seam came in
// the other order, and the stitched example kept a quad open between that
// segment and its neighbour (4 border edges, and no insertion closed).
TEST(Segmented_meshes_finer, a_finely_triangulated_scan_is_stitched_closed)
{
  MPM_REQUIRE_PSB(std::string("ant_97"));
  Training_input input;
  input.mesh = split_in_four(read_labeled_mesh(psb_file("ant_97.off"), psb_file("ant_97.seg")));
  input.annotation = propose_part_types(input.mesh).annotation;
  const Morphable_part_model model = learn_morphable_part_model({input});
  const Surface_soundness s = check_surface(to_labeled_mesh(model.examples.front()).mesh);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.border_edges, 0);
  EXPECT_EQ(s.non_manifold_edges, 0);
  EXPECT_LT(relative_hausdorff_distance(to_labeled_mesh(model.examples.front()).mesh, input.mesh.mesh), 0.005);
}

// octopus_124 split in four: segments whose border touches itself at a
// junction (two of its seams meeting at one vertex) get templates with two
// separate border loops, and stitching gave such a segment one side at
// that junction, on one loop: 5 border edges stayed open at the seams of
// labels 0, 5 and 13, and none of its 7 insertions closed. Each loop now
// has its own side there. Were a seam left open, learning would say so.
TEST(Segmented_meshes_finer, a_segment_whose_border_touches_itself_is_stitched_on_both_loops)
{
  MPM_REQUIRE_PSB(std::string("octopus_124"));
  Training_input input;
  input.mesh = split_in_four(read_labeled_mesh(psb_file("octopus_124.off"), psb_file("octopus_124.seg")));
  input.annotation = propose_part_types(input.mesh).annotation;
  std::vector<std::string> warnings;
  Learning_options options;
  options.warning = [&](const std::string& w) { warnings.push_back(w); };
  const Morphable_part_model model = learn_morphable_part_model({input}, options);
  const Surface_soundness s = check_surface(to_labeled_mesh(model.examples.front()).mesh);
  EXPECT_EQ(s.border_edges, 0);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.non_manifold_edges, 0);
  const bool reported = std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
    return w.find("the learned example is open at the seams of labels") != std::string::npos;
  });
  EXPECT_EQ(reported, s.border_edges > 0) << s.border_edges << " open edges";
}
