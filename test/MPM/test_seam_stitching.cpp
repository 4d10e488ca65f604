// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Merged seams of a training mesh whose parts were rebuilt by dense
// correspondence (internal::stitch_seams).
#include <CGAL/MPM/internal/Seam_stitching.h>

#include "Tube_mesh.h"

#include <gtest/gtest.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <map>
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

// The pinched ring itself rebuilt as a template would give it: an annulus
// whose lower border passes just below the pinch vertex `v` at a vertex X
// of its own, so that its two border loops no longer touch. The ring's
// faces at `v`, {a, v, c} and {b, d', v}, become four faces around X.
Rebuilt rebuild_ring_as_annulus(const Labeled_mesh& original, int pinch)
{
  const int a = 2 * sides + pinch, b = 2 * sides + (pinch + 1) % sides, c = a + sides, v = b + sides;
  const int d2 = 3 * sides + (pinch + 2) % sides;
  Labeled_mesh annulus = original;
  const int x = original.mesh.number_of_vertices();
  annulus.mesh.points.conservativeResize(x + 1, 3);
  annulus.mesh.points.row(x) = 0.8 * original.mesh.points.row(v) + 0.1 * original.mesh.points.row(a) +
                               0.1 * original.mesh.points.row(b);
  annulus.mesh.triangles.clear();
  annulus.face_labels.clear();
  for(std::size_t f = 0; f < original.mesh.triangles.size(); ++f)
  {
    const Triangle& t = original.mesh.triangles[f];
    if(original.face_labels[f] == 1 && std::find(t.begin(), t.end(), v) != t.end()) continue;
    annulus.mesh.triangles.push_back(t);
    annulus.face_labels.push_back(original.face_labels[f]);
  }
  for(const Triangle& t : {Triangle{a, x, c}, Triangle{x, v, c}, Triangle{x, d2, v}, Triangle{b, d2, x}})
  {
    annulus.mesh.triangles.push_back(t);
    annulus.face_labels.push_back(1);
  }
  Rebuilt r;
  r.mesh = annulus;
  const int n = annulus.mesh.number_of_vertices();
  for(int u = 0; u < x; ++u) r.original_vertex.push_back(u);
  r.original_vertex.push_back(-1);
  std::map<int, int> copy_of;
  for(std::size_t f = 0; f < annulus.mesh.triangles.size(); ++f)
  {
    const int label = annulus.face_labels[f];
    for(int& u : r.mesh.mesh.triangles[f])
    {
      if(label == 1 && u != x)
      {
        const auto [it, added] = copy_of.insert({u, n + int(copy_of.size())});
        u = it->second;
      }
      std::vector<int>& part = r.part_vertices[label];
      if(std::find(part.begin(), part.end(), u) == part.end()) part.push_back(u);
    }
  }
  r.mesh.mesh.points.conservativeResize(n + int(copy_of.size()), 3);
  for(const auto& [u, copy] : copy_of)
  {
    r.mesh.mesh.points.row(copy) = annulus.mesh.points.row(u);
    r.original_vertex.push_back(-1);
  }
  return r;
}

TEST(Seam_stitching, a_rebuilt_ring_whose_loops_no_longer_touch_is_stitched_on_both_loops)
{
  for(int pinch = 0; pinch < sides; ++pinch)
  {
    SCOPED_TRACE("pinch at " + std::to_string(pinch));
    const Labeled_mesh original = pinched_ring_tube(pinch);
    const Rebuilt rebuilt = rebuild_ring_as_annulus(original, pinch);
    const std::vector<internal::Stitched_seam> seams =
      internal::stitch_seams(original, rebuilt.mesh, rebuilt.original_vertex, rebuilt.part_vertices, {1});
    // Vertices identified by the seams, as (label, local): no part may
    // have two of its own vertices made one, and every border vertex of
    // the rebuilt ring must be stitched to a neighbour (no hole).
    std::map<std::pair<int, int>, int> id;
    const auto key = [&](int label, int local) { return id.insert({{label, local}, int(id.size())}).first->second; };
    std::vector<int> rank(4096), parent(4096);
    boost::disjoint_sets<int*, int*> identified(rank.data(), parent.data());
    for(int i = 0; i < 4096; ++i) identified.make_set(i);
    std::set<int> stitched_ring_vertices;
    ASSERT_EQ(seams.size(), std::size_t(2));
    for(const internal::Stitched_seam& seam : seams)
      for(const Seam_vertex& sv : seam.merged)
      {
        for(int side = 0; side < 2; ++side)
        {
          if((side == 0 ? seam.label_a : seam.label_b) != 1) continue;
          if(sv.local[side] >= 0) stitched_ring_vertices.insert(sv.local[side]);
          // The ring meets label 0 on its lower loop (rings 2 and X, z < 3)
          // and label 2 on its upper loop (ring 3, z = 3).
          for(int local : {sv.local[side], sv.from[side], sv.to[side]})
          {
            if(local < 0) continue;
            const double z = rebuilt.mesh.mesh.points(rebuilt.part_vertices.at(1)[std::size_t(local)], 2);
            const int neighbour = side == 0 ? seam.label_b : seam.label_a;
            EXPECT_EQ(neighbour == 0, z < 2.9) << "label " << neighbour << " is stitched to the ring's vertex at z " << z;
          }
        }
        if(sv.local[0] >= 0 && sv.local[1] >= 0)
          identified.union_set(key(seam.label_a, sv.local[0]), key(seam.label_b, sv.local[1]));
      }
    std::map<std::pair<int, int>, std::pair<int, int>> part_vertex_of_class;
    for(const auto& [vertex, i] : id)
    {
      const auto [it, added] = part_vertex_of_class.insert({{vertex.first, identified.find_set(i)}, vertex});
      EXPECT_TRUE(added) << "label " << vertex.first << ": locals " << it->second.second << " and " << vertex.second
                         << " are made one";
    }
    // The ring's border: `sides` vertices above, `sides` and X below.
    EXPECT_EQ(stitched_ring_vertices.size(), std::size_t(2 * sides + 1));
  }
}

} // namespace
