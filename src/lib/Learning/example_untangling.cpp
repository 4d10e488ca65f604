// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Example_untangling.h>

#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <map>
#include <memory>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle_iterator = std::vector<Kernel::Triangle_3>::const_iterator;
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Triangle_iterator>>>;

// The input's faces of one label, to project onto.
struct Label_surface
{
  std::vector<Kernel::Triangle_3> triangles;
  std::unique_ptr<Triangle_tree> tree;
};

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
  const int own = std::max(crossing_pairs(input.mesh), 0);
  if(best <= own) return {};
  // Each vertex's label; -1 on a seam (faces of two labels), where it stays:
  // a seam vertex moved would be merged anew when the model is learned
  // again, and the dockings it changed folded an ant's legs when
  // symmetrized.
  std::vector<int> label(std::size_t(mesh.points.rows()), -2);
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int v : mesh.triangles[f])
      label[std::size_t(v)] = label[std::size_t(v)] == -2 || label[std::size_t(v)] == face_labels[f] ? face_labels[f] : -1;
  std::vector<std::vector<int>> next(label.size());
  for(const Cluster_edge& e : mesh_edges(mesh.triangles))
  {
    next[std::size_t(e.source)].push_back(e.target);
    next[std::size_t(e.target)].push_back(e.source);
  }
  const std::map<int, Label_surface> surfaces = surfaces_by_label(input);
  const std::size_t folded = folded_faces(mesh, input.mesh).size();
  // A vertex inside a part to the mean of its neighbours, back onto its
  // part of the input.
  const auto move_to_neighbours = [&](std::size_t v, Point_matrix& points) {
    const auto s = surfaces.find(label[v]);
    if(s == surfaces.end() || next[v].empty()) return;
    Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
    for(int w : next[v]) mean += points.row(w);
    mean /= double(next[v].size());
    const Kernel::Point_3 q = s->second.tree->closest_point(Kernel::Point_3(mean[0], mean[1], mean[2]));
    points.row(Eigen::Index(v)) << q.x(), q.y(), q.z();
  };
  Indexed_mesh best_mesh = mesh;
  bool improved = false;
  int rings = 1;
  for(int pass = 0; pass < 12 && best > own; ++pass)
  {
    std::vector<bool> moving(label.size(), false);
    for(int f : crossing)
      for(int v : mesh.triangles[std::size_t(f)]) moving[std::size_t(v)] = true;
    for(int r = 0; r < rings; ++r)
    {
      const std::vector<bool> before = moving;
      for(std::size_t v = 0; v < label.size(); ++v)
        if(before[v])
          for(int w : next[v]) moving[std::size_t(w)] = true;
    }
    Indexed_mesh candidate = best_mesh;
    for(int sweep = 0; sweep < 5; ++sweep)
      for(std::size_t v = 0; v < label.size(); ++v)
        if(moving[v]) move_to_neighbours(v, candidate.points);
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
