// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Unfolding an edit's target: a fold pushed through a tube is taken out
// around the fold and nowhere else, as is a spike pulled out of it; a tube
// bent past a half turn is no fold.
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Target_unfolding.h>

#include "Tube_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace {

using namespace CGAL::MPM;

constexpr int rings = 25, sides = 16;
constexpr double length = 2., radius = 0.2;

Point_matrix tube(double angle) { return mpm_test::bent_tube(rings, sides, length, radius, angle); }

Indexed_mesh mesh_of(const Point_matrix& p)
{
  Indexed_mesh m;
  m.points = p;
  m.triangles = mpm_test::tube_triangles(rings, sides);
  return m;
}

TEST(Target_unfolding, a_tube_bent_past_a_half_turn_is_kept)
{
  const Point_matrix rest = tube(0.), target = tube(3.6); // 206 degrees, on a radius 2.8 times the tube's
  // One rotation for the whole tube sees the far half turned over ...
  ASSERT_GE(inverted_faces(mesh_of(target), mesh_of(rest)).size(), 10u);
  // ... but no face is folded against its neighbourhood.
  const Point_matrix unfolded = internal::unfold_target(target, rest, mpm_test::tube_triangles(rings, sides));
  EXPECT_EQ((unfolded - target).cwiseAbs().maxCoeff(), 0.);
}

TEST(Target_unfolding, a_fold_is_taken_out_where_it_is)
{
  const Point_matrix rest = tube(0.);
  Point_matrix target = rest;
  // A vertex of the middle ring pushed through the axis to the far side.
  const int fold = (rings / 2) * sides;
  target.row(fold) = Eigen::RowVector3d(-1.5 * radius, 0., rest(fold, 2));
  const std::size_t before = inverted_faces(mesh_of(target), mesh_of(rest)).size();
  ASSERT_GE(before, 4u);
  const Point_matrix unfolded = internal::unfold_target(target, rest, mpm_test::tube_triangles(rings, sides));
  EXPECT_EQ(inverted_faces(mesh_of(unfolded), mesh_of(rest)).size(), 0u);
  // The vertex goes back near its place on the wall.
  EXPECT_LT((unfolded.row(fold) - rest.row(fold)).norm(), 0.3 * radius);
  // Rings more than six away from the fold are the target's.
  for(int r = 0; r < rings; ++r)
    if(std::abs(r - rings / 2) > 6)
      for(int s = 0; s < sides; ++s) EXPECT_EQ(unfolded.row(r * sides + s), target.row(r * sides + s)) << r << " " << s;
}

// A vertex pulled out of the wall: its faces turn by less than a half turn
// (no fold against their neighbourhood) but meet the rest of the wall at a
// crease the rest does not have, as a caricature makes of a fold it doubles.
TEST(Target_unfolding, a_spike_pulled_out_of_the_wall_is_taken_out)
{
  const Point_matrix rest = tube(0.);
  Point_matrix target = rest;
  const int spike = (rings / 2) * sides;
  target.row(spike) = Eigen::RowVector3d(4. * radius, 0., rest(spike, 2));
  ASSERT_EQ(internal::locally_inverted_faces(target, rest, mpm_test::tube_triangles(rings, sides)).size(), 0u);
  const Point_matrix unfolded = internal::unfold_target(target, rest, mpm_test::tube_triangles(rings, sides));
  EXPECT_LT((unfolded.row(spike) - rest.row(spike)).norm(), 0.3 * radius);
  for(int r = 0; r < rings; ++r)
    if(std::abs(r - rings / 2) > 6)
      for(int s = 0; s < sides; ++s) EXPECT_EQ(unfolded.row(r * sides + s), target.row(r * sides + s)) << r << " " << s;
}

// The public entry for an edit's result: held vertices (handles) stay put,
// even inside a fold, and bad arguments are refused naming what is wrong.
TEST(Target_unfolding, an_edit_result_keeps_its_handles)
{
  const Indexed_mesh rest = mesh_of(tube(0.));
  Point_matrix result = rest.points;
  const int fold = (rings / 2) * sides;
  result.row(fold) = Eigen::RowVector3d(-1.5 * radius, 0., rest.points(fold, 2));
  const int handle = fold + 1; // a corner of the folded faces
  const Point_matrix unfolded = unfold_faces(rest, result, {handle});
  EXPECT_EQ(unfolded.row(handle), result.row(handle));
  EXPECT_LT((unfolded.row(fold) - rest.points.row(fold)).norm(), 0.3 * radius);
  EXPECT_EQ(unfold_faces(rest, rest.points), rest.points);
  EXPECT_THROW(unfold_faces(rest, result, {int(rest.points.rows())}), Input_error);
  EXPECT_THROW(unfold_faces(rest, result.topRows(3)), Input_error);
}

} // namespace
