// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Example_untangling.h>

#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Edge_faces.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <map>
#include <memory>
#include <set>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle_iterator = std::vector<Kernel::Triangle_3>::const_iterator;
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Triangle_iterator>>>;
using Segment_iterator = std::vector<Kernel::Segment_3>::const_iterator;
using Segment_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_segment_primitive<Kernel, Segment_iterator>>>;
using Label_pair = std::pair<int, int>;

// The input's faces of one label, to project onto.
struct Label_surface
{
  std::vector<Kernel::Triangle_3> triangles;
  std::unique_ptr<Triangle_tree> tree;
};

// The input's seam between two labels (edges with a face of each), to
// slide a seam vertex along.
struct Seam_curve
{
  std::vector<Kernel::Segment_3> segments;
  std::unique_ptr<Segment_tree> tree;
};

std::map<Label_pair, Seam_curve> seams_by_label_pair(const Labeled_mesh& input)
{
  std::map<Label_pair, Seam_curve> seams;
  const Point_matrix& p = input.mesh.points;
  for(const auto& [edge, faces] : faces_of_edges(input.mesh))
  {
    if(faces.size() != 2) continue;
    const int l0 = input.face_labels[std::size_t(faces[0])], l1 = input.face_labels[std::size_t(faces[1])];
    if(l0 == l1) continue;
    seams[{std::min(l0, l1), std::max(l0, l1)}].segments.emplace_back(
      Kernel::Point_3(p(edge.first, 0), p(edge.first, 1), p(edge.first, 2)),
      Kernel::Point_3(p(edge.second, 0), p(edge.second, 1), p(edge.second, 2)));
  }
  for(auto& [pair, c] : seams) c.tree = std::make_unique<Segment_tree>(c.segments.begin(), c.segments.end());
  return seams;
}

std::map<int, Label_surface> surfaces_by_label(const Labeled_mesh& input)
{
  std::map<int, Label_surface> surfaces;
  const auto point = [&](int v) {
    return Kernel::Point_3(input.mesh.points(v, 0), input.mesh.points(v, 1), input.mesh.points(v, 2));
  };
  for(std::size_t f = 0; f < input.mesh.triangles.size(); ++f)
  {
    const Triangle& t = input.mesh.triangles[f];
    surfaces[input.face_labels[f]].triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  }
  for(auto& [label, s] : surfaces)
  {
    s.tree = std::make_unique<Triangle_tree>(s.triangles.begin(), s.triangles.end());
    s.tree->accelerate_distance_queries();
  }
  return surfaces;
}

int crossing_pairs(const Indexed_mesh& mesh, std::vector<int>* faces = nullptr)
{
  std::vector<std::pair<int, int>> pairs;
  if(!self_intersecting_faces(mesh, pairs)) return -1;
  if(faces)
  {
    faces->clear();
    for(const auto& [a, b] : pairs)
    {
      faces->push_back(a);
      faces->push_back(b);
    }
  }
  return int(pairs.size());
}

} // namespace

Point_matrix untangled_positions(const Indexed_mesh& mesh, const std::vector<int>& face_labels,
                                 const Labeled_mesh& input)
{
  std::vector<int> crossing;
  int best = crossing_pairs(mesh, &crossing);
  const int own = crossing_pairs(input.mesh);
  if(best <= std::max(own, 0)) return {};
  // The labels of each vertex's faces: one inside a part; two on a seam,
  // along which it slides; more where seams meet, where it stays.
  std::vector<std::set<int>> labels(std::size_t(mesh.points.rows()));
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int v : mesh.triangles[f]) labels[std::size_t(v)].insert(face_labels[f]);
  std::vector<std::vector<int>> next(labels.size());
  for(const Cluster_edge& e : mesh_edges(mesh.triangles))
  {
    next[std::size_t(e.source)].push_back(e.target);
    next[std::size_t(e.target)].push_back(e.source);
  }
  const std::map<int, Label_surface> surfaces = surfaces_by_label(input);
  const std::map<Label_pair, Seam_curve> seams = seams_by_label_pair(input);
  const std::size_t folded = folded_faces(mesh, input.mesh).size();
  // A vertex to the mean of its neighbours (on a seam, of its neighbours on
  // the same seam), back onto its part of the input (its seam).
  const auto move_to_neighbours = [&](int v, Point_matrix& points) {
    const std::set<int>& own = labels[std::size_t(v)];
    if(own.size() > 2) return;
    Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
    int count = 0;
    for(int w : next[std::size_t(v)])
      if(own.size() == 1 || labels[std::size_t(w)] == own)
      {
        mean += points.row(w);
        ++count;
      }
    if(count == 0) return;
    mean /= double(count);
    const Kernel::Point_3 m(mean[0], mean[1], mean[2]);
    Kernel::Point_3 q;
    if(own.size() == 1)
    {
      const auto s = surfaces.find(*own.begin());
      if(s == surfaces.end()) return;
      q = s->second.tree->closest_point(m);
    }
    else
    {
      const auto c = seams.find({*own.begin(), *own.rbegin()});
      if(c == seams.end()) return;
      q = c->second.tree->closest_point(m);
    }
    points.row(v) << q.x(), q.y(), q.z();
  };
  Indexed_mesh best_mesh = mesh;
  bool improved = false;
  int rings = 1;
  for(int pass = 0; pass < 12 && best > std::max(own, 0); ++pass)
  {
    std::vector<bool> moving(labels.size(), false);
    for(int f : crossing)
      for(int v : mesh.triangles[std::size_t(f)]) moving[std::size_t(v)] = true;
    for(int r = 0; r < rings; ++r)
    {
      const std::vector<bool> before = moving;
      for(std::size_t v = 0; v < labels.size(); ++v)
        if(before[v])
          for(int w : next[v]) moving[std::size_t(w)] = true;
    }
    Indexed_mesh candidate = best_mesh;
    for(int sweep = 0; sweep < 5; ++sweep)
      for(std::size_t v = 0; v < labels.size(); ++v)
        if(moving[v] && !next[v].empty()) move_to_neighbours(int(v), candidate.points);
    std::vector<int> now;
    const int count = crossing_pairs(candidate, &now);
    if(count >= 0 && count < best && folded_faces(candidate, input.mesh).size() <= folded)
    {
      best = count;
      best_mesh = std::move(candidate);
      crossing = std::move(now);
      improved = true;
    }
    else
      rings = std::min(rings + 1, 6);
  }
  return improved ? best_mesh.points : Point_matrix();
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
