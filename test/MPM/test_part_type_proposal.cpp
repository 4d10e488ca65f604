// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Part types proposed from a segmentation (Part_type_proposal.h): on the
// synthetic hand, whose true types are known, on the segmented PSB meshes
// (MPM_PSB_DIR, skipped with a message when absent; only read), the checks
// of bad segmentations, and `mpm learn --write-annotation`.
#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include "Tool_test_support.h"
#include "Psb_meshes.h"

#include "Learned_models.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <set>

#include <unistd.h>

namespace {

using namespace CGAL::MPM;
namespace fs = std::filesystem;

Labeled_mesh read_psb(const std::string& name)
{
  return read_labeled_mesh(mpm_test::psb_file(name + ".off"), mpm_test::psb_file(name + ".seg"));
}

// Groups of labels as a set of sets: two annotations agree when they put
// the same segments together, whatever the names.
std::set<std::set<int>> grouping(const std::map<int, std::string>& types)
{
  std::map<std::string, std::set<int>> by_type;
  for(const auto& [label, type] : types) by_type[type].insert(label);
  std::set<std::set<int>> r;
  for(const auto& [type, labels] : by_type) r.insert(labels);
  return r;
}

std::string message_of(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch(const Input_error& e)
  {
    return e.what();
  }
  ADD_FAILURE() << "no Input_error thrown";
  return "";
}

void print_counts(const std::string& name, const Part_type_proposal& p)
{
  std::cout << "  " << name << " (root " << p.root << "):";
  for(const auto& [type, count] : p.instances_of_type()) std::cout << " " << type << " x" << count;
  std::cout << "\n";
}

// Every proposed type can be put in correspondence: one seam count each.
void expect_uniform_seams(const Labeled_mesh& mesh, const Part_type_proposal& p)
{
  Training_input input;
  input.mesh = mesh;
  input.annotation = p.annotation;
  EXPECT_NO_THROW(validate_seam_counts({input})) << mesh.source;
}

const Segment_proposal& segment(const Part_type_proposal& p, int label)
{
  for(const Segment_proposal& s : p.segments)
    if(s.label == label) return s;
  throw std::out_of_range("no label " + std::to_string(label));
}

} // namespace

TEST(Proposal, SyntheticHandGroupsLikeItsTrueTypes)
{
  Synthetic_options o;
  o.vertices = 6000;
  const Synthetic_model hand = make_synthetic_model(Synthetic_family::hand, o);
  const Part_type_proposal p = propose_part_types(hand.mesh);
  print_counts("synthetic hand", p);
  EXPECT_EQ(grouping(p.annotation.part_type_of_label), grouping(hand.annotation.part_type_of_label));
  EXPECT_EQ(hand.annotation.part_type_of_label.at(p.root), "palm");
  const std::map<std::string, int> expected{{"root", 1}, {"chain1", 5}, {"chain2", 5}, {"tip3", 5}};
  EXPECT_EQ(p.instances_of_type(), expected);
  expect_uniform_seams(hand.mesh, p);
  for(const Segment_proposal& s : p.segments) EXPECT_TRUE(s.reason.empty()) << s.label << ": " << s.reason;
}

TEST(Proposal, SeveralMeshesKeepConsistentNames)
{
  Synthetic_options a, b;
  a.vertices = b.vertices = 3000;
  b.seed = 2;
  const Labeled_mesh m1 = make_synthetic_model(Synthetic_family::hand, a).mesh;
  const Labeled_mesh m2 = make_synthetic_model(Synthetic_family::hand, b).mesh;
  const std::vector<Part_type_proposal> p = propose_part_types(std::vector<Labeled_mesh>{m1, m2});
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].instances_of_type(), p[1].instances_of_type());
  EXPECT_TRUE(segments_share_connectivity({m1, m2}));
}

TEST(Proposal, PsbHandsGroupPhalangesByLevel)
{
  for(const char* name : {"hand_181", "hand_190", "hand_194", "hand_196", "hand_197"})
  {
    MPM_REQUIRE_PSB(name);
    const Labeled_mesh mesh = read_psb(name);
    EXPECT_FALSE(segments_share_connectivity({mesh}));
    const Part_type_proposal p = propose_part_types(mesh);
    print_counts(name, p);
    const std::map<std::string, int> n = p.instances_of_type();
    EXPECT_EQ(segment(p, p.root).neighbours.size(), 5u) << name << ": the palm is the root";
    EXPECT_EQ(n.at("root"), 1) << name;
    EXPECT_EQ(n.at("tip3"), 5) << name << ": five distal phalanges in one type";
    EXPECT_EQ(n.at("chain2"), 5) << name << ": five middle phalanges in one type";
    EXPECT_GE(n.at("chain1"), 4) << name << ": proximal phalanges (the thumb's may be split off)";
    EXPECT_EQ(n.size(), n.at("chain1") == 5 ? 4u : 5u) << name;
    expect_uniform_seams(mesh, p);
  }
}

