// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exaggeration by local rotations: a bent tube bends further and stays
// sound, where doubling the point offsets does not bend it further.
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Shape_exaggeration.h>

#include "Tube_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace {

using namespace CGAL::MPM;

constexpr int rings = 25, sides = 16;
constexpr double length = 2., radius = 0.2;

Point_matrix bent_tube(double angle) { return mpm_test::bent_tube(rings, sides, length, radius, angle); }

// Largest distance after the best rigid alignment of `a` onto `b`.
double aligned_distance(const Point_matrix& a, const Point_matrix& b)
{
  const Eigen::Matrix4d m = Eigen::umeyama(Eigen::Matrix3Xd(a.transpose()), Eigen::Matrix3Xd(b.transpose()), false);
  const Point_matrix moved = ((m.topLeftCorner<3, 3>() * a.transpose()).colwise() + m.topRightCorner<3, 1>()).transpose();
  return (moved - b).rowwise().norm().maxCoeff();
}

int inverted(const Point_matrix& after, const Point_matrix& before)
{
  Indexed_mesh a, b;
  a.triangles = b.triangles = mpm_test::tube_triangles(rings, sides);
  a.points = after;
  b.points = before;
  return static_cast<int>(inverted_faces(a, b).size());
}

} // namespace

TEST(Shape_exaggeration, doubling_a_bend_bends_twice_as_far_without_folding)
{
  const std::vector<Triangle> triangles = mpm_test::tube_triangles(rings, sides);
  const Point_matrix mean = bent_tube(0.), shape = bent_tube(0.6 * M_PI);
  const Point_matrix exaggerated = shape + internal::exaggeration_offsets(mean, shape, triangles, 2.);
  const double error = aligned_distance(exaggerated, bent_tube(1.2 * M_PI)) / length;
  std::cout << "bend of 108 degrees doubled: " << 100. * error << "% of the length from the 216-degree bend\n";
  EXPECT_LT(error, 0.03);
  EXPECT_EQ(inverted(exaggerated, shape), 0);
  // Scaling the offsets instead does not bend the tube further: it
  // stretches the chord and shrinks the arc.
  const double linear = aligned_distance(shape + (shape - mean), bent_tube(1.2 * M_PI)) / length;
  std::cout << "offsets doubled: " << 100. * linear << "% of the length from it\n";
  EXPECT_GT(linear, 10. * error);
}

TEST(Shape_exaggeration, factor_one_moves_nothing_and_factor_zero_gives_the_mean)
{
  const std::vector<Triangle> triangles = mpm_test::tube_triangles(rings, sides);
  const Point_matrix mean = bent_tube(0.), shape = bent_tube(0.3 * M_PI);
  EXPECT_EQ(internal::exaggeration_offsets(mean, shape, triangles, 1.).norm(), 0.);
  const double error =
    aligned_distance(shape + internal::exaggeration_offsets(mean, shape, triangles, 0.), mean) / length;
  EXPECT_LT(error, 0.01) << 100. * error << "% of the length";
}
