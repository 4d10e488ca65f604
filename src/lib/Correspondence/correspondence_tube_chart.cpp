// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Correspondence_surface.h>

#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace MPM {
namespace internal {
namespace correspondence {

namespace {

constexpr double pi = 3.141592653589793;
constexpr int knots_inside = 16;

double wrapped(double angle)
{
  angle = std::fmod(angle + pi, 2. * pi);
  if(angle < 0) angle += 2. * pi;
  return angle - pi;
}

// A segment with one or two loops seen as a tube: per vertex the position
// along it (0 on its first loop, 1 on its other loop or at its tip, from
// shortest-path distances along its edges) and the angle about its axis
// (the centroids of slices along it), measured in a frame carried along the
// axis without twisting from a chosen point of the first loop.
class Tube
{
public:
  Tube(const Surface& x, int first, int other, const Vec3& start)
  {
    const std::vector<Cluster_edge> edges = mesh_edges(x.mesh.triangles);
    const std::vector<double> from_first = edge_graph_distances(x.mesh.points, edges, x.loops[first].vertices);
    const Eigen::Index n = x.mesh.points.rows();
    u_.resize(std::size_t(n));
    if(other >= 0)
    {
      const std::vector<double> from_other = edge_graph_distances(x.mesh.points, edges, x.loops[other].vertices);
      for(Eigen::Index v = 0; v < n; ++v)
      {
        const double sum = from_first[v] + from_other[v];
        u_[v] = sum > 0 && std::isfinite(sum) ? from_first[v] / sum : 0.;
      }
    }
    else
    {
      const double far = *std::max_element(from_first.begin(), from_first.end());
      if(!(far > 0) || !std::isfinite(far)) return;
      for(Eigen::Index v = 0; v < n; ++v) u_[v] = from_first[v] / far;
    }
    if(!axis(x, first, other)) return;
    frames(start);
    theta_.resize(std::size_t(n));
    for(Eigen::Index v = 0; v < n; ++v) theta_[v] = angle(x.mesh.points.row(v).transpose(), u_[v]);
    valid_ = true;
  }

  bool valid() const { return valid_; }
  // Axis length over the first loop's mean radius.
  double slenderness() const { return slenderness_; }
  double u(int v) const { return u_[std::size_t(v)]; }
  // The vertex farthest along the tube (its tip, with one loop).
  int tip() const { return tip_; }
  double theta(int v) const { return theta_[std::size_t(v)]; }

  // The angle of point `p` at position `u` along the tube.
  double angle(const Vec3& p, double u) const
  {
    const std::size_t k = interval(u);
    const double w = std::clamp((u - knot_[k]) / (knot_[k + 1] - knot_[k]), 0., 1.);
    const Vec3 centre = (1 - w) * centre_[k] + w * centre_[k + 1];
    const Vec3 tangent = ((1 - w) * tangent_[k] + w * tangent_[k + 1]).normalized();
    Vec3 e = (1 - w) * e_[k] + w * e_[k + 1];
    e = (e - e.dot(tangent) * tangent).normalized();
    const Vec3 d = p - centre;
    return std::atan2(d.dot(tangent.cross(e)), d.dot(e));
  }

private:
  std::size_t interval(double u) const
  {
    const auto it = std::upper_bound(knot_.begin(), knot_.end(), u);
    const std::size_t k = std::size_t(std::max<std::ptrdiff_t>(1, it - knot_.begin())) - 1;
    return std::min(k, knot_.size() - 2);
  }

