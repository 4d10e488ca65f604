// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cutting along user cutting lines: the synthetic hand's true seams give its
// true parts back, the feature term makes a sparse cut follow a curved
// valley, every bad input is a clear Input_error, and `mpm cut` writes what
// `mpm learn` reads.
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include "Io_test_support.h"
#include "Tool_test_support.h"
#include "Learned_models.h"
#include "Hand_cuts.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>


namespace {

using namespace CGAL::MPM;
using mpm_test::small_hand;
using mpm_test::hand_cuts;
using mpm_test::inner_vertex;
using mpm_test::seam_loop;
using mpm_test::sparse;

double agreement(const std::vector<int>& a, const std::vector<int>& b)
{
  int same = 0;
  for(std::size_t f = 0; f < a.size(); ++f) same += a[f] == b[f];
  return double(same) / double(a.size());
}

TEST(Mesh_cutting, HandSeamsGiveTheTrueParts)
{
  const Synthetic_model& hand = small_hand();
  ASSERT_EQ(hand.connections.size(), 15u);
  const Cut_specification spec = hand_cuts(hand);
  for(double weight : {0., 1.}) {
    Cutting_options options;
    options.feature_weight = weight;
    const Cutting_result cut = cut_mesh(hand.mesh.mesh, spec, options, "hand");
    EXPECT_EQ(cut.regions, 16);
    EXPECT_GE(agreement(cut.mesh.face_labels, hand.mesh.face_labels), 0.99) << "feature weight " << weight;
    ASSERT_EQ(cut.paths.size(), spec.cuts.size());
    for(std::size_t i = 0; i < cut.paths.size(); ++i) {
      // The path is the seam loop itself: closed, as long as the seam.
      const std::vector<int> loop = seam_loop(hand.mesh, hand.connections[i].first, hand.connections[i].second);
      EXPECT_EQ(cut.paths[i].front(), cut.paths[i].back());
      EXPECT_EQ(cut.paths[i].size(), loop.size() + 1) << spec.cuts[i].name;
      EXPECT_GT(cut.lengths[i], 0.);
    }
    EXPECT_EQ(cut.mesh.mesh.points, hand.mesh.mesh.points);
  }
}

TEST(Mesh_cutting, UnnamedRegionsAreNumberedByTheirFirstFace)
{
  const Synthetic_model& hand = small_hand();
  Cut_specification spec = hand_cuts(hand);
  const int palm = hand.instances.front().label;
  spec.parts = {{40, inner_vertex(hand.mesh, palm)}};
  const Cutting_result cut = cut_mesh(hand.mesh.mesh, spec);
  std::map<int, int> first_face_of_label;
  for(std::size_t f = 0; f < cut.mesh.face_labels.size(); ++f)
    first_face_of_label.emplace(cut.mesh.face_labels[f], int(f));
  ASSERT_EQ(first_face_of_label.size(), 16u);
  ASSERT_EQ(first_face_of_label.count(40), 1u);
  // The other labels are 0..14, increasing with the region's first face.
  int expected = 0, previous_face = -1;
  std::vector<std::pair<int, int>> by_face;
  for(const auto& [label, face] : first_face_of_label)
    if(label != 40) by_face.push_back({face, label});
  std::sort(by_face.begin(), by_face.end());
  for(const auto& [face, label] : by_face) {
    EXPECT_EQ(label, expected++);
    EXPECT_GT(face, previous_face);
    previous_face = face;
  }
  // The seeded region is the palm.
  for(std::size_t f = 0; f < cut.mesh.face_labels.size(); ++f)
    EXPECT_EQ(cut.mesh.face_labels[f] == 40, hand.mesh.face_labels[f] == palm) << "face " << f;
}

// A sheet z = depth * |y - c(x)| over [0,1] x [-1,1] on a grid with
// alternating diagonals: a valley along the curve y = c(x).
struct Valley
{
  Indexed_mesh mesh;
  int nx = 61, ny = 81;
  static double crease(double x) { return 0.35 * std::sin(2. * std::acos(-1.) * x); }
  int vertex(int i, int j) const { return j * nx + i; }
  Valley()
  {
    mesh.points.resize(nx * ny, 3);
    for(int j = 0; j < ny; ++j)
      for(int i = 0; i < nx; ++i) {
        const double x = double(i) / (nx - 1), y = -1. + 2. * double(j) / (ny - 1);
        mesh.points.row(vertex(i, j)) << x, y, 0.3 * std::abs(y - crease(x));
      }
    for(int j = 0; j + 1 < ny; ++j)
      for(int i = 0; i + 1 < nx; ++i) {
        const int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
        if((i + j) % 2 == 0) {
          mesh.triangles.push_back({a, b, c});
          mesh.triangles.push_back({a, c, d});
        } else {
          mesh.triangles.push_back({a, b, d});
          mesh.triangles.push_back({b, c, d});
        }
      }
  }
  // The grid vertex on column i nearest to the crease.
  int on_crease(int i) const
  {
    const double y = crease(double(i) / (nx - 1));
    return vertex(i, int(std::lround((y + 1.) / 2. * (ny - 1))));
  }
  double mean_distance_to_crease(const std::vector<int>& path) const
  {
    double sum = 0.;
    for(int v : path) sum += std::abs(mesh.points(v, 1) - crease(mesh.points(v, 0)));
    return sum / double(path.size());
  }
};

TEST(Mesh_cutting, FeatureTermFollowsAValley)
{
  const Valley valley;
  Cut_specification spec;
  Cut_line cut; // border to border along the valley, with one point in between
  cut.vertices = {valley.on_crease(0), valley.on_crease(valley.nx / 2), valley.on_crease(valley.nx - 1)};
  cut.closed = false;
  spec.cuts = {cut};
  const double spacing = 2. / (valley.ny - 1);
  Cutting_options geodesic;
  geodesic.feature_weight = 0.;
  const Cutting_result plain = cut_mesh(valley.mesh, spec, geodesic, "valley");
  const Cutting_result snapped = cut_mesh(valley.mesh, spec, Cutting_options(), "valley");
  const double plain_distance = valley.mean_distance_to_crease(plain.paths[0]);
  const double snapped_distance = valley.mean_distance_to_crease(snapped.paths[0]);
  std::cout << "valley cut, mean distance to the crease in grid spacings: feature weight 0: "
            << plain_distance / spacing << ", 1: " << snapped_distance / spacing << "\n";
  EXPECT_EQ(plain.regions, 2);
  EXPECT_EQ(snapped.regions, 2);
  EXPECT_GT(plain_distance, 4. * spacing);
  EXPECT_LT(snapped_distance, spacing);
  EXPECT_LT(snapped_distance, 0.2 * plain_distance);
}

TEST(Mesh_cutting, BadCutsAreInputErrors)
{
  const Synthetic_model& hand = small_hand();
  const Indexed_mesh& mesh = hand.mesh.mesh;
  const Cut_specification good = hand_cuts(hand);
  const int n = mesh.number_of_vertices();

  Cut_specification spec = good;
  spec.cuts[2].vertices[1] = n + 5;
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "hand cuts", "cuts[2] \"" + good.cuts[2].name + "\"",
                         "vertex " + std::to_string(n + 5) + " is out of range");

