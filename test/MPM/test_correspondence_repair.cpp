// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The repairs of a dense correspondence's folds (correspondence_repair.cpp,
// correspondence_chart.cpp) on a thin bent tube with a ring pulled along
// it: a fold the closest-point smoothing cannot open.
#include <CGAL/MPM/internal/Correspondence_surface.h>

#include "Tube_mesh.h"

#include <gtest/gtest.h>

namespace {

using namespace CGAL::MPM;
using namespace CGAL::MPM::internal::correspondence;

constexpr int rings = 14, sides = 16;

struct Folded_tube
{
  Indexed_mesh mesh{mpm_test::bent_tube(rings, sides, 3., 0.04, 1.2), mpm_test::tube_triangles(rings, sides)};
  Surface surface{mesh, "tube", "tube.off"};
  Template_info info = make_template_info(surface);
  Landmarks landmarks;
  Point_matrix folded = mesh.points;

  // The third ring moved four rings along and turned by a step: the bands
  // on either side of it fold over those rings.
  Folded_tube()
  {
    for(int s = 0; s < sides; ++s) folded.row(2 * sides + s) = mesh.points.row(6 * sides + (s + 1) % sides);
  }
};

double largest_distance_to(const Surface& s, const Point_matrix& y)
{
  double d = 0.;
  for(Eigen::Index v = 0; v < y.rows(); ++v) d = std::max(d, (s.closest(y.row(v).transpose()) - y.row(v).transpose()).norm());
  return d;
}

TEST(Correspondence_repair, ClosestPointSmoothingLeavesAFoldOnAThinTube)
{
  Folded_tube tube;
  const std::size_t before = flipped_faces(tube.surface, tube.folded, tube.mesh.triangles).size();
  ASSERT_GT(before, 8u);
  Point_matrix y = tube.folded;
  unfold(tube.surface, tube.info, tube.landmarks, tube.mesh.triangles, y);
  const std::size_t after = flipped_faces(tube.surface, y, tube.mesh.triangles).size();
  EXPECT_GT(after, 8u);
  EXPECT_LT(10 * after, tube.mesh.triangles.size()); // a fold, not a template laid wrongly
}

TEST(Correspondence_repair, ChartOpensTheFoldAndKeepsTheSeamAndTheSurface)
{
  Folded_tube tube;
  Point_matrix y = tube.folded;
  unfold(tube.surface, tube.info, tube.landmarks, tube.mesh.triangles, y);
  unfold_in_chart(tube.surface, tube.info, tube.landmarks, tube.mesh.triangles, y);
  EXPECT_EQ(flipped_faces(tube.surface, y, tube.mesh.triangles).size(), 0u);
  EXPECT_LT(largest_distance_to(tube.surface, y), 1e-9);
  for(Eigen::Index v = 0; v < y.rows(); ++v)
    if(tube.info.loop[v] >= 0) EXPECT_EQ((y.row(v) - tube.mesh.points.row(v)).norm(), 0.) << "seam vertex " << v;
  // Vertices away from the fold stay where the fit put them.
  for(Eigen::Index v = 10 * sides; v < 12 * sides; ++v) EXPECT_EQ((y.row(v) - tube.folded.row(v)).norm(), 0.) << v;
}

TEST(Correspondence_repair, ChartLeavesATemplateLaidWronglyAlone)
{
  Folded_tube tube;
  Point_matrix y = tube.mesh.points;
  // Every ring but the seams turned: most triangles face the wrong way.
  for(int r = 1; r + 1 < rings; ++r)
    for(int s = 0; s < sides; ++s) y.row(r * sides + s) = tube.mesh.points.row(r * sides + (s + 5 * r) % sides);
  const Point_matrix before = y;
  unfold_in_chart(tube.surface, tube.info, tube.landmarks, tube.mesh.triangles, y);
  EXPECT_EQ((y - before).norm(), 0.);
}

} // namespace