  // Knots at both ends (the first loop's centroid; the other loop's or the
  // tip) and at the centroids of slices of equal width in u between them.
  bool axis(const Surface& x, int first, int other)
  {
    std::vector<Vec3> sum(knots_inside, Vec3::Zero());
    std::vector<int> count(knots_inside, 0);
    for(std::size_t v = 0; v < u_.size(); ++v)
    {
      const int k = std::min(knots_inside - 1, int(u_[v] * knots_inside));
      sum[std::size_t(k)] += x.mesh.points.row(Eigen::Index(v)).transpose();
      ++count[std::size_t(k)];
      if(u_[v] > u_[std::size_t(tip_)]) tip_ = int(v);
    }
    knot_.push_back(0.);
    centre_.push_back(x.loops[first].centroid);
    for(int k = 0; k < knots_inside; ++k)
      if(count[std::size_t(k)] > 0)
      {
        knot_.push_back((k + 0.5) / knots_inside);
        centre_.push_back(sum[std::size_t(k)] / count[std::size_t(k)]);
      }
    const Vec3 end = other >= 0 ? x.loops[other].centroid : Vec3(x.mesh.points.row(tip_).transpose());
    // A last slice holding the tip alone would be a second knot on it.
    while(centre_.size() > 1 && !((centre_.back() - end).norm() > 0)) centre_.pop_back(), knot_.pop_back();
    knot_.push_back(1.);
    centre_.push_back(end);
    if(knot_.size() < knots_inside / 2) return false;
    double length = 0.;
    for(std::size_t k = 0; k + 1 < centre_.size(); ++k) length += (centre_[k + 1] - centre_[k]).norm();
    const double radius = x.loops[first].mean_radius();
    slenderness_ = radius > 0 ? length / radius : 0.;
    for(std::size_t k = 0; k < centre_.size(); ++k)
    {
      const Vec3 d = centre_[std::min(k + 1, centre_.size() - 1)] - centre_[k > 0 ? k - 1 : 0];
      if(!(d.norm() > 0)) return false;
      tangent_.push_back(d.normalized());
    }
    return true;
  }

  // Parallel transport of the start direction along the axis.
  void frames(const Vec3& start)
  {
    Vec3 e = start - centre_[0];
    for(const Vec3& t : tangent_)
    {
      e = e - e.dot(t) * t;
      if(!(e.norm() > 0)) e = t.unitOrthogonal();
      e.normalize();
      e_.push_back(e);
    }
  }

  bool valid_ = false;
  int tip_ = 0;
  double slenderness_ = 0.;
  std::vector<double> u_, theta_, knot_;
  std::vector<Vec3> centre_, tangent_, e_;
};

// The segment's triangles in the (u, angle) plane, bucketed for lookup;
// triangles across the angle's cut are unwrapped and also kept a turn lower.
class Tube_lookup
{
public:
  explicit Tube_lookup(const Tube& tube, const Indexed_mesh& mesh) : mesh_(mesh)
  {
    cells_.resize(rows * columns);
    for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    {
      const Triangle& t = mesh.triangles[f];
      Corners c;
      for(int k = 0; k < 3; ++k)
      {
        double a = tube.theta(t[std::size_t(k)]);
        if(k > 0) a = c[0].y() + wrapped(a - c[0].y());
        c[std::size_t(k)] = Eigen::Vector2d(tube.u(t[std::size_t(k)]), a);
      }
      add(f, c);
      const double top = std::max({c[0].y(), c[1].y(), c[2].y()});
      if(top > pi)
      {
        for(Eigen::Vector2d& p : c) p.y() -= 2. * pi;
        add(f, c);
      }
    }
  }

  // The point of the segment at (u, angle), or false when no triangle is
  // near enough.
  bool point(double u, double angle, Vec3& p) const
  {
    const Eigen::Vector2d q(u, wrapped(angle));
    double best = -std::numeric_limits<double>::infinity();
    for(const Entry& e : cells_[cell(q)])
    {
      const Eigen::Vector3d w = weights(q, e.corners);
      if(w.minCoeff() > best)
      {
        best = w.minCoeff();
        const Triangle& t = mesh_.triangles[e.face];
        const Eigen::Vector3d c = w.cwiseMax(0.) / w.cwiseMax(0.).sum();
        p = c[0] * mesh_.points.row(t[0]).transpose() + c[1] * mesh_.points.row(t[1]).transpose() +
            c[2] * mesh_.points.row(t[2]).transpose();
      }
    }
    return best > -0.25;
  }

private:
  using Corners = std::array<Eigen::Vector2d, 3>;
  struct Entry
  {
    std::size_t face;
    Corners corners;
  };
  static constexpr std::size_t rows = 32, columns = 32;