  spec = good;
  spec.cuts[1].vertices.resize(1);
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "cuts[1]", "has 1 vertex; a cut needs at least two");

  spec = good;
  spec.cuts[0].vertices.push_back(spec.cuts[0].vertices[1]);
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "cuts[0]", "is listed twice");

  // An open line on a closed surface separates nothing.
  spec = good;
  Cut_line scratch;
  scratch.name = "scratch";
  scratch.closed = false;
  scratch.vertices = {inner_vertex(hand.mesh, hand.instances.front().label),
                      inner_vertex(hand.mesh, hand.instances.front().label, 40)};
  spec.cuts.push_back(scratch);
  spec.parts.clear();
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "cuts[15] \"scratch\"", "does not separate the mesh");

  // The same loop twice: neither copy is needed.
  spec = good;
  spec.cuts.push_back(good.cuts[4]);
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "cuts[4]", "does not separate");

  spec = good;
  spec.parts[3].seed = good.cuts[0].vertices[0];
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "parts[3]", "lies on cuts[0]", "choose a vertex inside the part");

  spec = good;
  spec.parts[5].seed = good.parts[6].seed;
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "parts[6]", "same region as parts[5]");

  spec = good;
  spec.parts[2].label = good.parts[7].label;
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "parts[7]", "appears twice (also in parts[2])");

  spec = good;
  spec.parts[0].label = -1;
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "parts[0]", "negative label");

  spec = good;
  spec.parts[0].seed = -3;
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, spec), "parts[0]", "seed vertex -3 is out of range");

  Cutting_options options;
  options.feature_weight = -1.;
  MPM_EXPECT_INPUT_ERROR(cut_mesh(mesh, good, options), "feature_weight", "non-negative");
}

