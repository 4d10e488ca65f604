// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One click per joint: on the synthetic hand with its labels removed, one
// click next to each true seam finds a cut close to it and gives the true
// parts back; bad clicks and bad meshes are Input_errors naming the vertex.
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Cutting/Segmentation_measures.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include "Io_test_support.h"
#include "Psb_meshes.h"
#include "Learned_models.h"
#include "Tool_test_support.h"
#include "Tube_mesh.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <string>

namespace {

using namespace CGAL::MPM;
using mpm_test::small_hand;

double mean_edge_length(const Indexed_mesh& m)
{
  double sum = 0.;
  for(const Triangle& t : m.triangles)
    for(int k = 0; k < 3; ++k) sum += (m.points.row(t[k]) - m.points.row(t[(k + 1) % 3])).norm();
  return sum / (3. * double(m.triangles.size()));
}

// A neighbour of the cut vertex nearest the cut's centroid that is not on
// the cut: a click next to the joint, as a user would make it.
int click_next_to(const Indexed_mesh& m, const std::vector<int>& cut)
{
  const int on = central_cut_vertex(m, cut);
  const std::set<int> on_cut(cut.begin(), cut.end());
  for(const Triangle& t : m.triangles)
    if(std::find(t.begin(), t.end(), on) != t.end())
      for(int v : t)
        if(on_cut.count(v) == 0) return v;
  return on;
}

std::string error_of(const Indexed_mesh& m, const std::vector<int>& clicks)
{
  try {
    cut_at_vertices(m, clicks, Joint_cutting_options(), "mesh.off");
  } catch(const Input_error& e) {
    return e.what();
  }
  return "";
}

// The seams between two finger segments. The knuckles, where a finger meets
// the palm, are left out: on this hand the section through a click there
// also crosses the palm and the skeleton near the palm has no clean finger
// axis, so the cut found lies several edges off (a known limitation, see
// doc/MPM/Cutting.md).
std::vector<std::vector<int>> finger_joints(const Synthetic_model& hand)
{
  std::map<int, std::string> type;
  for(const Synthetic_instance& i : hand.instances) type[i.label] = i.type;
  std::vector<std::vector<int>> joints;
  for(const Segmentation_cut& seam : segmentation_cuts(hand.mesh.mesh, hand.mesh.face_labels))
    if(type[seam.first_label] != "palm" && type[seam.second_label] != "palm") joints.push_back(seam.vertices);
  return joints;
}

TEST(Joint_cutting, OneClickPerJointFindsTheFingerJoints)
{
  const Synthetic_model& hand = small_hand();
  const Indexed_mesh& m = hand.mesh.mesh;
  const std::vector<std::vector<int>> joints = finger_joints(hand);
  ASSERT_EQ(joints.size(), 10u);
  std::vector<int> clicks;
  for(const std::vector<int>& joint : joints) clicks.push_back(click_next_to(m, joint));

  const Joint_cutting_result result = cut_at_vertices(m, clicks, Joint_cutting_options(), "hand");
  ASSERT_EQ(result.cuts.size(), joints.size());
  EXPECT_TRUE(result.skipped.empty());
  const double edge = mean_edge_length(m);
  for(std::size_t i = 0; i < joints.size(); ++i) {
    const Joint_cut& c = result.cuts[i];
    EXPECT_EQ(c.vertex, clicks[i]);
    EXPECT_EQ(c.path.front(), c.path.back());
    EXPECT_GT(c.length, 0.);
    // Within about one edge of the true seam (an edge is about 1.5% of the
    // diagonal of this 3k-vertex hand).
    EXPECT_LT(cut_distance(m, c.path, joints[i]), 1.2 * edge) << "cut at vertex " << clicks[i];
  }
  // The palm with the five proximal segments, and ten more segments.
  std::set<int> labels(result.mesh.face_labels.begin(), result.mesh.face_labels.end());
  EXPECT_EQ(labels.size(), 11u);
}

TEST(Joint_cutting, BadClicksNameTheVertex)
{
  const Synthetic_model& hand = small_hand();
  const Indexed_mesh& m = hand.mesh.mesh;
  const int a = click_next_to(m, finger_joints(hand).front());
  // Two clicks on one joint: next to a finger joint, then on the cut that
  // click made (people cut thin rings: a click a ring away is a second cut).
  const std::vector<int> made = cut_at_vertices(m, {a}, Joint_cutting_options(), "mesh.off").cuts.front().path;
  for(int on : {made.front(), made[made.size() / 2]}) {
    const std::string twice = error_of(m, {a, on});
    EXPECT_NE(twice.find("vertex " + std::to_string(on) + ": is on the same joint as vertex " + std::to_string(a)),
              std::string::npos)
      << twice;
  }

  const std::string out = error_of(m, {m.number_of_vertices()});
  EXPECT_NE(out.find("out of range"), std::string::npos) << out;

  // Vertex 0 is on the palm, away from every finger.
  const auto face = std::find_if(m.triangles.begin(), m.triangles.end(),
                                 [](const Triangle& t) { return std::find(t.begin(), t.end(), 0) != t.end(); });
  const int label = hand.mesh.face_labels[std::size_t(face - m.triangles.begin())];
  for(const Synthetic_instance& i : hand.instances)
    if(i.label == label) ASSERT_EQ(i.type, "palm");
  const std::string body = error_of(m, {0});
  EXPECT_NE(body.find("vertex 0: is on the body"), std::string::npos) << body;
}

TEST(Joint_cutting, BadMeshesAreInputErrors)
{
  const Synthetic_model& hand = small_hand();
  Indexed_mesh holed = hand.mesh.mesh;
  holed.triangles.pop_back();
  const std::string hole = error_of(holed, {0});
  EXPECT_NE(hole.find("hole"), std::string::npos) << hole;

  Indexed_mesh two = hand.mesh.mesh;
  const int n = two.number_of_vertices();
  two.points.conservativeResize(2 * n, 3);
  two.points.bottomRows(n) = hand.mesh.mesh.points.rowwise() + Eigen::RowVector3d(100., 0., 0.);
  for(const Triangle& t : hand.mesh.mesh.triangles) two.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  const std::string components = error_of(two, {0});
  EXPECT_NE(components.find("2 connected components"), std::string::npos) << components;

  // A square tube closed by two apexes: four vertices around.
  Indexed_mesh tube;
  const int rings = 12, sides = 4;
  tube.points = mpm_test::bent_tube(rings, sides, 10., 1., 0.);
  tube.triangles = mpm_test::tube_triangles(rings, sides);
  const int bottom = rings * sides, top = bottom + 1;
  tube.points.conservativeResize(top + 1, 3);
  tube.points.row(bottom) << 0., 0., -1.;
  tube.points.row(top) << 0., 0., 11.;
  for(int s = 0; s < sides; ++s) {
    tube.triangles.push_back({bottom, (s + 1) % sides, s});
    tube.triangles.push_back({top, (rings - 1) * sides + s, (rings - 1) * sides + (s + 1) % sides});
  }
  const std::string coarse = error_of(tube, {5 * sides});
  EXPECT_NE(coarse.find("too coarse"), std::string::npos) << coarse;
}

TEST(Joint_cutting, CommandWritesLabelsAndNamesBadClicks)
{
  const mpm_test::Scratch_directory dir;
  const Synthetic_model& hand = small_hand();
  write_mesh_file(hand.mesh.mesh, dir.file("hand.off"));
  const std::vector<std::vector<int>> joints = finger_joints(hand);
  const int a = click_next_to(hand.mesh.mesh, joints[0]), b = click_next_to(hand.mesh.mesh, joints[1]);
  const std::string at = " --at " + std::to_string(a) + " --at " + std::to_string(b);

  const mpm_test::Run_result cut =
    mpm_test::run_tool(dir.path(), "cut " + dir.file("hand.off") + at + " -o " + dir.file("out/hand") + " --json");
  ASSERT_EQ(cut.status, 0) << cut.err;
  const nlohmann::json summary = nlohmann::json::parse(cut.out);
  ASSERT_EQ(summary["cuts"].size(), 2u);
  EXPECT_EQ(summary["cuts"][0]["vertex"].get<int>(), a);
  EXPECT_GT(summary["cuts"][1]["length"].get<double>(), 0.);
  EXPECT_EQ(summary["parts"].get<int>(), 3);
  const std::vector<int> labels = read_seg_file(dir.file("out/hand.seg"));
  EXPECT_EQ(labels.size(), hand.mesh.mesh.triangles.size());
  EXPECT_EQ(std::set<int>(labels.begin(), labels.end()).size(), 3u);

  // The same joint twice: exit status 1, the vertex named, nothing written.
  const mpm_test::Run_result twice = mpm_test::run_tool(
    dir.path(), "cut " + dir.file("hand.off") + " --at " + std::to_string(a) + " --at " + std::to_string(a) + " -o " +
                  dir.file("twice"));
  EXPECT_EQ(twice.status, 1);
  ASSERT_EQ(twice.err_lines().size(), 1u) << twice.err;
  EXPECT_TRUE(mpm_test::contains_all(twice.err_lines()[0], {"hand.off", "vertex " + std::to_string(a), "same joint"}))
    << twice.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("twice.seg")));
  // --cuts and --at together, or neither: usage errors.
  EXPECT_EQ(mpm_test::run_tool(dir.path(), "cut " + dir.file("hand.off") + " -o " + dir.file("x")).status, 2);
  EXPECT_EQ(mpm_test::run_tool(dir.path(), "cut " + dir.file("hand.off") + at + " --cuts c.json -o " + dir.file("x")).status, 2);
}