TEST(Proposal, PsbOctopusArmsGroupByLevel)
{
  // Arm pieces per level; octopus_124's first pieces are thin rings, three
  // of whose two seams touch (one loop as `boundary_loops()` walks them), so
  // they cannot share a type with the other five.
  const std::map<std::string, std::map<std::string, int>> expected{
    {"octopus_126", {{"root", 1}, {"chain1", 8}, {"tip2", 8}}},
    {"octopus_124", {{"root", 1}, {"chain1", 5}, {"chain1_s1", 3}, {"tip2", 8}}},
  };
  for(const auto& [name, counts] : expected)
  {
    MPM_REQUIRE_PSB(name);
    const Labeled_mesh mesh = read_psb(name);
    const Part_type_proposal p = propose_part_types(mesh);
    print_counts(name, p);
    EXPECT_EQ(segment(p, p.root).neighbours.size(), 8u) << name << ": the body is the root";
    EXPECT_EQ(p.instances_of_type(), counts) << name;
    expect_uniform_seams(mesh, p);
  }
  MPM_REQUIRE_PSB("octopus_137");
  const Labeled_mesh mesh = read_psb("octopus_137");
  const Part_type_proposal p = propose_part_types(mesh);
  print_counts("octopus_137", p);
  const std::map<std::string, int> n = p.instances_of_type();
  EXPECT_EQ(n.at("tip3"), 8);
  EXPECT_EQ(n.at("chain2"), 8);
  // The first pieces differ ninefold in area: split in two groups of four.
  EXPECT_EQ(n.at("chain1") + n.at("chain1_small"), 8);
  EXPECT_FALSE(segment(p, p.root).reason.size());
  expect_uniform_seams(mesh, p);
}

TEST(Proposal, PsbAntsSeparateLegsFromAntennae)
{
  for(const char* name : {"ant_81", "ant_83", "ant_90"})
  {
    MPM_REQUIRE_PSB(name);
    const Labeled_mesh mesh = read_psb(name);
    const Part_type_proposal p = propose_part_types(mesh);
    print_counts(name, p);
    const std::map<std::string, int> n = p.instances_of_type();
    // The thorax (legs and head attach to it) is the root, not the larger abdomen.
    const Segment_proposal& root = segment(p, p.root);
    EXPECT_EQ(root.neighbours.size(), 8u) << name;
    EXPECT_EQ(n.at("tip1"), 1) << name << ": the abdomen";
    EXPECT_EQ(n.at("branch1_s3"), 1) << name << ": the head";
    EXPECT_EQ(n.at("chain2"), 6) << name << ": six middle leg pieces";
    EXPECT_EQ(n.at("tip3"), 6) << name << ": six leg tips";
    EXPECT_EQ(n.at("branch1_s3.chain2"), 2) << name << ": antennae bases, apart from the legs";
    EXPECT_EQ(n.at("branch1_s3.tip3"), 2) << name << ": antennae tips";
    expect_uniform_seams(mesh, p);
  }
  MPM_REQUIRE_PSB("ant_97");
  const Labeled_mesh irregular = read_psb("ant_97");
  const Part_type_proposal p = propose_part_types(irregular);
  print_counts("ant_97", p);
  EXPECT_EQ(p.instances_of_type().at("chain1"), 6); // legs cut into 2-4 pieces still start alike
  expect_uniform_seams(irregular, p);
}