// Two tetrahedra far apart, and a vertex on no face.
Indexed_mesh two_tetrahedra()
{
  Indexed_mesh m;
  m.points.resize(9, 3);
  m.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 0, 0, 6, 0, 0, 5, 1, 0, 5, 0, 1, 9, 9, 9;
  for(int o : {0, 4}) {
    m.triangles.push_back({o + 0, o + 2, o + 1});
    m.triangles.push_back({o + 0, o + 1, o + 3});
    m.triangles.push_back({o + 0, o + 3, o + 2});
    m.triangles.push_back({o + 1, o + 2, o + 3});
  }
  return m;
}

TEST(Mesh_cutting, BadMeshesAreInputErrors)
{
  const Indexed_mesh m = two_tetrahedra();
  Cut_specification spec;
  spec.source = "cuts.json";
  spec.cuts.push_back({{0, 1, 2}, std::nullopt, "across"});
  // The loop 0-1-2 around a tetrahedron separates face (0, 2, 1) from the rest.
  EXPECT_EQ(cut_mesh(m, spec, Cutting_options(), "tets.off").regions, 3);

  spec.cuts[0].vertices = {0, 5};
  MPM_EXPECT_INPUT_ERROR(cut_mesh(m, spec, Cutting_options(), "tets.off"), "cuts.json", "cuts[0] \"across\"",
                         "vertices 0 and 5 lie on different connected components of the mesh: no path joins them");
  spec.cuts[0].vertices = {0, 8};
  MPM_EXPECT_INPUT_ERROR(cut_mesh(m, spec, Cutting_options(), "tets.off"), "cuts[0]", "vertex 8 belongs to no face");
  spec.cuts[0].vertices = {0, 1, 2};
  spec.parts = {{1, 8}};
  MPM_EXPECT_INPUT_ERROR(cut_mesh(m, spec, Cutting_options(), "tets.off"), "parts[0]",
                         "seed vertex 8 belongs to no face");

  Indexed_mesh fin = m; // a third triangle on edge (0, 1)
  fin.triangles.push_back({0, 1, 8});
  spec.parts.clear();
  MPM_EXPECT_INPUT_ERROR(cut_mesh(fin, spec, Cutting_options(), "fin.off"), "fin.off", "face 8",
                         "non-manifold edge");
  Indexed_mesh flat = m;
  flat.points.row(3) = flat.points.row(1);
  MPM_EXPECT_INPUT_ERROR(cut_mesh(flat, spec, Cutting_options(), "flat.off"), "flat.off", "face");
}

TEST(Mesh_cutting, CutFileFormat)
{
  const Cut_specification spec = parse_cut_specification(
    R"({"format": "cgal-mpm-cuts", "version": 1,
        "cuts": [{"name": "neck", "vertices": [4, 9, 12]}, {"vertices": [1, 2], "closed": false}],
        "parts": [{"label": 3, "seed": 7}]})",
    "c.json");
  ASSERT_EQ(spec.cuts.size(), 2u);
  EXPECT_EQ(spec.cuts[0].name, "neck");
  EXPECT_EQ(spec.cuts[0].vertices, (std::vector<int>{4, 9, 12}));
  EXPECT_FALSE(spec.cuts[0].closed.has_value());
  EXPECT_EQ(spec.cuts[1].closed, std::optional<bool>(false));
  ASSERT_EQ(spec.parts.size(), 1u);
  EXPECT_EQ(spec.parts[0].label, 3);
  EXPECT_EQ(spec.parts[0].seed, 7);
  EXPECT_EQ(spec.source, "c.json");

  MPM_EXPECT_INPUT_ERROR(parse_cut_specification("{\"parts\": []}", "c.json"), "c.json", "lacks \"cuts\"");
  MPM_EXPECT_INPUT_ERROR(parse_cut_specification(R"({"cuts": [{"vertex": [1, 2]}]})", "c.json"), "cuts[0]",
                         "unknown key \"vertex\"");
  MPM_EXPECT_INPUT_ERROR(parse_cut_specification(R"({"cuts": [{"vertices": [1, -2]}]})", "c.json"),
                         "cuts[0].vertices[1]", "must not be negative");
  MPM_EXPECT_INPUT_ERROR(parse_cut_specification(R"({"cuts": [{"vertices": [1, 2], "closed": 1}]})", "c.json"),
                         "cuts[0].closed", "must be true or false");
  MPM_EXPECT_INPUT_ERROR(parse_cut_specification(R"({"cuts": [], "parts": [{"label": 1}]})", "c.json"),
                         "parts[0]", "lacks \"seed\"");
  MPM_EXPECT_INPUT_ERROR(parse_cut_specification(R"({"format": "cgal-mpm-annotation", "cuts": []})", "c.json"),
                         "format", "is not \"cgal-mpm-cuts\"");
  MPM_EXPECT_INPUT_ERROR(parse_cut_specification("{\"cuts\": [", "c.json"), "c.json", "malformed JSON");
  MPM_EXPECT_INPUT_ERROR(read_cut_specification("/nonexistent/c.json"), "/nonexistent/c.json");
}

