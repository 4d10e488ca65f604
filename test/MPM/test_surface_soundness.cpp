// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Flipped and inverted faces: a part that turns as a whole flips faces but
// inverts none; a mirrored part is inside out.
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>

#include "Tube_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace {

using namespace CGAL::MPM;

// Two tubes side by side (groups 0 and 1), each 10 rings of 12 sides.
Indexed_mesh two_tubes()
{
  Indexed_mesh m;
  const std::vector<Triangle> tube = mpm_test::tube_triangles(10, 12);
  m.points.resize(240, 3);
  for(int k = 0; k < 2; ++k)
  {
    for(int r = 0; r < 10; ++r)
      for(int s = 0; s < 12; ++s)
        m.points.row(k * 120 + r * 12 + s) << 3. * k + std::cos(M_PI * s / 6), std::sin(M_PI * s / 6), 0.5 * r;
    for(Triangle t : tube)
    {
      for(int& v : t) v += 120 * k;
      m.triangles.push_back(t);
    }
  }
  return m;
}

} // namespace

TEST(Surface_soundness, a_part_turned_as_a_whole_flips_faces_but_inverts_none)
{
  const Indexed_mesh rest = two_tubes();
  std::vector<int> groups(rest.triangles.size(), 0);
  std::fill(groups.begin() + groups.size() / 2, groups.end(), 1);
  Indexed_mesh turned = rest;
  const Eigen::Matrix3d half_turn = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for(int v = 120; v < 240; ++v) turned.points.row(v) = (half_turn * rest.points.row(v).transpose()).transpose();
  const Surface_soundness s = check_surface(turned, &rest, &groups);
  EXPECT_GT(s.flipped_faces, 100);
  EXPECT_EQ(s.inverted_faces, 0);
  // Without the groups the two tubes are one piece, which no rotation turns back.
  EXPECT_GT(inverted_faces(turned, rest).size(), 100u);

  Indexed_mesh mirrored = rest;
  for(int v = 120; v < 240; ++v) mirrored.points(v, 0) = 6. - rest.points(v, 0);
  EXPECT_GT(inverted_faces(mirrored, rest, &groups).size(), 108u); // most of the mirrored tube's 216

  groups.pop_back();
  EXPECT_THROW(inverted_faces(turned, rest, &groups), Input_error);
}

TEST(Surface_soundness, a_thin_tube_curled_inverts_faces_within_its_part_but_folds_none)
{
  // The first tube made thin, then curled around the x axis by 270 degrees
  // along its length (a curled finger): its ends face against the tube's
  // mean rotation, yet the surface nowhere turns back on itself.
  Indexed_mesh rest = two_tubes();
  rest.points.topRows(120).leftCols(2) *= 0.2;
  Indexed_mesh curled = rest;
  const double radius = 4.5 / (1.5 * M_PI);
  for(int v = 0; v < 120; ++v)
  {
    const double angle = rest.points(v, 2) / radius, y = rest.points(v, 1);
    curled.points(v, 1) = radius - (radius - y) * std::cos(angle);
    curled.points(v, 2) = (radius - y) * std::sin(angle);
  }
  std::vector<int> groups(rest.triangles.size(), 0);
  std::fill(groups.begin() + groups.size() / 2, groups.end(), 1);
  EXPECT_GT(inverted_faces(curled, rest, &groups).size(), 10u);
  EXPECT_TRUE(locally_inverted_faces(curled, rest).empty());

  // One vertex of the second tube pushed through to the far side: its
  // faces fold over their neighbours (those whose three corners' rings all
  // see it), and only they.
  Indexed_mesh pushed = rest;
  const int v = 120 + 5 * 12;
  pushed.points(v, 0) = 2.;
  const std::vector<int> folded = locally_inverted_faces(pushed, rest);
  EXPECT_GE(folded.size(), 2u);
  EXPECT_LE(folded.size(), 6u);
  for(int f : folded)
    EXPECT_NE(std::find(rest.triangles[f].begin(), rest.triangles[f].end(), v), rest.triangles[f].end());

  Indexed_mesh fewer = rest;
  fewer.triangles.pop_back();
  EXPECT_THROW(locally_inverted_faces(curled, fewer), Input_error);
}

// Every face of a tetrahedron meets its three neighbours at 109.5 degrees
// (between normals): a spike; a smooth tube has none.
TEST(Surface_soundness, spikes_are_faces_sharp_on_all_three_edges)
{
  Indexed_mesh tetrahedron;
  tetrahedron.points.resize(4, 3);
  tetrahedron.points << 1., 1., 1., 1., -1., -1., -1., 1., -1., -1., -1., 1.;
  tetrahedron.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  EXPECT_EQ(spike_faces(tetrahedron).size(), 4u);
  EXPECT_EQ(spike_faces(tetrahedron, 2.).size(), 0u); // 1.91 radians
  EXPECT_TRUE(spike_faces(two_tubes()).empty());
  EXPECT_TRUE(spike_faces(two_tubes(), CGAL_PI / 3., 2).empty());
  EXPECT_EQ(spike_faces(tetrahedron, CGAL_PI / 3., 2).size(), 4u);
  EXPECT_EQ(spike_faces(tetrahedron, CGAL_PI / 3., 4).size(), 0u); // a triangle has three edges
}
