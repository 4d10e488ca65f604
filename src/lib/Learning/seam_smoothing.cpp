// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Seam_smoothing.h>

#include <CGAL/MPM/internal/Edge_faces.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle_iterator = std::vector<Kernel::Triangle_3>::const_iterator;
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Triangle_iterator>>>;

Kernel::Point_3 point_of(const Point_matrix& p, Eigen::Index v) { return {p(v, 0), p(v, 1), p(v, 2)}; }

} // namespace

Point_matrix smoothed_seams(const Indexed_mesh& mesh, const std::vector<int>& face_labels,
                            const std::set<std::pair<int, int>>& merged, const Indexed_mesh& surface,
                            int iterations)
{
  // Per vertex, its neighbours along merged seams; a vertex on any other
  // seam stays.
  std::vector<std::vector<int>> along(std::size_t(mesh.points.rows()));
  std::vector<bool> kept(along.size(), false);
  for(const auto& [edge, faces] : faces_of_edges(mesh)) {
    if(faces.size() != 2) continue;
    const int a = face_labels[std::size_t(faces[0])], b = face_labels[std::size_t(faces[1])];
    if(a == b) continue;
    if(merged.count({std::min(a, b), std::max(a, b)})) {
      along[std::size_t(edge.first)].push_back(edge.second);
      along[std::size_t(edge.second)].push_back(edge.first);
    } else
      kept[std::size_t(edge.first)] = kept[std::size_t(edge.second)] = true;
  }
  std::vector<int> moving;
  for(std::size_t v = 0; v < along.size(); ++v)
    if(along[v].size() == 2 && !kept[v]) moving.push_back(int(v));
  Point_matrix points = mesh.points;
  if(moving.empty() || surface.triangles.empty()) return points;
  std::vector<Kernel::Triangle_3> triangles;
  for(const Triangle& t : surface.triangles)
    triangles.emplace_back(point_of(surface.points, t[0]), point_of(surface.points, t[1]), point_of(surface.points, t[2]));
  Triangle_tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  for(int i = 0; i < iterations; ++i) {
    const Point_matrix before = points;
    for(int v : moving) {
      const std::vector<int>& n = along[std::size_t(v)];
      const Eigen::RowVector3d moved = 0.5 * before.row(v) + 0.25 * (before.row(n[0]) + before.row(n[1]));
      const Kernel::Point_3 q = tree.closest_point(Kernel::Point_3(moved[0], moved[1], moved[2]));
      points.row(v) << q.x(), q.y(), q.z();
    }
  }
  return points;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
