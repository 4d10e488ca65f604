// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Merged seams of a training mesh whose parts were rebuilt by dense
// correspondence (internal::stitch_seams).
#include <CGAL/MPM/internal/Seam_stitching.h>

#include "Tube_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace {

using namespace CGAL::MPM;

constexpr int sides = 8;

// A tube of four rows of quads: rows 0-1 label 0, row 2 the thin ring of
// label 1, row 3 label 2. At `pinch` one triangle of the ring is given to
// label 0, so that labels 0 and 2 touch at one vertex and the ring's border
// passes that vertex twice, as a person's cut leaves it on octopus_124.
Labeled_mesh pinched_ring_tube(int pinch)
{
  Labeled_mesh m;
  m.mesh.points = mpm_test::bent_tube(5, sides, 4., 1., 0.);
  m.mesh.triangles = mpm_test::tube_triangles(5, sides);
  for(std::size_t f = 0; f < m.mesh.triangles.size(); ++f)
    m.face_labels.push_back(std::max(0, int(f) / (2 * sides) - 1));
  m.face_labels[std::size_t(2 * 2 * sides + 2 * pinch)] = 0;
  return m;
}

// The same tube with label 2's part rebuilt: vertices of its own at the
// same places, its border on the seam it shares with the ring.
struct Rebuilt
{
  Labeled_mesh mesh;
  std::vector<int> original_vertex;
  std::map<int, std::vector<int>> part_vertices;
};

Rebuilt rebuild_label_2(const Labeled_mesh& original)
{
  Rebuilt r;
  r.mesh = original;
  const int n = original.mesh.number_of_vertices();
  for(int v = 0; v < n; ++v) r.original_vertex.push_back(v);
  std::map<int, int> copy_of;
  for(std::size_t f = 0; f < original.mesh.triangles.size(); ++f)
  {
    const int label = original.face_labels[f];
    for(int& v : r.mesh.mesh.triangles[f])
    {
      if(label == 2)
      {
        const auto [it, added] = copy_of.insert({v, n + int(copy_of.size())});
        v = it->second;
      }
      std::vector<int>& part = r.part_vertices[label];
      if(std::find(part.begin(), part.end(), v) == part.end()) part.push_back(v);
    }
  }
  r.mesh.mesh.points.conservativeResize(n + int(copy_of.size()), 3);
  for(const auto& [v, copy] : copy_of)
  {
    r.mesh.mesh.points.row(copy) = original.mesh.points.row(v);
    r.original_vertex.push_back(-1);
  }
  return r;
}

TEST(Seam_stitching, a_ring_pinched_to_a_vertex_stitches_its_rebuilt_neighbour_in_order)
{
  for(int pinch = 0; pinch < sides; ++pinch)
  {
    SCOPED_TRACE("pinch at " + std::to_string(pinch));
    const Labeled_mesh original = pinched_ring_tube(pinch);
    const Rebuilt rebuilt = rebuild_label_2(original);
    const std::vector<internal::Stitched_seam> seams =
      internal::stitch_seams(original, rebuilt.mesh, rebuilt.original_vertex, rebuilt.part_vertices, {2});
    const auto seam = std::find_if(seams.begin(), seams.end(),
                                   [](const internal::Stitched_seam& s) { return s.label_a == 1 && s.label_b == 2; });
    ASSERT_NE(seam, seams.end());
    // Every vertex of the ring's upper loop once, each side's own vertex at
    // the same place, in order around the tube.
    ASSERT_EQ(seam->merged.size(), std::size_t(sides));
    std::set<int> ring_positions;
    for(std::size_t k = 0; k < seam->merged.size(); ++k)
    {
      const Seam_vertex& v = seam->merged[k];
      ASSERT_GE(v.local[0], 0);
      ASSERT_GE(v.local[1], 0);
      const int ring_vertex = rebuilt.part_vertices.at(1)[std::size_t(v.local[0])];
      const int part_vertex = rebuilt.part_vertices.at(2)[std::size_t(v.local[1])];
      EXPECT_EQ((rebuilt.mesh.mesh.points.row(ring_vertex) - rebuilt.mesh.mesh.points.row(part_vertex)).norm(), 0.);
      ASSERT_GE(ring_vertex, 3 * sides);
      ASSERT_LT(ring_vertex, 4 * sides);
      ring_positions.insert(ring_vertex);
      if(k > 0)
      {
        const int previous = rebuilt.part_vertices.at(1)[std::size_t(seam->merged[k - 1].local[0])];
        const int step = (ring_vertex - previous + sides) % sides;
        EXPECT_TRUE(step == 1 || step == sides - 1) << previous << " then " << ring_vertex;
      }
    }
    EXPECT_EQ(ring_positions.size(), std::size_t(sides));
  }
}

} // namespace