TEST(Mesh_cutting, CommandWritesWhatLearnReads)
{
  const mpm_test::Scratch_directory dir;
  const Synthetic_model& hand = small_hand();
  write_mesh_file(hand.mesh.mesh, dir.file("hand.off"));
  const Cut_specification spec = hand_cuts(hand);
  nlohmann::json cuts = nlohmann::json::array(), parts = nlohmann::json::array();
  for(const Cut_line& c : spec.cuts) cuts.push_back({{"name", c.name}, {"vertices", c.vertices}});
  for(const Part_seed& p : spec.parts) parts.push_back({{"label", p.label}, {"seed", p.seed}});
  mpm_test::write_bytes(dir.file("hand.cuts.json"),
                        nlohmann::json({{"format", "cgal-mpm-cuts"}, {"cuts", cuts}, {"parts", parts}}).dump());

  const mpm_test::Run_result cut = mpm_test::run_tool(
    dir.path(), "cut " + dir.file("hand.off") + " --cuts " + dir.file("hand.cuts.json") + " -o " + dir.file("out/cut") + " --json");
  ASSERT_EQ(cut.status, 0) << cut.err;
  const nlohmann::json summary = nlohmann::json::parse(cut.out);
  EXPECT_EQ(summary["parts"].size(), 16u);
  EXPECT_EQ(summary["cuts"].size(), 15u);
  const Labeled_mesh written = read_labeled_mesh(dir.file("out/cut.off"), dir.file("out/cut.seg"));
  EXPECT_EQ(written.mesh.triangles, hand.mesh.mesh.triangles);
  EXPECT_LT((written.mesh.points - hand.mesh.mesh.points).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_GE(agreement(written.face_labels, hand.mesh.face_labels), 0.99);
  int faces = 0;
  for(const auto& p : summary["parts"]) faces += p["faces"].get<int>();
  EXPECT_EQ(faces, hand.mesh.mesh.number_of_faces());

  // A quad would be split by the reader, changing what is written: refused.
  mpm_test::write_bytes(dir.file("quad.off"), "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 1 2 3\n3 0 1 4\n");
  mpm_test::write_bytes(dir.file("quad.cuts.json"), R"({"cuts": [{"vertices": [0, 2]}]})");
  const mpm_test::Run_result quad = mpm_test::run_tool(
    dir.path(), "cut " + dir.file("quad.off") + " --cuts " + dir.file("quad.cuts.json") + " -o " + dir.file("quad_out"));
  EXPECT_EQ(quad.status, 1);
  ASSERT_EQ(quad.err_lines().size(), 1u) << quad.err;
  EXPECT_TRUE(mpm_test::contains_all(quad.err_lines()[0], {"quad.off", "face 0", "has 4 corners", "triangle mesh"}))
    << quad.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("quad_out.seg")));
  EXPECT_EQ(mpm_test::run_tool(dir.path(), "cut " + dir.file("hand.off") + " -o " + dir.file("x")).status, 2);
}

// Unreached vertices must read as +infinity: Boost's default, the largest
// finite double, passed std::isfinite() and sent the cut tracer round a
// predecessor chain that never reached its source (a hang, then out of memory).
TEST(Mesh_cutting, UnreachedVerticesAreAtInfiniteDistance)
{
  const std::vector<Cluster_edge> edges = {{0, 1, false}, {2, 3, false}};
  const internal::Edge_graph_paths paths = internal::edge_graph_shortest_paths(4, edges, {1., 1.}, {0});
  EXPECT_DOUBLE_EQ(paths.distance[1], 1.);
  EXPECT_TRUE(std::isinf(paths.distance[2]));
  EXPECT_EQ(paths.predecessor[2], -1);
  EXPECT_EQ(paths.predecessor[1], 0);
}

} // namespace
