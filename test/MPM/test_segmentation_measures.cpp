// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Princeton Segmentation Benchmark's measures against values computed by
// hand on a strip of four unit squares (eight triangles of area 1/2).
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Cutting/Segmentation_measures.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using namespace CGAL::MPM;

// Vertices (i, 0) = 2i and (i, 1) = 2i + 1 for i = 0..4; square i is faces 2i and 2i + 1.
Indexed_mesh strip()
{
  Indexed_mesh m;
  m.points.resize(10, 3);
  for(int i = 0; i <= 4; ++i) {
    m.points.row(2 * i) << i, 0., 0.;
    m.points.row(2 * i + 1) << i, 1., 0.;
  }
  for(int i = 0; i < 4; ++i) {
    m.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
    m.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  }
  return m;
}

// Label 0 on the first `squares` squares, 1 on the others.
std::vector<int> split_after(int squares)
{
  std::vector<int> labels(8, 1);
  for(int f = 0; f < 2 * squares; ++f) labels[std::size_t(f)] = 0;
  return labels;
}

TEST(Segmentation_measures, IdenticalSegmentationsGiveZero)
{
  const Indexed_mesh m = strip();
  const std::vector<int> a = split_after(1), renamed = {7, 7, 3, 3, 3, 3, 3, 3};
  const Segmentation_comparison s = compare_segmentations(m, a, renamed);
  EXPECT_DOUBLE_EQ(s.cut_discrepancy, 0.);
  EXPECT_DOUBLE_EQ(s.hamming.missing, 0.);
  EXPECT_DOUBLE_EQ(s.hamming.false_alarm, 0.);
  EXPECT_DOUBLE_EQ(s.rand_index_error, 0.);
  EXPECT_DOUBLE_EQ(s.consistency.global, 0.);
  EXPECT_DOUBLE_EQ(s.consistency.local, 0.);
}

// Cut after square 1 against the reference cut after square 2: areas 1 | 3
// against 2 | 2, overlaps (0,0) = 1, (1,0) = 1, (1,1) = 2.
TEST(Segmentation_measures, ShiftedCutGivesHandComputedValues)
{
  const Indexed_mesh m = strip();
  const std::vector<int> a = split_after(1), b = split_after(2);

  // Pairs together: 1 + 9 in a, 4 + 4 in b, 1 + 1 + 4 in both; distinct
  // ordered pairs: 4^2 - 8 (1/2)^2 = 14.
  EXPECT_NEAR(rand_index_error(m, a, b), (10. + 8. - 2. * 6.) / 14., 1e-12);

  // Reference segment 0 is matched to a's segment 0 or 1 (overlap 1 each)
  // and misses 1; a's segment 1 (area 3) overlaps b's segment 1 by 2.
  const Hamming_distance h = hamming_distance(m, a, b);
  EXPECT_NEAR(h.missing, 0.25, 1e-12);
  EXPECT_NEAR(h.false_alarm, 0.25, 1e-12);
  EXPECT_NEAR(h.average, 0.25, 1e-12);

  // Errors per overlap, a against b: 0, 2/3, 1/3; b against a: 1/2, 1/2, 0.
  // GCE = min(1*0 + 1*2/3 + 2*1/3, 1/2 + 1/2 + 0) / 4; LCE = (0 + 1/2 + 0) / 4.
  const Consistency_error c = consistency_error(m, a, b);
  EXPECT_NEAR(c.global, 0.25, 1e-12);
  EXPECT_NEAR(c.local, 0.125, 1e-12);

  // The cuts are the edges x = 1 and x = 2, one edge step apart everywhere:
  // each direction contributes 1. Normalised by the mean distance from the
  // face centroids, (i + 2/3, 1/3) and (i + 1/3, 2/3), to the centroid (2, 1/2).
  double radius = 0.;
  for(int i = 0; i < 4; ++i)
    radius += std::hypot(i + 2. / 3. - 2., 1. / 6.) / 8. + std::hypot(i + 1. / 3. - 2., 1. / 6.) / 8.;
  EXPECT_NEAR(cut_discrepancy(m, a, b), 2. / radius, 1e-12);
}