TEST(Proposal, AllPsbMeshesTogetherPoolByName)
{
  MPM_REQUIRE_PSB("hand_181");
  std::vector<Labeled_mesh> hands;
  for(const char* name : {"hand_181", "hand_190", "hand_194", "hand_196", "hand_197"}) hands.push_back(read_psb(name));
  const std::vector<Part_type_proposal> p = propose_part_types(hands);
  std::map<std::string, int> pooled;
  for(const Part_type_proposal& q : p)
    for(const auto& [type, count] : q.instances_of_type()) pooled[type] += count;
  std::cout << "  five hands pooled:";
  for(const auto& [type, count] : pooled) std::cout << " " << type << " x" << count;
  std::cout << "\n";
  // Palms whose seams touch have fewer loops than the first hand's: renamed
  // `root_sN`, they cannot be put in correspondence with the others.
  int roots = 0;
  for(const auto& [type, count] : pooled)
    if(type.rfind("root", 0) == 0) roots += count;
  EXPECT_EQ(roots, 5);
  EXPECT_GE(pooled.at("root"), 3);
  EXPECT_EQ(pooled.at("tip3"), 25);
  EXPECT_EQ(pooled.at("chain2"), 25);
  std::vector<Training_input> inputs(hands.size());
  for(std::size_t i = 0; i < hands.size(); ++i)
  {
    inputs[i].mesh = hands[i];
    inputs[i].annotation = p[i].annotation;
  }
  EXPECT_NO_THROW(validate_seam_counts(inputs));
}

// ---- bad segmentations ----------------------------------------------------

namespace {

TEST(Proposal, OctopusArmPiecesOfDifferentSizeAreNotPooled)
{
  // By position, every arm's first segment is `chain1`. octopus_124's are
  // thin rings by the body (20-28 faces), octopus_126's halves of arms
  // (430-1,020 faces), octopus_137's in between with four rings of its own:
  // pooled, the rings of both meshes share one name and no ring shares one
  // with an arm half.
  MPM_REQUIRE_PSB("octopus_124");
  std::vector<Labeled_mesh> octopuses;
  for(const char* name : {"octopus_124", "octopus_126", "octopus_137"}) octopuses.push_back(read_psb(name));
  const std::vector<Part_type_proposal> p = propose_part_types(octopuses);
  std::map<std::string, std::vector<int>> faces_of_type;
  for(const Part_type_proposal& q : p)
    for(const Segment_proposal& s : q.segments)
      if(s.depth == 1 && s.seam_loops == 2) faces_of_type[s.type].push_back(s.faces);
  for(const auto& [type, faces] : faces_of_type)
  {
    const auto [smallest, largest] = std::minmax_element(faces.begin(), faces.end());
    std::cout << "  " << type << ": " << faces.size() << " segments, " << *smallest << "-" << *largest << " faces\n";
    EXPECT_LT(*largest, 10 * *smallest) << type;
  }
  ASSERT_TRUE(faces_of_type.count("chain1_small"));
  EXPECT_EQ(faces_of_type.at("chain1_small").size(), 9u);
  // One mesh alone is named as before.
  EXPECT_EQ(propose_part_types(octopuses[0]).instances_of_type().count("chain1_small"), 0u);
}

} // namespace

TEST(Bad_segmentation, DisconnectedSegmentIsNamed)
{
  Labeled_mesh m = mpm_test::small_hand().mesh;
  m.source = "hand.off";
  const Part_type_proposal p = propose_part_types(m);
  // Two fingertips under one label: two pieces.
  std::vector<int> tips;
  for(const Segment_proposal& s : p.segments)
    if(s.type == "tip3") tips.push_back(s.label);
  ASSERT_GE(tips.size(), 2u);
  for(int& l : m.face_labels)
    if(l == tips[1]) l = tips[0];
  const std::string message = message_of([&] { validate_segmentation(m); });
  std::cout << "  " << message << "\n";
  EXPECT_NE(message.find("hand.off: segment " + std::to_string(tips[0]) + ": is not connected: 2"), std::string::npos)
    << message;
  EXPECT_FALSE(message_of([&] { propose_part_types(m); }).empty());
}

TEST(Bad_segmentation, LabelsNotCoveringTheMesh)
{
  Labeled_mesh m = mpm_test::small_hand().mesh;
  m.source = "hand.off";
  m.face_labels.pop_back();
  const std::string message = message_of([&] { validate_segmentation(m); });
  std::cout << "  " << message << "\n";
  EXPECT_NE(message.find("face labels for"), std::string::npos) << message;
}