using mpm_test::psb_directory;

// The human cuts of a PSB mesh a user would click (`joint_cuts()`, as
// bench/quality_segmentation clicks them) and one click on each (the vertex
// nearest the cut's centroid).
struct Human_cuts
{
  Labeled_mesh human;
  std::vector<std::vector<int>> cuts;
  std::vector<int> clicks;
  double diagonal = 0.;

  // The distance of each found cut to its human cut, over the diagonal.
  std::vector<double> distances(const Joint_cutting_result& result) const
  {
    std::vector<double> d;
    for(const Joint_cut& c : result.cuts) {
      const std::size_t i = std::size_t(std::find(clicks.begin(), clicks.end(), c.vertex) - clicks.begin());
      d.push_back(cut_distance(human.mesh, c.path, cuts.at(i)) / diagonal);
    }
    return d;
  }
};

bool read_human_cuts(const std::string& name, Human_cuts& h)
{
  const std::string base = mpm_test::psb_file(name);
  if(!std::filesystem::exists(base + ".off")) return false;
  h.human = read_labeled_mesh(base + ".off", base + ".seg");
  for(const Segmentation_cut& c : joint_cuts(segmentation_cuts(h.human.mesh, h.human.face_labels))) {
    h.cuts.push_back(c.vertices);
    h.clicks.push_back(central_cut_vertex(h.human.mesh, c.vertices));
  }
  h.diagonal = internal::bounding_box_diagonal(h.human.mesh.points);
  return true;
}

