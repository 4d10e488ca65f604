// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Joints proposed with no click: on synthetic families with their labels
// removed, the proposed cuts lie on the true seams; on real scans the limbs
// are found and cut where they leave the body, and a raw mesh becomes a
// learned model in one command; bad input is an Input_error naming the mesh.
#include <CGAL/MPM/Cutting/Joint_proposal.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Cutting/Segmentation_measures.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include "Io_test_support.h"
#include "Psb_meshes.h"
#include "Learned_models.h"
#include "Tool_test_support.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

namespace {

using namespace CGAL::MPM;

double diagonal(const Indexed_mesh& m) { return internal::bounding_box_diagonal(m.points); }

// True seams with a proposed cut within `tolerance` of them.
int seams_found(const Labeled_mesh& truth, const Joint_proposal& p, double tolerance)
{
  int found = 0;
  for(const Segmentation_cut& seam : segmentation_cuts(truth.mesh, truth.face_labels)) {
    bool near = false;
    for(const Joint_cut& c : p.cutting.cuts) near = near || cut_distance(truth.mesh, c.path, seam.vertices) < tolerance;
    found += near;
  }
  return found;
}

// The synthetic hand with its labels removed: the four fingers and the
// thumb are limbs, and the fingers are cut where they leave the palm and at
// both joints, on the true seams (12 of the 15 seams). The thumb, on the
// palm's side, is cut one segment out from the palm: its skeleton bends into
// the palm, so sections across it close around it alone only from its first
// joint on (see doc/MPM/Cutting.md).
TEST(Joint_proposal, SyntheticHandIsCutAtItsJoints)
{
  const Synthetic_model& hand = mpm_test::learned(Synthetic_family::hand, 3000).truth;
  const Indexed_mesh& m = hand.mesh.mesh;
  const Joint_proposal p = cut_at_proposed_joints(m);
  EXPECT_GE(p.limbs, 5);
  EXPECT_EQ(p.cutting.cuts.size(), p.joints.size() - p.cutting.skipped.size());
  EXPECT_GE(seams_found(hand.mesh, p, 0.005 * diagonal(m)), 12) << "of 15";
  EXPECT_LT(rand_index_error(m, p.cutting.mesh.face_labels, hand.mesh.face_labels), 0.15);
  // Sensitivity 0 cuts the limbs off the body only.
  Joint_proposal_options bases;
  bases.sensitivity = 0.;
  const Joint_proposal b = cut_at_proposed_joints(m, bases);
  for(const Proposed_joint& j : b.joints) EXPECT_TRUE(j.at_base);
  EXPECT_EQ(int(b.joints.size()), b.limbs);
}

// The same hand turned, scaled by 37 and moved: the proposal hardly depends
// on where the mesh lies or on its units (the curve skeleton of the turned
// mesh differs slightly: 11 of the 15 seams instead of 12).
TEST(Joint_proposal, TurnedAndScaledHandIsCutAlike)
{
  Labeled_mesh hand = mpm_test::learned(Synthetic_family::hand, 3000).truth.mesh;
  const Eigen::Matrix3d turn =
    (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1., 2., 3.).normalized())).toRotationMatrix();
  hand.mesh.points = (37. * hand.mesh.points * turn.transpose()).rowwise() + Eigen::RowVector3d(5., -3., 2.);
  const Joint_proposal p = cut_at_proposed_joints(hand.mesh);
  EXPECT_GE(p.limbs, 5);
  EXPECT_GE(seams_found(hand, p, 0.005 * diagonal(hand.mesh)), 11) << "of 15";
}

// The synthetic spider: eight legs, and most seams found.
TEST(Joint_proposal, SyntheticSpiderHasEightLegs)
{
  const Synthetic_model& spider = mpm_test::learned(Synthetic_family::spider, 3000).truth;
  const Indexed_mesh& m = spider.mesh.mesh;
  const Joint_proposal p = cut_at_proposed_joints(m);
  EXPECT_EQ(p.limbs, 8);
  EXPECT_GE(seams_found(spider.mesh, p, 0.01 * diagonal(m)), 16) << "of 32";
  EXPECT_LT(rand_index_error(m, p.cutting.mesh.face_labels, spider.mesh.face_labels), 0.2);
}