TEST(Bad_segmentation, NonManifoldEdgeAndVertexAreNamed)
{
  Labeled_mesh m = mpm_test::small_hand().mesh;
  m.source = "hand.off";
  // A fin on an edge of face 0: that edge now has three faces.
  const Triangle t = m.mesh.triangles[0];
  const int label = m.face_labels[0];
  m.mesh.points.conservativeResize(m.mesh.points.rows() + 1, 3);
  m.mesh.points.row(m.mesh.points.rows() - 1) = m.mesh.points.row(t[0]) + Eigen::RowVector3d(0., 0., 0.5);
  m.mesh.triangles.push_back({t[1], t[0], int(m.mesh.points.rows() - 1)});
  m.face_labels.push_back(label);
  std::string message = message_of([&] { validate_segmentation(m); });
  std::cout << "  " << message << "\n";
  EXPECT_NE(message.find("hand.off: segment " + std::to_string(label) + ": edge"), std::string::npos) << message;
  EXPECT_NE(message.find("not manifold"), std::string::npos) << message;

  // Two tetrahedra meeting at one vertex.
  Labeled_mesh bowtie;
  bowtie.source = "bowtie.off";
  bowtie.mesh.points.resize(7, 3);
  bowtie.mesh.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1;
  bowtie.mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}};
  bowtie.face_labels = {1, 1, 1, 1, 2, 2, 2, 2};
  message = message_of([&] { validate_segmentation(bowtie); });
  std::cout << "  " << message << "\n";
  EXPECT_NE(message.find("bowtie.off: segments 1, 2: vertex 0"), std::string::npos) << message;
}

TEST(Bad_segmentation, TypeMixingSeamCountsNamesTheSegments)
{
  Synthetic_options o;
  o.vertices = 3000;
  const Synthetic_model hand = make_synthetic_model(Synthetic_family::hand, o);
  Training_input input;
  input.mesh = hand.mesh;
  input.annotation = hand.annotation;
  input.annotation.source = "hand.json";
  // One distal phalanx (one seam) declared a middle one (two seams).
  int distal = -1;
  for(const auto& [label, type] : input.annotation.part_type_of_label)
    if(type == "distal" && distal < 0) distal = label;
  ASSERT_GE(distal, 0);
  input.annotation.part_type_of_label[distal] = "middle";
  const std::string message = message_of([&] { validate_seam_counts({input}); });
  std::cout << "  " << message << "\n";
  EXPECT_NE(message.find("hand.json: part type \"middle\": segments have different numbers of seam loops"),
            std::string::npos)
    << message;
  EXPECT_NE(message.find("label " + std::to_string(distal) + ": 1"), std::string::npos) << message;
  EXPECT_NE(message.find(": 2"), std::string::npos) << message;
  input.annotation = hand.annotation;
  EXPECT_NO_THROW(validate_seam_counts({input}));
}

// ---- the command line -----------------------------------------------------

TEST(Proposal, CliLearnProposesPrintsAndWritesTheAnnotation)
{
  MPM_REQUIRE_PSB("hand_181");
  const fs::path dir = fs::temp_directory_path() / ("mpm_proposal_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string mesh = mpm_test::psb_file("hand_181.off"), seg = mpm_test::psb_file("hand_181.seg");
  const std::string annotation = (dir / "hand_181.json").string(), model = (dir / "hand_181.mpm").string();
  const mpm_test::Run_result r =
    mpm_test::run_tool(dir, "learn " + mpm_test::quote(mesh) + " --labels " + mpm_test::quote(seg) +
                              " --write-annotation " + mpm_test::quote(annotation) + " -o " + mpm_test::quote(model));
  std::cout << r.out.substr(0, r.out.find("\n\n") + 1);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Proposed part types for " + mesh + " (root: segment 0)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tip3 x5"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("annotation: proposed, written to " + annotation), std::string::npos) << r.out;
  const Annotation a = read_annotation(annotation);
  EXPECT_EQ(a.part_type_of_label.size(), 16u);
  std::map<std::string, int> n;
  for(const auto& [label, type] : a.part_type_of_label) ++n[type];
  EXPECT_EQ(n["tip3"], 5);
  EXPECT_EQ(n["chain2"], 5);
  EXPECT_TRUE(fs::is_regular_file(model));
  EXPECT_EQ(r.err.find("no part type has two instances"), std::string::npos) << r.err;

  // One type per segment, given by hand: learning says it learned no variation.
  Annotation single = a;
  for(auto& [label, type] : single.part_type_of_label) type = "segment" + std::to_string(label);
  write_annotation(single, (dir / "single.json").string());
  const mpm_test::Run_result s =
    mpm_test::run_tool(dir, "learn " + mpm_test::quote(mesh) + " --labels " + mpm_test::quote(seg) +
                              " --annotation " + mpm_test::quote((dir / "single.json").string()) + " -o " +
                              mpm_test::quote((dir / "single.mpm").string()));
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_NE(s.err.find("warning: no part type has two instances"), std::string::npos) << s.err;
  if(!::testing::Test::HasFailure()) fs::remove_all(dir);
}