  static Eigen::Vector3d weights(const Eigen::Vector2d& p, const Corners& c)
  {
    const Eigen::Vector2d e0 = c[1] - c[0], e1 = c[2] - c[0], e2 = p - c[0];
    const double det = e0.x() * e1.y() - e0.y() * e1.x();
    if(!(std::abs(det) > 0)) return Eigen::Vector3d::Constant(-1.);
    const double v = (e2.x() * e1.y() - e2.y() * e1.x()) / det, w = (e0.x() * e2.y() - e0.y() * e2.x()) / det;
    return Eigen::Vector3d(1. - v - w, v, w);
  }

  static std::size_t row_of(double u) { return std::size_t(std::clamp(int(u * rows), 0, int(rows) - 1)); }
  static std::size_t column_of(double angle)
  {
    return std::size_t(std::clamp(int((angle + pi) / (2. * pi) * columns), 0, int(columns) - 1));
  }
  std::size_t cell(const Eigen::Vector2d& q) const { return row_of(q.x()) * columns + column_of(q.y()); }

  void add(std::size_t face, const Corners& c)
  {
    const double u0 = std::min({c[0].x(), c[1].x(), c[2].x()}), u1 = std::max({c[0].x(), c[1].x(), c[2].x()});
    const double a0 = std::min({c[0].y(), c[1].y(), c[2].y()}), a1 = std::max({c[0].y(), c[1].y(), c[2].y()});
    if(a1 < -pi || a0 > pi) return;
    for(std::size_t r = row_of(u0); r <= row_of(u1); ++r)
      for(std::size_t k = column_of(std::max(a0, -pi)); k <= column_of(std::min(a1, pi)); ++k)
        cells_[r * columns + k].push_back({face, c});
  }

  const Indexed_mesh& mesh_;
  std::vector<std::vector<Entry>> cells_;
};

} // namespace

bool tube_chart_start(const Surface& t, const Surface& s, Landmarks& lm, double min_slenderness, Point_matrix& y)
{
  const int loops = static_cast<int>(t.loops.size());
  if(loops < 1 || loops > 2 || int(s.loops.size()) != loops || int(lm.loops.size()) != loops) return false;
  const Loop_match& first = lm.loops[0];
  const Tube from(t, 0, loops == 2 ? 1 : -1, t.loops[0].at(0.));
  const Tube onto(s, first.target, loops == 2 ? lm.loops[1].target : -1, s.loops[first.target].at(first.offset));
  if(!from.valid() || !onto.valid() || from.slenderness() < min_slenderness || onto.slenderness() < min_slenderness)
    return false;
  // The frames start at matched points of the first loops; the other
  // loops' matched points may lie at different angles (the tubes twist
  // differently): the difference is spread along the tube.
  double twist = 0.;
  if(loops == 2)
  {
    const Loop_match& second = lm.loops[1];
    twist = wrapped(onto.angle(s.loops[second.target].at(second.offset), 1.) - from.angle(t.loops[1].at(0.), 1.));
  }
  const Tube_lookup lookup(onto, s.mesh);
  y = lm.motion.apply(t.mesh.points);
  for(Eigen::Index v = 0; v < y.rows(); ++v)
  {
    const double u = from.u(int(v));
    Vec3 p;
    if(lookup.point(u, from.theta(int(v)) + u * twist, p)) y.row(v) = p.transpose();
  }
  // The fit that follows pulls a thin tip back where nothing holds it.
  if(loops == 1) lm.vertex_targets.push_back({from.tip(), s.mesh.points.row(onto.tip()).transpose()});
  return true;
}

} // namespace correspondence
} // namespace internal
} // namespace MPM
} // namespace CGAL
