// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Dense correspondence never turns a part inside out: a segment given with
// its mirror image as one part type, and the phalanges of a real hand
// (MPM_PSB_DIR, skipped with a message when absent; only read).
#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/IO/Mesh_io.h>

#include "Tube_mesh.h"
#include "Psb_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace CGAL::MPM;

// A tube of elliptic section between two oblique cuts leaning different
// ways (the lower towards +x, the upper towards +y), bent towards +x: a
// chiral segment, which no rotation carries onto its mirror image.
Indexed_mesh oblique_tube(int rings, int sides)
{
  Indexed_mesh m;
  m.points.resize(rings * sides, 3);
  const double pi = std::acos(-1.);
  for(int r = 0; r < rings; ++r)
    for(int s = 0; s < sides; ++s)
    {
      const double u = double(r) / (rings - 1), phi = 2 * pi * s / sides;
      const double x = 1.3 * std::cos(phi), y = 0.8 * std::sin(phi);
      const double z = 4. * u + (1. - u) * 0.5 * x + u * 0.5 * y;
      m.points.row(r * sides + s) << x + 0.6 * z * z / 16., y, z;
    }
  m.triangles = mpm_test::tube_triangles(rings, sides);
  return m;
}

// Reflected through x = 0 with its triangles reversed: a valid, outward
// oriented surface again.
Indexed_mesh mirror_image(Indexed_mesh m)
{
  m.points.col(0) *= -1.;
  for(Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// Seam tags telling the two cuts apart, as learning gives them.
std::vector<int> end_tags(int rings, int sides)
{
  std::vector<int> tags(rings * sides, -1);
  for(int s = 0; s < sides; ++s)
  {
    tags[s] = 0;
    tags[(rings - 1) * sides + s] = 1;
  }
  return tags;
}

TEST(Dense_correspondence_orientation, mirror_image_is_not_turned_inside_out)
{
  std::vector<Correspondence_segment> segments(2);
  segments[0].mesh = oblique_tube(24, 32);
  segments[0].seam_tags = end_tags(24, 32);
  segments[0].name = "left.off label 3";
  segments[1].mesh = mirror_image(oblique_tube(30, 28)); // a different triangulation
  segments[1].seam_tags = end_tags(30, 28);
  segments[1].name = "right.off label 8";
  std::vector<std::string> forwarded;
  Dense_correspondence_options options;
  options.warning = [&](const std::string& w) { forwarded.push_back(w); };
  // The mirror check runs for every fit, not only after poor ones.
  options.mirror_check_residual = 0.;
  const Dense_correspondence c = compute_dense_correspondence(segments, "phalanx", options);
  ASSERT_EQ(c.segments.size(), 2u);
  const double faces = static_cast<double>(c.triangles.size());
  EXPECT_EQ(c.segments[0].flipped_faces, 0);
  EXPECT_LE(c.segments[1].flipped_faces / faces, 0.02) << c.segments[1].flipped_faces << " of " << faces;
  EXPECT_EQ(forwarded, c.warnings);
  // The orientation-preserving fit covers this mirror image to about 0.15%
  // of its diagonal, so the mirror does not win and no warning is due; when
  // it does, the warning names the segment. (A shape whose proper fit fails
  // while its reflection fits, as a thumb on a real hand did, is still to
  // be found for this test.)
  EXPECT_LE(c.segments[1].residual, 0.01);
  if(c.segments[1].mirrored)
  {
    ASSERT_FALSE(c.warnings.empty());
    EXPECT_NE(c.warnings.front().find("right.off label 8"), std::string::npos) << c.warnings.front();
    EXPECT_NE(c.warnings.front().find("mirror image"), std::string::npos) << c.warnings.front();
    EXPECT_NE(c.warnings.front().find("part type \"phalanx\""), std::string::npos) << c.warnings.front();
  }
}

// The segments of a labelled mesh grouped by their depth in the segment
// graph from the largest segment (on a hand: palm, proximal, middle,
// distal), seam vertices tagged with the depth across the seam.
std::map<int, std::vector<Correspondence_segment>> segments_by_depth(const Labeled_mesh& lm)
{
  const Indexed_mesh& mesh = lm.mesh;
  std::map<int, int> faces_of;
  for(int l : lm.face_labels) ++faces_of[l];
  std::vector<std::set<int>> labels_at(mesh.number_of_vertices());
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int v : mesh.triangles[f]) labels_at[v].insert(lm.face_labels[f]);
  std::map<int, std::set<int>> adjacent;
  for(const std::set<int>& s : labels_at)
    for(int a : s)
      for(int b : s)
        if(a != b) adjacent[a].insert(b);
  int root = faces_of.begin()->first;
  for(const auto& [l, n] : faces_of)
    if(n > faces_of[root]) root = l;
  std::map<int, int> depth{{root, 0}};
  std::deque<int> queue{root};
  for(; !queue.empty(); queue.pop_front())
    for(int b : adjacent[queue.front()])
      if(depth.emplace(b, depth[queue.front()] + 1).second) queue.push_back(b);
  std::map<int, std::vector<Correspondence_segment>> types;
  for(const auto& [label, count] : faces_of)
  {
    if(label == root) continue;
    Correspondence_segment s;
    std::map<int, int> local;
    for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    {
      if(lm.face_labels[f] != label) continue;
      Triangle t;
      for(int k = 0; k < 3; ++k) t[k] = local.emplace(mesh.triangles[f][k], int(local.size())).first->second;
      s.mesh.triangles.push_back(t);
    }
    s.mesh.points.resize(local.size(), 3);
    s.seam_tags.assign(local.size(), -1);
    for(const auto& [v, i] : local)
    {
      s.mesh.points.row(i) = mesh.points.row(v);
      for(int other : labels_at[v])
        if(other != label) s.seam_tags[i] = depth[other];
    }
    s.name = lm.source + " label " + std::to_string(label);
    types[depth[label]].push_back(std::move(s));
  }
  return types;
}

TEST(Dense_correspondence_orientation, real_hand_phalanges_keep_their_orientation)
{
  // hand_190: its thumb's base, typed like the other proximal phalanges,
  // was matched to the template as a mirror image (95% of its triangles
  // inside out).
  MPM_REQUIRE_PSB("hand_190");
  const Labeled_mesh lm = read_labeled_mesh(mpm_test::psb_file("hand_190.off"), mpm_test::psb_file("hand_190.seg"));
  for(const auto& [depth, segments] : segments_by_depth(lm))
  {
    ASSERT_EQ(segments.size(), 5u) << "depth " << depth;
    const Dense_correspondence c = compute_dense_correspondence(segments, "depth " + std::to_string(depth));
    for(std::size_t i = 0; i < segments.size(); ++i)
    {
      EXPECT_FALSE(c.segments[i].mirrored) << segments[i].name;
      const double fraction = c.segments[i].flipped_faces / double(c.triangles.size());
      EXPECT_LE(fraction, 0.12) << segments[i].name << ": " << c.segments[i].flipped_faces << " flipped";
      EXPECT_LE(c.segments[i].residual, 0.01) << segments[i].name;
    }
  }
}

} // namespace
