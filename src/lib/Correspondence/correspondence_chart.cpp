// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Correspondence_surface.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

namespace CGAL {
namespace MPM {
namespace internal {
namespace correspondence {

namespace {

using Uv = Eigen::Matrix<double, Eigen::Dynamic, 2>;

// Barycentric coordinates of `p` in triangle (a, b, c), any dimension.
template <typename V>
Eigen::Vector3d barycentric(const V& p, const V& a, const V& b, const V& c)
{
  const V e0 = b - a, e1 = c - a, e2 = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = e2.dot(e0), d21 = e2.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  if(!(std::abs(det) > 0)) return Eigen::Vector3d(1., 0., 0.);
  const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
  return Eigen::Vector3d(1. - v - w, v, w);
}

double signed_area(const Uv& uv, const Triangle& t)
{
  const Eigen::Vector2d a = uv.row(t[0]), b = uv.row(t[1]), c = uv.row(t[2]);
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

// The segment flattened into a disk by CGAL's mean value parameterization
// (its longest loop on the unit circle by arc length): one-to-one for any
// triangulation (Floater), where cotangent weights on a scan's obtuse
// triangles are not. A second loop is first capped by a fan around its
// centroid, so that the segment is a disk (a convex-combination map of an
// annulus with both loops fixed folds: on the PSB hands a quarter of a
// phalanx's triangles came out turned). Segments with more loops, or whose
// parameterization fails, have no chart.
class Chart
{
public:
  explicit Chart(const Surface& s) : s_(s)
  {
    if(s.loops.empty() || s.loops.size() > 2) return;
    Indexed_mesh disk = s.mesh;
    if(s.loops.size() == 2)
    {
      const Loop& cap = s.loops[1];
      disk.points.conservativeResize(disk.points.rows() + 1, 3);
      disk.points.row(disk.points.rows() - 1) = cap.centroid.transpose();
      const int centre = int(disk.points.rows() - 1), k = int(cap.vertices.size());
      for(int i = 0; i < k; ++i)
        disk.triangles.push_back({cap.vertices[std::size_t((i + 1) % k)], cap.vertices[std::size_t(i)], centre});
    }
    Indexed_surface_mesh mesh;
    try
    {
      mesh = to_surface_mesh(disk, "segment", "a chart");
    }
    catch(const Input_error&)
    {
      return;
    }
    using Vertex = Indexed_surface_mesh::Vertex_index;
    namespace SMP = CGAL::Surface_mesh_parameterization;
    auto uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
    const auto border = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
    if(border == Indexed_surface_mesh::null_halfedge() ||
       SMP::parameterize(mesh, SMP::Mean_value_coordinates_parameterizer_3<Indexed_surface_mesh>(), border, uv) != SMP::OK)
      return;
    uv_.resize(s.mesh.points.rows(), 2);
    for(Eigen::Index v = 0; v < uv_.rows(); ++v) uv_.row(v) << uv[Vertex(std::uint32_t(v))].x(), uv[Vertex(std::uint32_t(v))].y();
    for(const Triangle& t : s.mesh.triangles) flat_.emplace_back(flat(t[0]), flat(t[1]), flat(t[2]));
    tree_.insert(flat_.begin(), flat_.end());
    tree_.accelerate_distance_queries();
  }

  bool exists() const { return !flat_.empty(); }

  // Where a point on (or near) the segment lies in the chart.
  Eigen::Vector2d to_chart(const Vec3& p) const
  {
    const auto [q, id] = s_.tree.closest_point_and_primitive(to_point(p));
    const Triangle& t = s_.mesh.triangles[std::size_t(id - s_.triangles.begin())];
    const Eigen::Vector3d w = barycentric<Vec3>(to_vec(q), s_.mesh.points.row(t[0]), s_.mesh.points.row(t[1]),
                                                s_.mesh.points.row(t[2]));
    return w(0) * uv_.row(t[0]).transpose() + w(1) * uv_.row(t[1]).transpose() + w(2) * uv_.row(t[2]).transpose();
  }

  // The segment's point at a chart position (the nearest one outside it).
  Vec3 to_surface(const Eigen::Vector2d& p) const
  {
    const auto [q, id] = tree_.closest_point_and_primitive(Point_3(p.x(), p.y(), 0.));
    const Triangle& t = s_.mesh.triangles[std::size_t(id - flat_.begin())];
    const Eigen::Vector3d w = barycentric<Eigen::Vector2d>(Eigen::Vector2d(q.x(), q.y()), uv_.row(t[0]),
                                                           uv_.row(t[1]), uv_.row(t[2]));
    return w(0) * s_.mesh.points.row(t[0]).transpose() + w(1) * s_.mesh.points.row(t[1]).transpose() +
           w(2) * s_.mesh.points.row(t[2]).transpose();
  }

private:
  Point_3 flat(int v) const { return Point_3(uv_(v, 0), uv_(v, 1), 0.); }

  const Surface& s_;
  Uv uv_;
  std::vector<Kernel::Triangle_3> flat_;
  Triangle_tree tree_;
};

} // namespace

// Folds the local repair (unfold()) leaves, taken out in a chart of the
// segment. unfold() moves a vertex to the mean of its neighbours and back
// onto the segment by closest point: on a thin tube that mean lies near
// the axis and projects to either side, and at a seam the ring squeezed
// against it projects onto the seam, so those folds never open (a
// phalanx of a PSB hand kept 37 of 957 triangles folded). In a chart a
// fold is a triangle of negative area and the mean of neighbours stays on
// the segment's side: the same smoothing, done there, opens it. The
// region grows by a ring whenever a pass opens no fold; seam vertices and
// landmarks stay. Kept only if fewer triangles face against the segment.
void unfold_in_chart(const Surface& s, const Template_info& info, const Landmarks& lm,
                     const std::vector<Triangle>& triangles, Point_matrix& y)
{
  const std::size_t flipped = flipped_faces(s, y, triangles).size();
  // More is no fold but a template laid wrongly on the segment (a thumb's
  // base on a finger's: a fifth of it turned, 11% of its diagonal off),
  // which learning refuses by its coverage; smoothed, it would pass.
  if(flipped == 0 || 10 * flipped > triangles.size()) return;
  const Chart chart(s);
  if(!chart.exists()) return;
  const Eigen::Index n = y.rows();
  Uv uv(n, 2);
  for(Eigen::Index v = 0; v < n; ++v) uv.row(v) = chart.to_chart(y.row(v).transpose()).transpose();
  const std::vector<bool> pinned = pinned_vertices(info, lm);
  const auto turned = [&](const Uv& at) {
    std::vector<int> r;
    for(std::size_t f = 0; f < triangles.size(); ++f)
      if(!(signed_area(at, triangles[f]) > 0)) r.push_back(int(f));
    return r;
  };
  std::vector<int> folds = turned(uv);
  std::vector<bool> moved(std::size_t(n), false);
  int rings = 1;
  for(int pass = 0; pass < 100 && !folds.empty(); ++pass)
  {
    const std::vector<bool> moving = vertices_near(folds, triangles, info.neighbours, rings);
    Uv next = uv;
    for(int sweep = 0; sweep < 4; ++sweep)
    {
      const Uv previous = next;
      for(Eigen::Index v = 0; v < n; ++v)
      {
        if(!moving[std::size_t(v)] || pinned[std::size_t(v)]) continue;
        Eigen::RowVector2d mean = Eigen::RowVector2d::Zero();
        for(int w : info.neighbours[std::size_t(v)]) mean += previous.row(w);
        next.row(v) = mean / double(info.neighbours[std::size_t(v)].size());
      }
    }
    std::vector<int> now = turned(next);
    if(now.size() < folds.size())
    {
      for(Eigen::Index v = 0; v < n; ++v) moved[std::size_t(v)] = moved[std::size_t(v)] || (moving[std::size_t(v)] && !pinned[std::size_t(v)]);
      uv = next;
      folds = std::move(now);
    }
    else
      rings = std::min(rings + 1, 12);
  }
  Point_matrix mapped = y;
  for(Eigen::Index v = 0; v < n; ++v)
    if(moved[std::size_t(v)]) mapped.row(v) = chart.to_surface(uv.row(v).transpose()).transpose();
  if(flipped_faces(s, mapped, triangles).size() < flipped) y = mapped;
}

} // namespace correspondence
} // namespace internal
} // namespace MPM
} // namespace CGAL