TEST(Joint_proposal, BadInputIsAnInputError)
{
  const Indexed_mesh& m = mpm_test::learned(Synthetic_family::hand, 3000).truth.mesh.mesh;
  Joint_proposal_options bad;
  bad.sensitivity = 1.5;
  EXPECT_THROW(cut_at_proposed_joints(m, bad), Input_error);
  bad = Joint_proposal_options();
  bad.minimum_segment_length = 0.;
  EXPECT_THROW(cut_at_proposed_joints(m, bad), Input_error);
  // A hole: the error names the mesh and the hole.
  Indexed_mesh holed = m;
  holed.triangles.pop_back();
  try {
    cut_at_proposed_joints(holed, Joint_proposal_options(), "hand.off");
    ADD_FAILURE() << "an open mesh was cut";
  } catch(const Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("hand.off"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("hole"), std::string::npos) << e.what();
  }
}

// Where the limbs leave the body on a real scan: the human cuts around the
// largest segment (the palm, the octopus's body) each have a proposed cut
// within 1.5% of the diagonal, all but two of them.
void check_limbs_of_real_mesh(const std::string& name, int limbs, double rand_index_bound)
{
  const std::string base = mpm_test::psb_file(name);
  const Labeled_mesh human = read_labeled_mesh(base + ".off", base + ".seg");
  const Indexed_mesh& m = human.mesh;
  const Joint_proposal p = cut_at_proposed_joints(m, Joint_proposal_options(), base + ".off");
  EXPECT_GE(p.limbs, limbs) << name;
  std::map<int, int> faces;
  for(int l : human.face_labels) ++faces[l];
  const int body =
    std::max_element(faces.begin(), faces.end(), [](auto a, auto b) { return a.second < b.second; })->first;
  int around_body = 0, found = 0;
  for(const Segmentation_cut& c : segmentation_cuts(m, human.face_labels)) {
    if(c.first_label != body && c.second_label != body) continue;
    ++around_body;
    bool near = false;
    for(const Joint_cut& j : p.cutting.cuts) near = near || cut_distance(m, j.path, c.vertices) < 0.015 * diagonal(m);
    found += near;
  }
  EXPECT_GE(found, around_body - 2) << name << ": cuts around the body found";
  EXPECT_LT(rand_index_error(m, p.cutting.mesh.face_labels, human.face_labels), rand_index_bound) << name;
}

TEST(Joint_proposal, RealHandAndOctopusLimbs)
{
  MPM_REQUIRE_PSB("hand_190");
  check_limbs_of_real_mesh("hand_190", 5, 0.1);
  check_limbs_of_real_mesh("octopus_126", 8, 0.1);
}

// A raw scan to a learned model with one command and no file written by hand.
TEST(Joint_proposal, LearnWithAutoCutFromRawMeshes)
{
  const mpm_test::Scratch_directory dir;
  for(const std::string name : {"hand_190", "octopus_126"}) {
    MPM_REQUIRE_PSB(name);
    const std::string mesh = mpm_test::psb_file(name + ".off");
    // A copy without its .seg beside it: nothing but the mesh.
    std::filesystem::copy_file(mesh, dir.file(name + ".off"));
    const mpm_test::Run_result learn = mpm_test::run_tool(
      dir.path(), "learn " + dir.file(name + ".off") + " --auto-cut -o " + dir.file(name + ".mpm") + " --json");
    ASSERT_EQ(learn.status, 0) << learn.err;
    const nlohmann::json summary = nlohmann::json::parse(learn.out);
    EXPECT_EQ(summary["inputs"][0]["labels"], "cut at proposed joints");
    EXPECT_TRUE(summary["inputs"][0]["types_proposed"].get<bool>());
    EXPECT_TRUE(std::filesystem::exists(dir.file(name + ".mpm")));
    // The model is editable: symmetrize runs on it.
    const mpm_test::Run_result edit = mpm_test::run_tool(
      dir.path(), "symmetrize " + dir.file(name + ".mpm") + " -o " + dir.file(name + "_sym.off"));
    EXPECT_EQ(edit.status, 0) << edit.err;
  }
  // --auto with --at: a usage error.
  const mpm_test::Run_result both =
    mpm_test::run_tool(dir.path(), "cut " + dir.file("hand_190.off") + " --auto --at 3 -o " + dir.file("x"));
  EXPECT_EQ(both.status, 2);
}

} // namespace