TEST(Segmentation_measures, SymmetricMeasuresAreSymmetric)
{
  const Indexed_mesh m = strip();
  const std::vector<int> a = split_after(1), b = {0, 0, 1, 1, 1, 2, 2, 2};
  EXPECT_NEAR(cut_discrepancy(m, a, b), cut_discrepancy(m, b, a), 1e-12);
  EXPECT_NEAR(rand_index_error(m, a, b), rand_index_error(m, b, a), 1e-12);
  EXPECT_NEAR(consistency_error(m, a, b).global, consistency_error(m, b, a).global, 1e-12);
  EXPECT_NEAR(consistency_error(m, a, b).local, consistency_error(m, b, a).local, 1e-12);
  // Hamming is directional: swapping the roles swaps Rm and Rf.
  EXPECT_NEAR(hamming_distance(m, a, b).missing, hamming_distance(m, b, a).false_alarm, 1e-12);
  EXPECT_GT(hamming_distance(m, a, b).false_alarm, 0.);
}

TEST(Segmentation_measures, RefinementHasNoConsistencyError)
{
  const Indexed_mesh m = strip();
  const std::vector<int> coarse = split_after(2), fine = {0, 0, 1, 1, 2, 2, 3, 3};
  const Consistency_error c = consistency_error(m, fine, coarse);
  EXPECT_DOUBLE_EQ(c.global, 0.);
  EXPECT_DOUBLE_EQ(c.local, 0.);
  // ... but the Rand Index sees the extra cuts: pairs together 4 * 1 in fine,
  // 2 * 4 in coarse, 4 in both, out of 14.
  EXPECT_NEAR(rand_index_error(m, fine, coarse), (4. + 8. - 8.) / 14., 1e-12);
}

TEST(Segmentation_measures, CutDiscrepancyIsUndefinedAgainstNoCut)
{
  const Indexed_mesh m = strip();
  const std::vector<int> none(8, 0);
  EXPECT_TRUE(std::isnan(cut_discrepancy(m, split_after(1), none)));
  EXPECT_DOUBLE_EQ(cut_discrepancy(m, none, none), 0.);
  EXPECT_THROW(rand_index_error(m, std::vector<int>(7, 0), none), Input_error);
}

TEST(Segmentation_measures, CutsAreTheSeamsBetweenLabelPairs)
{
  const Indexed_mesh m = strip();
  // Three segments: cuts at x = 1 (labels 0 | 1) and x = 3 (labels 1 | 2).
  const std::vector<Segmentation_cut> cuts = segmentation_cuts(m, {0, 0, 1, 1, 1, 1, 2, 2});
  ASSERT_EQ(cuts.size(), 2u);
  EXPECT_EQ(cuts[0].vertices, (std::vector<int>{2, 3}));
  EXPECT_EQ(cuts[1].vertices, (std::vector<int>{6, 7}));
  EXPECT_EQ(cuts[1].first_label, 1);
  EXPECT_EQ(cuts[1].second_label, 2);
  EXPECT_EQ(cuts[0].edges, 1); // an open stretch from border to border
  // Both vertices are 1/2 from the centroid (1, 1/2); the first is kept.
  EXPECT_EQ(central_cut_vertex(m, cuts[0].vertices), 2);
  // From the cut x = 1 to the cut x = 3: 2; from (3, 0) and (3, 1) to (3, 0) alone: 1/2.
  EXPECT_DOUBLE_EQ(cut_distance(m, cuts[0].vertices, cuts[1].vertices), 2.);
  EXPECT_DOUBLE_EQ(cut_distance(m, cuts[1].vertices, {6}), 0.5);
}

// The cuts a user would click: closed loops, and an open stretch only where
// it is the longest of one of its two parts (a phalanx's seam along the
// next finger is not; the stretch to its own neighbour is).
TEST(Segmentation_measures, JointCutsAreLoopsAndEachPartsLongestStretch)
{
  const std::vector<Segmentation_cut> cuts{{0, 1, {1, 2, 3, 4}, 3},
                                           {1, 2, {5, 6}, 1},
                                           {2, 3, {7, 8, 9}, 2},
                                           {0, 4, {10, 11, 12}, 3}};
  const std::vector<Segmentation_cut> joints = joint_cuts(cuts);
  ASSERT_EQ(joints.size(), 3u);
  EXPECT_EQ(joints[0].vertices, cuts[0].vertices); // the longest of parts 0 and 1
  EXPECT_EQ(joints[1].vertices, cuts[2].vertices); // the longest of parts 2 and 3
  EXPECT_EQ(joints[2].vertices, cuts[3].vertices); // a closed loop
}

} // namespace