double mean_of(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.) / double(v.size()); }

// The bar on a real scan: one click on each human cut of an ant
// (legs, antennae, body segments: closed seam loops) finds every cut, at a
// mean distance below 1% of the bounding box diagonal (doc/MPM/Cutting.md),
// each cut within 1%.
TEST(Joint_cutting, OneClickPerHumanCutOfAnAnt)
{
  Human_cuts h;
  if(!read_human_cuts("ant_81", h))
    GTEST_SKIP() << mpm_test::psb_not_found(psb_directory());
  ASSERT_GE(h.cuts.size(), 20u);
  const Joint_cutting_result result = cut_at_vertices(h.human.mesh, h.clicks, Joint_cutting_options(), "ant_81.off");
  ASSERT_EQ(result.cuts.size(), h.cuts.size());
  const std::vector<double> d = h.distances(result);
  for(std::size_t i = 0; i < d.size(); ++i) EXPECT_LT(d[i], 0.01) << "click at vertex " << h.clicks[i];
  EXPECT_LT(mean_of(d), 0.01);
  EXPECT_LT(rand_index_error(h.human.mesh, result.mesh.face_labels, h.human.face_labels), 0.02);
}

// Where people cut along a crease oblique to the limb (octopus arms near
// the body), the cut snapped to the crease follows theirs more closely
// than the plane section through the click does (0.26% of the diagonal on
// average against 0.34% when measured; 0.7% before the thinner limb's own
// section was tried at a limb's flared base, doc/MPM/Cutting.md).
// Every human cut is found: two arms' cuts whose centres lie within a limb
// radius of each other near the body are two joints, not one.
TEST(Joint_cutting, CutsFollowTheCreasePeopleCutAlong)
{
  Human_cuts h;
  if(!read_human_cuts("octopus_137", h))
    GTEST_SKIP() << mpm_test::psb_not_found(psb_directory());
  Joint_cutting_options options;
  options.skip_unfound = true;
  const std::vector<double> snapped = h.distances(cut_at_vertices(h.human.mesh, h.clicks, options, "octopus_137.off"));
  options.snap_band = 0.;
  const std::vector<double> planar = h.distances(cut_at_vertices(h.human.mesh, h.clicks, options, "octopus_137.off"));
  ASSERT_EQ(snapped.size(), h.cuts.size());
  for(std::size_t i = 0; i < snapped.size(); ++i) EXPECT_LT(snapped[i], 0.01) << "cut " << i;
  EXPECT_LT(mean_of(snapped), 0.004);
  EXPECT_LT(mean_of(snapped), 0.85 * mean_of(planar));
}

