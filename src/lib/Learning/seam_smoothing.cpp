// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Seam_smoothing.h>

#include <CGAL/MPM/internal/Edge_faces.h>
#include <CGAL/MPM/internal/Nearest_surface.h>

namespace CGAL {
namespace MPM {
namespace internal {

Point_matrix smoothed_seams(const Indexed_mesh& mesh, const std::vector<int>& face_labels,
                            const std::set<std::pair<int, int>>& merged, const Indexed_mesh& surface,
                            int iterations)
{
  // Per vertex, its neighbours along merged seams and all its neighbours; a
  // vertex on any other seam stays.
  const std::size_t n = std::size_t(mesh.points.rows());
  std::vector<std::vector<int>> along(n), next(n);
  std::vector<bool> kept(n, false);
  for(const auto& [edge, faces] : faces_of_edges(mesh)) {
    next[std::size_t(edge.first)].push_back(edge.second);
    next[std::size_t(edge.second)].push_back(edge.first);
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
  for(std::size_t v = 0; v < n; ++v)
    if(along[v].size() == 2 && !kept[v]) moving.push_back(int(v));
  Point_matrix points = mesh.points;
  if(moving.empty() || surface.triangles.empty()) return points;
  const Nearest_surface nearest(surface);
  std::vector<std::vector<int>> faces_at(n);
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int v : mesh.triangles[f]) faces_at[std::size_t(v)].push_back(int(f));
  const auto folded_around = [&](int v) {
    int count = 0;
    for(int f : faces_at[std::size_t(v)]) {
      const Triangle& t = mesh.triangles[std::size_t(f)];
      count += nearest.folded(points.row(t[0]).transpose(), points.row(t[1]).transpose(), points.row(t[2]).transpose());
    }
    return count;
  };
  // Moves `v` onto the surface's point nearest `target` unless that folds
  // more faces around it than `allowed` (a seam vertex moved across a
  // neighbour's chord turns over the sliver between them); whether it moved.
  const auto move = [&](int v, const Eigen::Vector3d& target, int allowed) {
    const Eigen::RowVector3d old = points.row(v);
    points.row(v) = nearest.closest_point(target).transpose();
    if(folded_around(v) <= allowed) return true;
    points.row(v) = old;
    return false;
  };
  for(int i = 0; i < iterations; ++i) {
    const Point_matrix before = points;
    for(int v : moving) {
      const std::vector<int>& a = along[std::size_t(v)];
      move(v, (0.5 * before.row(v) + 0.25 * (before.row(a[0]) + before.row(a[1]))).transpose(), folded_around(v));
    }
  }
  // Faces the correspondence left folded at a seam, such as a sliver whose
  // three corners are on one seam, turn back when a corner moves towards the
  // mean of its neighbours, some by part of the way; only moves that unfold
  // are kept.
  for(int pass = 0; pass < iterations; ++pass)
    for(int v : moving) {
      const int folded = folded_around(v);
      if(folded == 0) continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for(int w : next[std::size_t(v)]) mean += points.row(w).transpose();
      mean /= double(next[std::size_t(v)].size());
      const Eigen::Vector3d start = points.row(v).transpose();
      for(double step : {1., 0.5, 0.25, 2.})
        if(move(v, start + step * (mean - start), folded - 1)) break;
    }
  return points;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
