// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Untangling a learned example: faces that cross each other where the input
// does not are moved apart on the input's surface, and faces folded over it
// turned back, a vertex inside a part back among its neighbours; seam
// vertices stay.
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Example_untangling.h>

#include "Tube_mesh.h"

#include <gtest/gtest.h>

namespace {

using namespace CGAL::MPM;

constexpr int rings = 25, sides = 16;

// A tube of two parts: label 0 up to ring 12, label 1 beyond; ring 12 is
// their seam.
Labeled_mesh two_part_tube()
{
  Labeled_mesh m;
  m.mesh.points = mpm_test::bent_tube(rings, sides, 2., 0.2, 0.);
  m.mesh.triangles = mpm_test::tube_triangles(rings, sides);
  for(const Triangle& t : m.mesh.triangles)
    m.face_labels.push_back(std::min({t[0], t[1], t[2]}) / sides < 12 ? 0 : 1);
  return m;
}

int crossings(const Indexed_mesh& mesh)
{
  std::vector<std::pair<int, int>> pairs;
  EXPECT_TRUE(self_intersecting_faces(mesh, pairs));
  return int(pairs.size());
}

// Moves `vertex` along the tube's axis by `rings_along` ring spacings: past
// its neighbours, so that its faces fold over theirs.
Indexed_mesh tangled(const Labeled_mesh& input, int vertex, double rings_along, double around = 0.)
{
  Indexed_mesh m = input.mesh;
  const double spacing = 2. / (rings - 1);
  m.points(vertex, 2) += rings_along * spacing;
  const double angle = std::atan2(m.points(vertex, 1), m.points(vertex, 0)) + around * 2. * M_PI / sides;
  m.points(vertex, 0) = 0.2 * std::cos(angle);
  m.points(vertex, 1) = 0.2 * std::sin(angle);
  return m;
}

TEST(Example_untangling, a_vertex_folded_over_its_neighbours_goes_back_among_them)
{
  const Labeled_mesh input = two_part_tube();
  const int vertex = 6 * sides + 3;
  const Indexed_mesh example = tangled(input, vertex, 1.6);
  ASSERT_GT(crossings(example), 0);
  ASSERT_EQ(crossings(input.mesh), 0);
  const Point_matrix untangled = internal::untangled_positions(example, input.face_labels, input);
  ASSERT_EQ(untangled.rows(), input.mesh.points.rows());
  EXPECT_EQ(crossings(Indexed_mesh{untangled, input.mesh.triangles}), 0);
  EXPECT_LT((untangled.row(vertex) - input.mesh.points.row(vertex)).norm(), 0.5 * 2. / (rings - 1));
  // Far from the fold nothing moves; every vertex stays on the tube.
  for(int r = 12; r < rings; ++r)
    for(int s = 0; s < sides; ++s)
      EXPECT_EQ(untangled.row(r * sides + s), example.points.row(r * sides + s)) << r << " " << s;
  for(Eigen::Index v = 0; v < untangled.rows(); ++v)
    EXPECT_NEAR(untangled.row(v).head<2>().norm(), 0.2, 0.2 * (1. - std::cos(M_PI / sides)) + 1e-9) << v;
}

// A seam vertex stays where it is: the folded faces next to it are moved
// apart by its neighbours inside the parts, or not at all.
TEST(Example_untangling, seam_vertices_stay)
{
  const Labeled_mesh input = two_part_tube();
  const int vertex = 11 * sides + 5; // next to the seam (ring 12)
  const Indexed_mesh example = tangled(input, vertex, 1.6);
  ASSERT_GT(crossings(example), 0);
  const Point_matrix untangled = internal::untangled_positions(example, input.face_labels, input);
  ASSERT_EQ(untangled.rows(), input.mesh.points.rows());
  EXPECT_EQ(crossings(Indexed_mesh{untangled, input.mesh.triangles}), 0);
  for(int s = 0; s < sides; ++s) EXPECT_EQ(untangled.row(12 * sides + s), example.points.row(12 * sides + s)) << s;
}

// A vertex next to the seam moved past it and a little off the surface:
// two faces fold over the input without crossing any other face (a
// template's sliver by an ant's antenna seam); they are turned back.
TEST(Example_untangling, faces_folded_over_the_input_without_crossing_are_turned_back)
{
  const Labeled_mesh input = two_part_tube();
  const int vertex = 11 * sides + 5;
  Indexed_mesh example = tangled(input, vertex, 1.2);
  example.points.row(vertex) *= 1.02;
  ASSERT_EQ(crossings(example), 0);
  ASSERT_EQ(folded_faces(example, input.mesh).size(), 2u);
  const Point_matrix untangled = internal::untangled_positions(example, input.face_labels, input);
  ASSERT_EQ(untangled.rows(), input.mesh.points.rows());
  const Indexed_mesh mended{untangled, input.mesh.triangles};
  EXPECT_TRUE(folded_faces(mended, input.mesh).empty());
  EXPECT_EQ(crossings(mended), 0);
  EXPECT_LT((untangled.row(vertex) - input.mesh.points.row(vertex)).norm(), 0.5 * 2. / (rings - 1));
  for(int s = 0; s < sides; ++s) EXPECT_EQ(untangled.row(12 * sides + s), example.points.row(12 * sides + s)) << s;
}

TEST(Example_untangling, nothing_to_do_gives_nothing)
{
  const Labeled_mesh input = two_part_tube();
  EXPECT_EQ(internal::untangled_positions(input.mesh, input.face_labels, input).rows(), 0);
}

} // namespace
