// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Correspondence_surface.h>

#include <set>

namespace CGAL {
namespace MPM {
namespace internal {
namespace correspondence {

namespace {

// Squared distance of each of the segment's vertices to the mapped
// template surface; empty when every mapped triangle is degenerate.
std::vector<double> squared_distances_to_mapped(const Surface& s, const Point_matrix& y,
                                                const std::vector<Triangle>& triangles)
{
  std::vector<Kernel::Triangle_3> mapped;
  for(const Triangle& t : triangles)
  {
    const Kernel::Triangle_3 tri(to_point(y.row(t[0])), to_point(y.row(t[1])), to_point(y.row(t[2])));
    if(!tri.is_degenerate()) mapped.push_back(tri);
  }
  if(mapped.empty()) return {};
  Triangle_tree tree(mapped.begin(), mapped.end());
  tree.accelerate_distance_queries();
  std::vector<double> d(std::size_t(s.mesh.points.rows()));
  for(Eigen::Index v = 0; v < s.mesh.points.rows(); ++v) d[std::size_t(v)] = tree.squared_distance(to_point(s.mesh.points.row(v)));
  return d;
}

// `v` (ring 0) and the `count` rings of vertices around it.
std::vector<std::vector<int>> rings_around(const std::vector<std::vector<int>>& neighbours, int v, int count)
{
  std::vector<std::vector<int>> rings{{v}};
  std::vector<bool> seen(neighbours.size(), false);
  seen[std::size_t(v)] = true;
  for(int r = 0; r < count; ++r)
  {
    rings.emplace_back();
    for(int u : rings[std::size_t(r)])
      for(int w : neighbours[std::size_t(u)])
        if(!seen[std::size_t(w)])
        {
          seen[std::size_t(w)] = true;
          rings.back().push_back(w);
        }
  }
  return rings;
}

} // namespace

// Seam vertices, landmarks and vertices of no triangle: what the repairs
// leave where they are.
std::vector<bool> pinned_vertices(const Template_info& info, const Landmarks& lm)
{
  std::vector<bool> pinned(info.loop.size(), false);
  for(std::size_t v = 0; v < pinned.size(); ++v) pinned[v] = info.loop[v] >= 0 || info.neighbours[v].empty();
  for(const auto& [v, p] : lm.vertex_targets) pinned[std::size_t(v)] = true;
  return pinned;
}

// The vertices of `faces` and the `rings` rings of vertices around them.
std::vector<bool> vertices_near(const std::vector<int>& faces, const std::vector<Triangle>& triangles,
                                const std::vector<std::vector<int>>& neighbours, int rings)
{
  std::vector<bool> near(neighbours.size(), false);
  for(int f : faces)
    for(int v : triangles[std::size_t(f)]) near[std::size_t(v)] = true;
  for(int r = 0; r < rings; ++r)
  {
    std::vector<bool> grown = near;
    for(std::size_t v = 0; v < near.size(); ++v)
      if(near[v])
        for(int w : neighbours[v]) grown[std::size_t(w)] = true;
    near.swap(grown);
  }
  return near;
}

// RMS distance of the segment's vertices to the mapped template surface.
double coverage_residual(const Surface& s, const Point_matrix& y, const std::vector<Triangle>& triangles)
{
  const std::vector<double> d = squared_distances_to_mapped(s, y, triangles);
  if(d.empty()) return 1.;
  double sum = 0.;
  for(double x : d) sum += x;
  return std::sqrt(sum / s.mesh.points.rows()) / s.diagonal;
}

// Mapped template triangles facing against the segment: the normal of the
// mapped triangle against that of the segment's face nearest to its
// centroid. Degenerate mapped triangles have no side and are not counted.
std::vector<int> flipped_faces(const Surface& s, const Point_matrix& y, const std::vector<Triangle>& triangles)
{
  std::vector<int> flipped;
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const Triangle& t = triangles[f];
    const Vec3 a = y.row(t[0]), b = y.row(t[1]), c = y.row(t[2]);
    const Vec3 n = (b - a).cross(c - a);
    Vec3 normal;
    s.closest((a + b + c) / 3., &normal);
    if(n.dot(normal) < 0) flipped.push_back(static_cast<int>(f));
  }
  return flipped;
}

// Repairs folds of the correspondence: on real segments they sit in the
// first rings inside a seam, where the boundary vertices are pinned to
// their arc-length images on a jagged cut and the next ring, pulled to the
// closest surface points, folds over them. The free vertices of flipped
// triangles and `rings` rings around them go to the mean of their
// neighbours and back onto the segment; a pass that removes no fold widens
// the region (a fold wider than two rings does not open otherwise: on the
// PSB hands that halved the self-intersections left). The result with
// fewest flipped triangles is kept. Boundary and landmark vertices stay.
void unfold(const Surface& s, const Template_info& info, const Landmarks& lm, const std::vector<Triangle>& triangles,
            Point_matrix& y)
{
  std::vector<int> flipped = flipped_faces(s, y, triangles);
  const std::vector<bool> pinned = pinned_vertices(info, lm);
  Point_matrix current = y;
  int rings = 1;
  for(int pass = 0; pass < 60 && !flipped.empty(); ++pass)
  {
    const std::vector<bool> moving = vertices_near(flipped, triangles, info.neighbours, rings);
    const Point_matrix previous = current;
    for(Eigen::Index v = 0; v < y.rows(); ++v)
    {
      if(!moving[v] || pinned[v] || info.neighbours[v].empty()) continue;
      Vec3 mean = Vec3::Zero();
      for(int w : info.neighbours[v]) mean += previous.row(w).transpose();
      current.row(v) = s.closest(mean / double(info.neighbours[v].size())).transpose();
    }
    std::vector<int> now = flipped_faces(s, current, triangles);
    if(now.size() < flipped.size())
    {
      y = current;
      flipped = std::move(now);
    }
    else
      rings = std::min(rings + 1, 8);
  }
}

// Template vertices pulled onto the segment's points that the mapped
// template misses. Projection takes each template vertex to its closest
// surface point, which never reaches the apex of a pointed extremity (a
// finger's pad, a leg's claw): the learned example stopped short of the
// input there by up to 0.7% of the mesh's diagonal. Farthest point first,
// the nearest free template vertex moves onto it and three rings around it
// follow by 60, 30 and 10% of its move, unless that turns more triangles
// around it against the surface than before. (With only its neighbours
// smoothed after it, every move onto the curled tip of octopus_137's arm 6
// turned its triangles and was undone: 0.55% of the diagonal missed, now
// 0.28%.) A point more than three edges from every template vertex is a
// region the fit missed, not an apex, and stays.
void cover_missed_points(const Surface& s, const Template_info& info, const Landmarks& lm,
                         const std::vector<Triangle>& triangles, Point_matrix& y)
{
  const Eigen::Index n = y.rows();
  std::vector<bool> fixed = pinned_vertices(info, lm);
  std::vector<std::vector<int>> faces_of{std::size_t(n)};
  double edge = 0.;
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      faces_of[std::size_t(triangles[f][k])].push_back(int(f));
      edge += (y.row(triangles[f][k]) - y.row(triangles[f][(k + 1) % 3])).norm();
    }
  if(triangles.empty()) return;
  edge /= 3. * double(triangles.size());
  // Triangles of `vertices` that face against the surface.
  const auto turned_among = [&](const std::vector<int>& vertices) {
    std::set<int> faces;
    for(int v : vertices) faces.insert(faces_of[std::size_t(v)].begin(), faces_of[std::size_t(v)].end());
    int turned = 0;
    for(int f : faces)
    {
      const Triangle& t = triangles[std::size_t(f)];
      const Vec3 a = y.row(t[0]), b = y.row(t[1]), c = y.row(t[2]);
      Vec3 normal;
      s.closest((a + b + c) / 3., &normal);
      turned += (b - a).cross(c - a).dot(normal) <= 0.;
    }
    return turned;
  };
  for(int pass = 0; pass < 8; ++pass)
  {
    const std::vector<double> squared = squared_distances_to_mapped(s, y, triangles);
    if(squared.empty()) return;
    std::vector<std::pair<double, int>> missed;
    for(std::size_t p = 0; p < squared.size(); ++p)
    {
      const double d = std::sqrt(squared[p]);
      if(d > 0.5 * edge) missed.emplace_back(d, int(p));
    }
    std::sort(missed.rbegin(), missed.rend());
    std::vector<Vec3> covered; // points moved onto in this pass
    for(const auto& [d, p] : missed)
    {
      const Vec3 q = s.mesh.points.row(p).transpose();
      if(std::any_of(covered.begin(), covered.end(), [&](const Vec3& c) { return (c - q).norm() < 2. * edge; })) continue;
      int nearest = -1;
      for(Eigen::Index v = 0; v < n; ++v)
        if(!fixed[v] && (nearest < 0 || (y.row(v).transpose() - q).norm() < (y.row(nearest).transpose() - q).norm()))
          nearest = int(v);
      if(nearest < 0 || (y.row(nearest).transpose() - q).norm() > 3. * edge) continue;
      // The three rings around it follow by a falling share of its move, so
      // that the triangles between the apex and the rest keep their side.
      const std::vector<std::vector<int>> rings = rings_around(info.neighbours, nearest, 3);
      std::vector<int> moved;
      for(const std::vector<int>& ring : rings) moved.insert(moved.end(), ring.begin(), ring.end());
      const Point_matrix before = y;
      const int turned_before = turned_among(moved);
      const Vec3 shift = q - y.row(nearest).transpose();
      y.row(nearest) = q.transpose();
      const double share[] = {1., 0.6, 0.3, 0.1};
      for(std::size_t r = 1; r < rings.size(); ++r)
        for(int w : rings[r])
          if(!fixed[std::size_t(w)]) y.row(w) = s.closest(y.row(w).transpose() + share[r] * shift).transpose();
      const bool sound = turned_among(moved) <= turned_before;
      if(!sound)
      {
        y = before;
        continue;
      }
      fixed[nearest] = true;
      covered.push_back(q);
    }
    if(covered.empty()) return;
  }
}

} // namespace correspondence
} // namespace internal
} // namespace MPM
} // namespace CGAL
