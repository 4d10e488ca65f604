// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Seam_smoothing.h>

#include <CGAL/MPM/internal/Edge_faces.h>
#include <CGAL/MPM/internal/Nearest_surface.h>

#include <algorithm>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// The example's vertices as the smoothing moves them: which may move (the
// vertices of merged seams with two seam neighbours), and how many faces
// around some vertices lie folded over the surface.
class Seam_smoother
{
public:
  Seam_smoother(const Indexed_mesh& mesh, const std::vector<int>& face_labels,
                const std::set<std::pair<int, int>>& merged, const Indexed_mesh& surface)
    : mesh_(mesh), points_(mesh.points), along_(mesh.points.rows()), next_(mesh.points.rows()),
      faces_at_(mesh.points.rows()), movable_(mesh.points.rows(), false)
  {
    // A vertex on a seam that is not merged stays.
    std::vector<bool> kept(movable_.size(), false);
    for(const auto& [edge, faces] : faces_of_edges(mesh)) {
      next_[std::size_t(edge.first)].push_back(edge.second);
      next_[std::size_t(edge.second)].push_back(edge.first);
      if(faces.size() != 2) continue;
      const int a = face_labels[std::size_t(faces[0])], b = face_labels[std::size_t(faces[1])];
      if(a == b) continue;
      if(merged.count({std::min(a, b), std::max(a, b)})) {
        along_[std::size_t(edge.first)].push_back(edge.second);
        along_[std::size_t(edge.second)].push_back(edge.first);
      } else
        kept[std::size_t(edge.first)] = kept[std::size_t(edge.second)] = true;
    }
    for(std::size_t v = 0; v < movable_.size(); ++v)
      if(along_[v].size() == 2 && !kept[v]) {
        movable_[v] = true;
        moving_.push_back(int(v));
      }
    for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for(int v : mesh.triangles[f]) faces_at_[std::size_t(v)].push_back(int(f));
    if(!moving_.empty() && !surface.triangles.empty()) nearest_ = std::make_unique<Nearest_surface>(surface);
  }

  bool active() const { return nearest_ != nullptr; }
  const Point_matrix& points() const { return points_; }

  // Each vertex halfway to the midpoint of its seam neighbours, back onto
  // the surface, unless that folds more faces around it.
  void straighten()
  {
    const Point_matrix before = points_;
    for(int v : moving_) {
      const std::vector<int>& a = along_[std::size_t(v)];
      move({v}, {(0.5 * before.row(v) + 0.25 * (before.row(a[0]) + before.row(a[1]))).transpose()},
           folded_around({v}));
    }
  }

  // Each vertex of a folded face towards the mean of its neighbours (all
  // the way, half, a quarter or twice), where that unfolds faces; whether
  // any vertex had a folded face around it.
  bool unfold_vertices()
  {
    bool any = false;
    for(int v : moving_) {
      const int folded = folded_around({v});
      if(folded == 0) continue;
      any = true;
      const Eigen::Vector3d start = points_.row(v).transpose(), mean = neighbour_mean(v);
      for(double step : {1., 0.5, 0.25, 2.})
        if(move({v}, {start + step * (mean - start)}, folded - 1)) break;
    }
    return any;
  }

  // The movable corners of each face still folded towards the means of
  // their neighbours together: a sliver whose three corners lie on one
  // seam folds as many faces as it unfolds when one corner moves alone.
  void unfold_faces()
  {
    for(std::size_t f = 0; f < mesh_.triangles.size(); ++f) {
      if(!folded(int(f))) continue;
      std::vector<int> corners;
      for(int v : mesh_.triangles[f])
        if(movable_[std::size_t(v)]) corners.push_back(v);
      if(corners.empty()) continue;
      const int before = folded_around(corners);
      for(double step : {1., 0.5, 0.25}) {
        std::vector<Eigen::Vector3d> targets;
        for(int v : corners) {
          const Eigen::Vector3d start = points_.row(v).transpose();
          targets.push_back(start + step * (neighbour_mean(v) - start));
        }
        // Kept when the face unfolds and no more faces around it are
        // folded: a fold next to it may then go at its own turn.
        if(move(corners, targets, before)) {
          if(!folded(int(f))) break;
          undo_last_move();
        }
      }
    }
  }

private:
  bool folded(int f) const
  {
    const Triangle& t = mesh_.triangles[std::size_t(f)];
    return nearest_->folded(points_.row(t[0]).transpose(), points_.row(t[1]).transpose(),
                            points_.row(t[2]).transpose());
  }

  // The faces around `vertices` folded over the surface, each once.
  int folded_around(const std::vector<int>& vertices) const
  {
    std::vector<int> faces;
    for(int v : vertices) faces.insert(faces.end(), faces_at_[std::size_t(v)].begin(), faces_at_[std::size_t(v)].end());
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return int(std::count_if(faces.begin(), faces.end(), [&](int f) { return folded(f); }));
  }

  Eigen::Vector3d neighbour_mean(int v) const
  {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for(int w : next_[std::size_t(v)]) mean += points_.row(w).transpose();
    return mean / double(next_[std::size_t(v)].size());
  }

  // Moves `vertices` onto the surface's points nearest `targets` unless that
  // leaves more than `allowed` faces around them folded (a seam vertex moved
  // across a neighbour's chord turns over the sliver between them); whether
  // they moved.
  bool move(const std::vector<int>& vertices, const std::vector<Eigen::Vector3d>& targets, int allowed)
  {
    moved_ = vertices;
    old_.clear();
    for(std::size_t i = 0; i < vertices.size(); ++i) {
      old_.push_back(points_.row(vertices[i]));
      points_.row(vertices[i]) = nearest_->closest_point(targets[i]).transpose();
    }
    if(folded_around(vertices) <= allowed) return true;
    undo_last_move();
    return false;
  }

  void undo_last_move()
  {
    for(std::size_t i = 0; i < moved_.size(); ++i) points_.row(moved_[i]) = old_[i];
  }

  const Indexed_mesh& mesh_;
  Point_matrix points_;
  std::vector<std::vector<int>> along_, next_, faces_at_;
  std::vector<bool> movable_;
  std::vector<int> moving_;
  std::unique_ptr<Nearest_surface> nearest_;
  std::vector<int> moved_; // by the last move(), from `old_`
  std::vector<Eigen::RowVector3d> old_;
};

} // namespace

Point_matrix smoothed_seams(const Indexed_mesh& mesh, const std::vector<int>& face_labels,
                            const std::set<std::pair<int, int>>& merged, const Indexed_mesh& surface,
                            int iterations)
{
  Seam_smoother smoother(mesh, face_labels, merged, surface);
  if(!smoother.active()) return mesh.points;
  for(int i = 0; i < iterations; ++i) smoother.straighten();
  // Faces the correspondence left folded at a seam.
  for(int pass = 0; pass < iterations; ++pass)
    if(!smoother.unfold_vertices()) break;
  smoother.unfold_faces();
  return smoother.points();
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