// The distance (fraction of the diagonal) from the cut clicked alone at the
// central vertex of the human cut between labels `first` and `second` of
// PSB mesh `name` to that human cut; NaN when the mesh is absent.
double one_click_distance(const std::string& name, int first, int second)
{
  Human_cuts h;
  if(!read_human_cuts(name, h)) return std::nan("");
  for(const Segmentation_cut& c : segmentation_cuts(h.human.mesh, h.human.face_labels))
    if(c.first_label == first && c.second_label == second) {
      const int click = central_cut_vertex(h.human.mesh, c.vertices);
      const Joint_cutting_result r = cut_at_vertices(h.human.mesh, {click}, Joint_cutting_options(), name + ".off");
      if(r.cuts.size() != 1u) return HUGE_VAL;
      return cut_distance(h.human.mesh, r.cuts[0].path, c.vertices) / h.diagonal;
    }
  ADD_FAILURE() << name << " has no cut between labels " << first << " and " << second;
  return HUGE_VAL;
}

// A click where a short leg piece of ant_97 meets the thorax (labels 8 and
// 20) lies on the thorax's surface as well as the leg's: the thorax's many
// skeleton edges filled the axes tried, and the click cut the thorax 6.8%
// of the diagonal away. The best fitting thinner limb is tried too.
TEST(Joint_cutting, AClickAtALegsBaseCutsTheLegNotTheBody)
{
  const double d = one_click_distance("ant_97", 8, 20);
  if(std::isnan(d))
    GTEST_SKIP() << mpm_test::psb_not_found(psb_directory());
  EXPECT_LT(d, 0.01);
}

// Where a limb flares into the body, the click lies farther from the limb's
// axis than the limb's radius allows and the body's axes fit it: ant_97's
// leg piece 24 at the thorax was cut 7.1% of the diagonal away, around the
// thorax, and hand_190's finger base (labels 0 and 7) around the palm. The
// section across the thinner limb near the click is tried too.
TEST(Joint_cutting, AClickWhereALimbFlaresIntoTheBodyCutsTheLimb)
{
  const double leg = one_click_distance("ant_97", 8, 24);
  if(std::isnan(leg))
    GTEST_SKIP() << mpm_test::psb_not_found(psb_directory());
  EXPECT_LT(leg, 0.01);
  EXPECT_LT(one_click_distance("hand_190", 0, 7), 0.01);
}

// Edges of the closed path `p` (first vertex repeated last), sorted.
std::vector<std::pair<int, int>> sorted_edges(const std::vector<int>& p)
{
  std::vector<std::pair<int, int>> e;
  for(std::size_t k = 0; k + 1 < p.size(); ++k) e.push_back(std::minmax(p[k], p[k + 1]));
  std::sort(e.begin(), e.end());
  return e;
}

// One click at the central vertex of each human cut between the given
// labels, and that cut.
void click_human_cuts(const Human_cuts& h, const std::vector<std::pair<int, int>>& between, std::vector<int>& clicks,
                      std::vector<std::vector<int>>& cuts)
{
  for(const std::pair<int, int>& labels : between)
    for(const Segmentation_cut& c : segmentation_cuts(h.human.mesh, h.human.face_labels))
      if(c.first_label == labels.first && c.second_label == labels.second) {
        clicks.push_back(central_cut_vertex(h.human.mesh, c.vertices));
        cuts.push_back(c.vertices);
      }
}

// Two human cuts of octopus_124 bound the thin ring (label 11) where an arm
// (8) leaves the body (0); the ring is pinched, so the two cuts share a
// few edges without crossing. The second click was refused as a second
// click on the first joint.
TEST(Joint_cutting, CutsThatShareAFewEdgesAreTwoJoints)
{
  Human_cuts h;
  if(!read_human_cuts("octopus_124", h))
    GTEST_SKIP() << mpm_test::psb_not_found(psb_directory());
  std::vector<int> clicks;
  std::vector<std::vector<int>> cuts;
  click_human_cuts(h, {{0, 11}, {8, 11}}, clicks, cuts);
  ASSERT_EQ(clicks.size(), 2u);
  const Joint_cutting_result r = cut_at_vertices(h.human.mesh, clicks, Joint_cutting_options(), "octopus_124.off");
  ASSERT_EQ(r.cuts.size(), 2u);
  const std::vector<std::pair<int, int>> first = sorted_edges(r.cuts[0].path), second = sorted_edges(r.cuts[1].path);
  std::vector<std::pair<int, int>> shared;
  std::set_intersection(first.begin(), first.end(), second.begin(), second.end(), std::back_inserter(shared));
  EXPECT_FALSE(shared.empty());
  for(std::size_t i = 0; i < 2; ++i)
    EXPECT_LT(cut_distance(h.human.mesh, r.cuts[i].path, cuts[i]) / h.diagonal, 0.01) << "click at vertex " << clicks[i];
}

// The thin ring (label 9) where another arm (2) of octopus_124 leaves the
// body (0) lies between two concave creases a ring of faces apart. Clicked
// on the body's side, the cut snaps to the arm's sharper crease and runs
// through the click on the arm's side; that click then takes its crease and
// the first cut goes back to the body's crease. Both orders give both human
// cuts; the second click was refused as a click on the first joint.
TEST(Joint_cutting, AThinRingBetweenTwoCreasesIsTwoJointsInEitherOrder)
{
  Human_cuts h;
  if(!read_human_cuts("octopus_124", h))
    GTEST_SKIP() << mpm_test::psb_not_found(psb_directory());
  std::vector<int> clicks;
  std::vector<std::vector<int>> cuts;
  click_human_cuts(h, {{0, 9}, {2, 9}}, clicks, cuts);
  ASSERT_EQ(clicks.size(), 2u);
  for(const bool reversed : {false, true}) {
    const std::vector<int> order = reversed ? std::vector<int>{clicks[1], clicks[0]} : clicks;
    const Joint_cutting_result r = cut_at_vertices(h.human.mesh, order, Joint_cutting_options(), "octopus_124.off");
    ASSERT_EQ(r.cuts.size(), 2u);
    for(std::size_t i = 0; i < 2; ++i)
      EXPECT_LT(cut_distance(h.human.mesh, r.cuts[i].path, cuts[reversed ? 1 - i : i]) / h.diagonal, 0.005)
        << "click at vertex " << order[i];
    // The ring is a region of its own: three in all.
    EXPECT_EQ(std::set<int>(r.mesh.face_labels.begin(), r.mesh.face_labels.end()).size(), 3u);
  }
}

} // namespace
