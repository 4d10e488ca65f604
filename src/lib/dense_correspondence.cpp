// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Dense_correspondence.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Laplacian_editing.h>
#include <CGAL/MPM/Part_type.h>
#include <CGAL/MPM/Shape_space.h>
#include <CGAL/MPM/Thin_plate_spline.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

namespace CGAL {
namespace MPM {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;
using Triangle_iterator = std::vector<Kernel::Triangle_3>::const_iterator;
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Triangle_iterator>>>;
using Segment_iterator = std::vector<Kernel::Segment_3>::const_iterator;
using Segment_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_segment_primitive<Kernel, Segment_iterator>>>;
using Vec3 = Eigen::Vector3d;
using Sparse = Eigen::SparseMatrix<double>;

Point_3 to_point(const Vec3& v) { return Point_3(v.x(), v.y(), v.z()); }
Vec3 to_vec(const Point_3& p) { return Vec3(p.x(), p.y(), p.z()); }

double diagonal_of(const Point_matrix& p) { return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(); }

// A boundary loop parametrized by arc length over [0, 1).
struct Loop
{
  std::vector<int> vertices;
  Point_matrix points;
  std::vector<double> arc; // cumulative length at each vertex, closing length last
  Vec3 centroid = Vec3::Zero();

  double length() const { return arc.back(); }
  double parameter(int k) const { return arc[k] / length(); }
  Vec3 at(double u) const
  {
    u -= std::floor(u);
    const double s = u * length();
    const std::size_t k = std::min<std::size_t>(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin(), arc.size() - 1) - 1;
    const double span = arc[k + 1] - arc[k];
    const double t = span > 0 ? (s - arc[k]) / span : 0.;
    const Eigen::Index a = static_cast<Eigen::Index>(k), b = static_cast<Eigen::Index>((k + 1) % vertices.size());
    return (1 - t) * points.row(a).transpose() + t * points.row(b).transpose();
  }
  Point_matrix samples(int count, double offset, int orientation) const
  {
    Point_matrix s(count, 3);
    for(int j = 0; j < count; ++j) s.row(j) = at(offset + orientation * double(j) / count).transpose();
    return s;
  }
};

std::vector<std::vector<int>> loops_of(const Indexed_mesh& mesh)
{
  std::map<std::pair<int, int>, int> uses;
  for(const Triangle& t : mesh.triangles)
    for(int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::multimap<int, int> next;
  for(const Triangle& t : mesh.triangles)
    for(int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      if(uses[{std::min(a, b), std::max(a, b)}] == 1) next.insert({a, b});
    }
  std::vector<std::vector<int>> loops;
  while(!next.empty())
  {
    std::vector<int> loop{next.begin()->first};
    int current = next.begin()->second;
    next.erase(next.begin());
    while(current != loop.front())
    {
      loop.push_back(current);
      const auto it = next.find(current);
      if(it == next.end()) break; // an open chain (non-manifold border): keep what was walked
      current = it->second;
      next.erase(it);
    }
    if(loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

Loop make_loop(const Point_matrix& points, std::vector<int> vertices)
{
  Loop l;
  l.vertices = std::move(vertices);
  const int k = static_cast<int>(l.vertices.size());
  l.points.resize(k, 3);
  for(int i = 0; i < k; ++i) l.points.row(i) = points.row(l.vertices[i]);
  l.arc.assign(1, 0.);
  for(int i = 0; i < k; ++i) l.arc.push_back(l.arc.back() + (l.points.row((i + 1) % k) - l.points.row(i)).norm());
  // The centroid of the polyline, not of its vertices: a remeshed or
  // scanned seam is sampled unevenly, and the vertex mean then drifts
  // towards the dense side, which tilts the axis and turns the lean of a
  // slightly tilted seam by 10 degrees or more.
  l.centroid.setZero();
  for(int i = 0; i < k; ++i)
    l.centroid += 0.5 * (l.points.row(i) + l.points.row((i + 1) % k)).transpose() * (l.arc[i + 1] - l.arc[i]);
  if(l.arc.back() > 0) l.centroid /= l.arc.back();
  return l;
}

class Surface;
Vec3 pole_of(const Surface& s);

// One segment with its search structures.
class Surface
{
public:
  Surface(const Indexed_mesh& m, const std::string& type_name, const std::string& name) : mesh(m)
  {
    const std::string element = "part type \"" + type_name + "\"";
    if(m.number_of_faces() == 0 || m.number_of_vertices() < 3)
      throw Input_error(name, element, "degenerate segment: no triangle");
    if(!m.points.allFinite()) throw Input_error(name, element, "degenerate segment: non-finite coordinates");
    const Point_matrix centred = m.points.rowwise() - m.points.colwise().mean();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(centred.transpose() * centred);
    if(!(pca.eigenvalues()(1) > 1e-12 * pca.eigenvalues()(2)))
      throw Input_error(name, element, "degenerate segment: its points are collinear");
    vertex_normals.assign(std::size_t(m.number_of_vertices()), Vec3::Zero());
    for(const Triangle& t : m.triangles)
    {
      for(int k = 0; k < 3; ++k)
        if(t[k] < 0 || t[k] >= m.number_of_vertices())
          throw Input_error(name, element, "degenerate segment: triangle corner out of range");
      triangles.emplace_back(to_point(m.points.row(t[0])), to_point(m.points.row(t[1])), to_point(m.points.row(t[2])));
      const Vec3 n = (m.points.row(t[1]) - m.points.row(t[0])).transpose().cross((m.points.row(t[2]) - m.points.row(t[0])).transpose());
      normals.push_back(n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero());
      for(int k = 0; k < 3; ++k) vertex_normals[t[k]] += n; // area-weighted
    }
    for(Vec3& n : vertex_normals)
      if(n.norm() > 0) n.normalize();
    tree.insert(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    for(std::vector<int>& vertices : loops_of(m)) loops.push_back(make_loop(m.points, std::move(vertices)));
    std::sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.length() > b.length(); });
    border.resize(loops.size());
    for(std::size_t l = 0; l < loops.size(); ++l)
    {
      const Loop& loop = loops[l];
      const int k = static_cast<int>(loop.vertices.size());
      for(int i = 0; i < k; ++i)
        border[l].segments.emplace_back(to_point(loop.points.row(i)), to_point(loop.points.row((i + 1) % k)));
      border[l].tree = std::make_unique<Segment_tree>(border[l].segments.begin(), border[l].segments.end());
      border[l].tree->accelerate_distance_queries();
    }
    diagonal = diagonal_of(m.points);
    double area = 0.;
    area_centroid.setZero();
    for(const Triangle& t : m.triangles)
    {
      const Vec3 a = m.points.row(t[0]), b = m.points.row(t[1]), c = m.points.row(t[2]);
      const double w = 0.5 * (b - a).cross(c - a).norm();
      area += w;
      area_centroid += w * (a + b + c) / 3.;
    }
    if(area > 0) area_centroid /= area;
    double total = 0.;
    for(const Triangle& t : m.triangles)
      for(int k = 0; k < 3; ++k) total += (m.points.row(t[k]) - m.points.row(t[(k + 1) % 3])).norm();
    edge_length = total / (3. * m.triangles.size());
    if(loops.size() == 1) tip = pole_of(*this);
  }

  Vec3 closest(const Vec3& p, Vec3* normal = nullptr) const
  {
    const auto [q, id] = tree.closest_point_and_primitive(to_point(p));
    if(normal) *normal = normals[id - triangles.begin()];
    return to_vec(q);
  }

  Vec3 closest_on_loop(int l, const Vec3& p, Vec3* tangent = nullptr) const
  {
    const auto [q, id] = border[l].tree->closest_point_and_primitive(to_point(p));
    if(tangent) *tangent = to_vec(id->target()) - to_vec(id->source()), tangent->normalize();
    return to_vec(q);
  }

  const Indexed_mesh& mesh;
  std::vector<Kernel::Triangle_3> triangles;
  std::vector<Vec3> normals;        // per triangle, unit
  std::vector<Vec3> vertex_normals; // unit, zero at an isolated vertex
  Triangle_tree tree;
  std::vector<Loop> loops;
  struct Border
  {
    std::vector<Kernel::Segment_3> segments;
    std::unique_ptr<Segment_tree> tree;
  };
  std::vector<Border> border;
  double diagonal = 0., edge_length = 0.;
  Vec3 area_centroid = Vec3::Zero();
  Vec3 tip = Vec3::Zero();    // pole_of(), for a segment with one loop
  std::vector<int> loop_tags; // per loop, -1 unknown
};

void tag_loops(Surface& s, const std::vector<int>& seam_tags)
{
  for(const Loop& l : s.loops)
  {
    std::map<int, int> count;
    for(int v : l.vertices)
      if(v < int(seam_tags.size()) && seam_tags[v] >= 0) ++count[seam_tags[v]];
    int tag = -1, best = 0;
    for(const auto& [t, c] : count)
      if(c > best)
      {
        best = c;
        tag = t;
      }
    s.loop_tags.push_back(tag);
  }
}

bool tags_agree(const Surface& t, const Surface& s, const std::vector<int>& permutation)
{
  for(std::size_t l = 0; l < permutation.size(); ++l)
  {
    const int a = t.loop_tags[l], b = s.loop_tags[permutation[l]];
    if(a >= 0 && b >= 0 && a != b) return false;
  }
  return true;
}

// How far a loop's plane leans away from the segment's axis (towards
// `axis_point`): the component of its unit normal across the axis, about
// the sine of the lean angle.
Vec3 lean_of(const Loop& l, const Vec3& axis_point, int orientation)
{
  Vec3 normal = Vec3::Zero();
  const Eigen::Index k = l.points.rows();
  for(Eigen::Index i = 0; i < k; ++i)
    normal += (l.points.row(i).transpose() - l.centroid).cross(l.points.row((i + 1) % k).transpose() - l.centroid);
  const Vec3 axis = axis_point - l.centroid;
  if(!(normal.norm() > 0) || !(axis.norm() > 0)) return Vec3::Zero();
  normal.normalize();
  const Vec3 a = axis.normalized();
  return orientation * (normal - normal.dot(a) * a);
}

// Where a loop's plane leans away from the segment's axis, as a point at
// the loop's radius from its centroid: the mitred joint of a bent tube
// tilts its seam towards the bend, which fixes the twist that circular
// seams leave open. Leans under about 6 degrees count less, none (the
// centroid itself) says nothing.
Vec3 tilt_point(const Loop& l, const Vec3& axis_point, int orientation)
{
  const Vec3 lean = lean_of(l, axis_point, orientation);
  if(!(lean.norm() > 1e-6)) return l.centroid;
  const double radius = (l.points.rowwise() - l.centroid.transpose()).rowwise().norm().mean();
  return l.centroid + radius * std::min(1., lean.norm() / 0.1) * lean.normalized();
}

// The tip of a segment with one loop (a fingertip): the surface point
// farthest along the axis from the loop's centroid towards the area
// centroid. On a round cap this is better defined than the vertex
// geodesically farthest from a tilted seam. The farthest vertex alone is
// off the tip by up to half an edge, which tilts a long tube; the centroid
// of the top slice (a fifth of the seam's radius deep), put back on the
// surface, is not.
Vec3 pole_of(const Surface& s)
{
  const Loop& loop = s.loops[0];
  const Vec3 c = loop.centroid;
  if(!((s.area_centroid - c).norm() > 0)) return s.closest(c); // a flat part: no axis
  const Vec3 axis = (s.area_centroid - c).normalized();
  const Eigen::VectorXd height = (s.mesh.points.rowwise() - c.transpose()) * axis;
  const double radius = (loop.points.rowwise() - c.transpose()).rowwise().norm().mean();
  const double top = height.maxCoeff() - 0.2 * radius;
  Vec3 sum = Vec3::Zero();
  double area = 0.;
  for(const Triangle& t : s.mesh.triangles)
  {
    if(height(t[0]) + height(t[1]) + height(t[2]) < 3. * top) continue;
    const Vec3 a = s.mesh.points.row(t[0]), b = s.mesh.points.row(t[1]), d = s.mesh.points.row(t[2]);
    const double w = 0.5 * (b - a).cross(d - a).norm();
    sum += w * (a + b + d) / 3.;
    area += w;
  }
  if(!(area > 0))
  {
    Eigen::Index best;
    height.maxCoeff(&best);
    return s.mesh.points.row(best).transpose();
  }
  return s.closest(sum / area);
}

// Where the cap of a one-loop segment turns towards its tip: the line on
// which the surface normal makes the angle acos(cosine) with the axis (from
// the loop's centroid to the tip), in the half nearer the tip, traced
// across the triangles (linear in the vertex normals) so that it does not
// depend on the sampling. Its centre and mean radius; `found` is false
// when the surface has no such line there (a flat or pointed end).
struct Cap_ring
{
  bool found = false;
  Vec3 axis = Vec3::UnitZ(), centre = Vec3::Zero();
  double radius = 0.;
};

Cap_ring cap_ring(const Surface& x, double cosine)
{
  Cap_ring ring;
  const Vec3 c = x.loops[0].centroid;
  const double length = (x.tip - c).norm();
  if(!(length > 0)) return ring;
  ring.axis = (x.tip - c) / length;
  std::vector<double> value(x.vertex_normals.size());
  for(std::size_t v = 0; v < value.size(); ++v)
    value[v] = x.vertex_normals[v].norm() > 0 ? x.vertex_normals[v].dot(ring.axis) - cosine : -1.;
  double total = 0., height = 0., radius = 0.;
  for(const Triangle& f : x.mesh.triangles)
  {
    Vec3 ends[2];
    int found = 0;
    for(int k = 0; k < 3 && found < 2; ++k)
    {
      const int i = f[k], j = f[(k + 1) % 3];
      if((value[i] < 0) == (value[j] < 0)) continue;
      const double t = value[i] / (value[i] - value[j]);
      ends[found++] = (1. - t) * x.mesh.points.row(i).transpose() + t * x.mesh.points.row(j).transpose();
    }
    if(found < 2) continue;
    const Vec3 mid = 0.5 * (ends[0] + ends[1]) - c;
    const double h = mid.dot(ring.axis);
    if(h < 0.5 * length) continue;
    const double w = (ends[1] - ends[0]).norm();
    total += w;
    height += w * h;
    radius += w * (mid - h * ring.axis).norm();
  }
  if(!(total > 0)) return ring;
  ring.found = true;
  ring.centre = c + (height / total) * ring.axis;
  ring.radius = radius / total;
  return ring;
}

// How a template loop maps onto a segment loop: template parameter u goes
// to `offset + orientation * u` on loop `target`. The orientation is +1 for
// every match: loops run like their triangles on both surfaces, so a map
// that keeps the surface's orientation keeps each loop's direction, and a
// reversed loop pins the seam to its mirror image (a proximal phalanx of a
// real hand came out partly inside out that way).
struct Loop_match
{
  int target = 0;
  int orientation = 1;
  double offset = 0.;
};

// Landmark pairs between the template and one segment.
struct Landmarks
{
  Point_matrix source, target;       // template rest space, segment
  std::vector<Loop_match> loops;     // per template loop
  std::vector<std::pair<int, Vec3>> vertex_targets; // template vertex -> point (user landmarks, extremity)
  int automatic = 0;
  Rigid_motion motion;               // template -> segment
};

Point_matrix stack(const std::vector<Point_matrix>& blocks)
{
  Eigen::Index rows = 0;
  for(const Point_matrix& b : blocks) rows += b.rows();
  Point_matrix r(rows, 3);
  rows = 0;
  for(const Point_matrix& b : blocks)
  {
    r.middleRows(rows, b.rows()) = b;
    rows += b.rows();
  }
  return r;
}

Point_matrix repeated(const Vec3& p, int count) { return p.transpose().replicate(count, 1); }

Point_matrix rows_of(const Point_matrix& p, const std::vector<int>& vertices)
{
  Point_matrix r(vertices.size(), 3);
  for(std::size_t i = 0; i < vertices.size(); ++i) r.row(i) = p.row(vertices[i]);
  return r;
}

double rms(const Point_matrix& a, const Point_matrix& b)
{
  return a.rows() ? std::sqrt((a - b).squaredNorm() / a.rows()) : 0.;
}

// A tube's twist is left open by its geometry (the scores of all twists
// agree to a fraction of a percent); same-type parts of one model are mostly
// placed alike (fingers point the same way), so among near-equal scores the
// alignment rotating least wins: a score grows by this fraction per half turn.
constexpr double rotation_preference = 1.;

// Candidate alignments (loop matching with cyclic shift, or principal
// frames for closed segments), all proper (no reflection), scored by the landmark residual
// after rigid alignment plus the mean distance of template samples to the
// segment: the loops fix the twist of a tube only up to its symmetry, the
// surface decides the rest.
Landmarks match_landmarks(const Surface& t, const Surface& s, const std::vector<int>& user_t,
                          const std::vector<int>& user_s, int samples, bool use_tilt)
{
  const int loops = static_cast<int>(t.loops.size());
  const Point_matrix user_source = rows_of(t.mesh.points, user_t), user_target = rows_of(s.mesh.points, user_s);
  const int user_weight = std::max(1, samples / 2);
  std::vector<Point_matrix> user_src_w(user_weight, user_source), user_tgt_w(user_weight, user_target);

  std::vector<int> probe;
  const int step = std::max(1, t.mesh.number_of_vertices() / 150);
  for(int v = 0; v < t.mesh.number_of_vertices(); v += step) probe.push_back(v);
  const Point_matrix probe_points = rows_of(t.mesh.points, probe);
  const auto surface_distance = [&](const Rigid_motion& m) {
    const Point_matrix moved = m.apply(probe_points);
    double sum = 0.;
    for(Eigen::Index i = 0; i < moved.rows(); ++i)
      sum += (s.closest(moved.row(i).transpose()) - moved.row(i).transpose()).norm();
    return sum / moved.rows();
  };

  struct Candidate
  {
    std::vector<Loop_match> loops;
    Point_matrix source, target;
    Rigid_motion motion;
    double residual = 0.;
    double score = -1.;
    bool tilt = false;
  };
  std::vector<Candidate> candidates;

  const bool extremity = loops == 1;
  const Vec3 &extremity_t = t.tip, &extremity_s = s.tip;
  const int extremity_weight = std::max(1, samples / 4);

  std::vector<Point_matrix> template_samples;
  for(const Loop& l : t.loops) template_samples.push_back(l.samples(samples, 0., 1));
  const auto finish = [&](Candidate& c) {
    c.motion = fit_rigid_motion(c.source, c.target);
    c.residual = rms(c.motion.apply(c.source), c.target);
  };
  // Tilt landmarks of template loop l matched by m, about the axis to the
  // area centroid (one loop: more robust than the extremity) or to the
  // other loop (two loops).
  const int tilt_weight = std::max(1, samples / 2);
  const auto add_tilt = [&](const Loop_match& m, int l, const std::vector<int>& permutation,
                            std::vector<Point_matrix>& src, std::vector<Point_matrix>& tgt) {
    if(loops == 1)
    {
      src.push_back(repeated(tilt_point(t.loops[0], t.area_centroid, 1), tilt_weight));
      tgt.push_back(repeated(tilt_point(s.loops[m.target], s.area_centroid, m.orientation), tilt_weight));
    }
    else if(loops == 2)
    {
      src.push_back(repeated(tilt_point(t.loops[l], t.loops[1 - l].centroid, 1), tilt_weight));
      tgt.push_back(repeated(tilt_point(s.loops[m.target], s.loops[permutation[1 - l]].centroid, m.orientation), tilt_weight));
    }
  };
  // Loop 0 of the template on loop permutation[0] at `offset`: rigid motion
  // from it and the other loops' centroids, then the other loops' best
  // shifts (at `resolution` per turn) under that motion, then the motion of all.
  // With `tilt`, the seams' lean joins the fit; the residual that ranks
  // candidates leaves it out.
  const auto loop_candidate = [&](const std::vector<int>& permutation, int orientation, double offset, int resolution,
                                  bool tilt) {
    Candidate c;
    c.tilt = tilt;
    c.loops.assign(loops, Loop_match());
    c.loops[0] = {permutation[0], orientation, offset};
    std::vector<Point_matrix> src{template_samples[0]},
      tgt{s.loops[permutation[0]].samples(samples, offset, orientation)};
    for(int l = 1; l < loops; ++l)
    {
      src.push_back(repeated(t.loops[l].centroid, samples));
      tgt.push_back(repeated(s.loops[permutation[l]].centroid, samples));
    }
    std::vector<Point_matrix> extra_src, extra_tgt, tilt_src, tilt_tgt;
    if(tilt) add_tilt(c.loops[0], 0, permutation, tilt_src, tilt_tgt);
    if(extremity)
    {
      extra_src.push_back(repeated(extremity_t, extremity_weight));
      extra_tgt.push_back(repeated(extremity_s, extremity_weight));
    }
    extra_src.insert(extra_src.end(), user_src_w.begin(), user_src_w.end());
    extra_tgt.insert(extra_tgt.end(), user_tgt_w.begin(), user_tgt_w.end());
    src.insert(src.end(), extra_src.begin(), extra_src.end());
    tgt.insert(tgt.end(), extra_tgt.begin(), extra_tgt.end());
    src.insert(src.end(), tilt_src.begin(), tilt_src.end());
    tgt.insert(tgt.end(), tilt_tgt.begin(), tilt_tgt.end());
    const Rigid_motion first = fit_rigid_motion(stack(src), stack(tgt));
    for(int l = 1; l < loops; ++l)
    {
      const Point_matrix moved = first.apply(template_samples[l]);
      double best = std::numeric_limits<double>::infinity();
      for(int k = 0; k < resolution; ++k)
      {
        const double d = (moved - s.loops[permutation[l]].samples(samples, double(k) / resolution, 1)).squaredNorm();
        if(d < best)
        {
          best = d;
          c.loops[l] = {permutation[l], 1, double(k) / resolution};
        }
      }
    }
    std::vector<Point_matrix> all_src, all_tgt;
    for(int l = 0; l < loops; ++l)
    {
      all_src.push_back(template_samples[l]);
      all_tgt.push_back(s.loops[c.loops[l].target].samples(samples, c.loops[l].offset, c.loops[l].orientation));
    }
    all_src.insert(all_src.end(), extra_src.begin(), extra_src.end());
    all_tgt.insert(all_tgt.end(), extra_tgt.begin(), extra_tgt.end());
    const Eigen::Index ranked = stack(all_src).rows();
    if(tilt)
      for(int l = 1; l < loops; ++l) add_tilt(c.loops[l], l, permutation, tilt_src, tilt_tgt);
    all_src.insert(all_src.end(), tilt_src.begin(), tilt_src.end());
    all_tgt.insert(all_tgt.end(), tilt_tgt.begin(), tilt_tgt.end());
    c.source = stack(all_src);
    c.target = stack(all_tgt);
    finish(c);
    c.residual = rms(c.motion.apply(c.source.topRows(ranked)), c.target.topRows(ranked));
    return c;
  };
  const auto score = [&](Candidate& c) {
    if(c.score < 0)
      c.score = (c.residual + surface_distance(c.motion)) *
                (1. + rotation_preference * Eigen::AngleAxisd(c.motion.rotation).angle() / 3.141592653589793);
    return c.score;
  };

  if(loops == 0)
  {
    // Closed segments: centroid and principal axes, in the 4 proper sign choices.
    const auto frame = [](const Point_matrix& p, Vec3& c, Eigen::Matrix3d& axes) {
      c = p.colwise().mean().transpose();
      const Point_matrix centred = p.rowwise() - c.transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> e(centred.transpose() * centred / p.rows());
      axes = e.eigenvectors() * e.eigenvalues().cwiseMax(0.).cwiseSqrt().asDiagonal();
    };
    Vec3 ct, cs;
    Eigen::Matrix3d at, as;
    frame(t.mesh.points, ct, at);
    frame(s.mesh.points, cs, as);
    for(int signs = 0; signs < 4; ++signs)
    {
      Candidate c;
      const double s0 = (signs & 1) ? -1. : 1., s1 = (signs & 2) ? -1. : 1.;
      const Eigen::Vector3d flip(s0, s1, s0 * s1);
      c.source.resize(7, 3);
      c.target.resize(7, 3);
      c.source.row(0) = ct.transpose();
      c.target.row(0) = cs.transpose();
      for(int k = 0; k < 3; ++k)
      {
        c.source.row(1 + 2 * k) = (ct + at.col(k)).transpose();
        c.source.row(2 + 2 * k) = (ct - at.col(k)).transpose();
        c.target.row(1 + 2 * k) = (cs + flip[k] * as.col(k)).transpose();
        c.target.row(2 + 2 * k) = (cs - flip[k] * as.col(k)).transpose();
      }
      finish(c);
      candidates.push_back(std::move(c));
    }
  }
  else
  {
    std::vector<int> permutation(loops);
    std::iota(permutation.begin(), permutation.end(), 0);
    // Loops come longest first, so without trying all orders (too many)
    // the length order matches them.
    const bool all_orders = loops <= 5;
    bool any_agrees = false;
    do
      any_agrees = any_agrees || tags_agree(t, s, permutation);
    while(all_orders && std::next_permutation(permutation.begin(), permutation.end()));
    std::iota(permutation.begin(), permutation.end(), 0);
    do
    {
      if(any_agrees && !tags_agree(t, s, permutation)) continue;
      for(int shift = 0; shift < samples; ++shift)
        candidates.push_back(loop_candidate(permutation, 1, double(shift) / samples, samples, use_tilt));
    } while(all_orders && std::next_permutation(permutation.begin(), permutation.end()));
  }

  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.residual < b.residual; });
  candidates.resize(std::min<std::size_t>(candidates.size(), 64));
  std::size_t best = 0;
  for(std::size_t i = 0; i < candidates.size(); ++i)
    if(score(candidates[i]) < score(candidates[best])) best = i;
  Candidate chosen = candidates[best];
  // The coarse search resolves the twist to 1/samples of a turn (15
  // degrees at 24 samples); search between the neighbouring shifts at
  // sixteen times that resolution.
  constexpr int fine = 16;
  if(loops > 0)
  {
    std::vector<int> matched;
    for(const Loop_match& m : chosen.loops) matched.push_back(m.target);
    const Loop_match first = chosen.loops[0];
    for(int k = 1 - fine; k < fine; ++k)
    {
      Candidate c = loop_candidate(matched, first.orientation, first.offset + k / double(fine * samples), fine * samples,
                                   chosen.tilt);
      if(score(c) < score(chosen)) chosen = c;
    }
  }

  // A lone seam that leans (over about 3 degrees, both ways) fixes the
  // twist more finely than the scores above, which barely change with it:
  // the shift, within two coarse steps, whose rigid fit (seam samples and
  // tip, as in the final landmarks) carries the template's lean onto the
  // segment's.
  constexpr double usable_lean = 0.05;
  if(loops == 1 && chosen.tilt && lean_of(t.loops[0], t.area_centroid, 1).norm() > usable_lean
     && lean_of(s.loops[chosen.loops[0].target], s.area_centroid, 1).norm() > usable_lean)
  {
    const Loop_match m = chosen.loops[0];
    const Point_matrix lean_t = tilt_point(t.loops[0], t.area_centroid, 1).transpose();
    const Point_matrix lean_s = tilt_point(s.loops[m.target], s.area_centroid, m.orientation).transpose();
    const auto misfit = [&](double offset) {
      const Rigid_motion motion =
        fit_rigid_motion(stack({template_samples[0], extremity_t.transpose()}),
                         stack({s.loops[m.target].samples(samples, offset, m.orientation), extremity_s.transpose()}));
      return (motion.apply(lean_t) - lean_s).norm();
    };
    double lowest = misfit(m.offset);
    for(int k = -2 * fine; k <= 2 * fine; ++k)
    {
      const double offset = m.offset + k / double(fine * samples), d = misfit(offset);
      if(d < lowest)
      {
        lowest = d;
        chosen.loops[0].offset = offset;
      }
    }
  }

  Landmarks r;
  r.loops = chosen.loops;
  std::vector<Point_matrix> src, tgt;
  for(int l = 0; l < loops; ++l)
  {
    src.push_back(t.loops[l].samples(samples, 0., 1));
    tgt.push_back(s.loops[r.loops[l].target].samples(samples, r.loops[l].offset, r.loops[l].orientation));
  }
  if(loops == 0)
  {
    src.push_back(chosen.source);
    tgt.push_back(chosen.target);
  }
  r.automatic = loops * samples + (loops == 0 ? 7 : 0);
  if(extremity)
  {
    src.push_back(extremity_t.transpose());
    tgt.push_back(extremity_s.transpose());
    ++r.automatic;
  }
  // The seam and the tip leave the stretch along a capped segment to the
  // regularizer, which spreads it over the cap; caps alike in shape are
  // matched alike here: the rings where the cap turns 70 and 45 degrees
  // from the axis, at directions carried over by the rigid fit so far.
  if(extremity)
  {
    const Rigid_motion aligned = fit_rigid_motion(stack(src), stack(tgt));
    const int n = std::max(4, samples / 2);
    for(double cosine : {0.342, 0.707})
    {
      const Cap_ring rt = cap_ring(t, cosine), rs = cap_ring(s, cosine);
      if(!rt.found || !rs.found) continue;
      const Vec3 u = rt.axis.unitOrthogonal(), w = rt.axis.cross(u);
      Point_matrix ring_t(n, 3), ring_s(n, 3);
      for(int j = 0; j < n; ++j)
      {
        const double phi = 2. * 3.141592653589793 * j / n;
        const Vec3 d = std::cos(phi) * u + std::sin(phi) * w;
        Vec3 e = aligned.rotation * d;
        e = (e - e.dot(rs.axis) * rs.axis).normalized();
        ring_t.row(j) = t.closest(rt.centre + rt.radius * d).transpose();
        ring_s.row(j) = s.closest(rs.centre + rs.radius * e).transpose();
      }
      src.push_back(ring_t);
      tgt.push_back(ring_s);
      r.automatic += n;
    }
  }
  src.push_back(user_source);
  tgt.push_back(user_target);
  for(std::size_t k = 0; k < user_t.size(); ++k) r.vertex_targets.push_back({user_t[k], user_target.row(k).transpose()});
  r.source = stack(src);
  r.target = stack(tgt);
  r.motion = fit_rigid_motion(r.source, r.target);
  return r;
}


// Near-coincident centres (a user landmark on a loop sample) would make the
// spline singular; the first of them wins.
Thin_plate_spline fit_spline(const Point_matrix& centres, const Point_matrix& displacements, double scale)
{
  std::vector<int> kept;
  for(Eigen::Index i = 0; i < centres.rows(); ++i)
  {
    bool duplicate = false;
    for(int j : kept)
      if((centres.row(i) - centres.row(j)).norm() <= 1e-7 * scale)
      {
        duplicate = true;
        break;
      }
    if(!duplicate) kept.push_back(static_cast<int>(i));
  }
  return Thin_plate_spline(rows_of(centres, kept), rows_of(displacements, kept));
}

// What the template knows about its own vertices.
struct Template_info
{
  std::vector<int> loop;          // per vertex: template loop, or -1
  std::vector<double> parameter;  // arc-length parameter on that loop
  Sparse laplacian_normal;        // L^T L of the cotangent Laplacian
  double laplacian_scale = 1.;    // mean diagonal of L^T L
  Sparse umbrella;                // uniform Laplacian: v minus the mean of its neighbours
  std::vector<std::vector<int>> neighbours;
};

Template_info make_template_info(const Surface& t)
{
  Template_info info;
  const int n = t.mesh.number_of_vertices();
  info.loop.assign(n, -1);
  info.parameter.assign(n, 0.);
  for(std::size_t l = 0; l < t.loops.size(); ++l)
    for(std::size_t k = 0; k < t.loops[l].vertices.size(); ++k)
    {
      info.loop[t.loops[l].vertices[k]] = static_cast<int>(l);
      info.parameter[t.loops[l].vertices[k]] = t.loops[l].parameter(static_cast<int>(k));
    }
  const Sparse laplacian = cotangent_laplacian(t.mesh);
  info.laplacian_normal = laplacian.transpose() * laplacian;
  info.laplacian_scale = std::max(1e-300, info.laplacian_normal.diagonal().mean());
  info.neighbours.assign(n, {});
  for(const Cluster_edge& e : internal::mesh_edges(t.mesh.triangles))
  {
    info.neighbours[e.source].push_back(e.target);
    info.neighbours[e.target].push_back(e.source);
  }
  std::vector<Eigen::Triplet<double>> entries;
  for(int v = 0; v < n; ++v)
  {
    if(info.neighbours[v].empty()) continue;
    entries.emplace_back(v, v, 1.);
    for(int w : info.neighbours[v]) entries.emplace_back(v, w, -1. / info.neighbours[v].size());
  }
  // Scaled by diagonal / mean edge length: a smooth tangential drift
  // changes the umbrella vectors by about (edge / diagonal)^2 of the drift,
  // so unscaled E_sample would vanish against trace(Sigma) on fine meshes.
  const double scale = t.edge_length > 0 ? t.diagonal / t.edge_length : 1.;
  for(Eigen::Triplet<double>& e : entries) e = Eigen::Triplet<double>(e.row(), e.col(), scale * e.value());
  info.umbrella.resize(n, n);
  info.umbrella.setFromTriplets(entries.begin(), entries.end());
  return info;
}

// Where ICP pulls each template vertex: boundary vertices to their
// arc-length image on the matched loop, landmark vertices to their
// landmark, the others to the closest surface point.
Point_matrix icp_targets(const Surface& s, const Template_info& info, const Landmarks& lm, const Point_matrix& y,
                         std::vector<bool>* constrained = nullptr)
{
  Point_matrix c(y.rows(), 3);
  if(constrained) constrained->assign(y.rows(), false);
  for(Eigen::Index v = 0; v < y.rows(); ++v)
  {
    const int l = info.loop[v];
    if(l >= 0)
    {
      const Loop_match& m = lm.loops[l];
      c.row(v) = s.loops[m.target].at(m.offset + m.orientation * info.parameter[v]).transpose();
      if(constrained) (*constrained)[v] = true;
    }
    else
      c.row(v) = s.closest(y.row(v).transpose()).transpose();
  }
  for(const auto& [v, p] : lm.vertex_targets)
  {
    c.row(v) = p.transpose();
    if(constrained) (*constrained)[v] = true;
  }
  return c;
}

// Coarse deformable ICP: a thin-plate spline through the landmarks and
// farthest-point-sampled free centres, each free centre moved by the mean
// pull of the vertices nearest to it.
Point_matrix spline_icp(const Surface& s, const Template_info& info, const Landmarks& lm, const Point_matrix& base,
                        const Dense_correspondence_options& options, int& iterations)
{
  const Point_matrix fixed_centres = lm.motion.apply(lm.source);
  const Point_matrix fixed_displacements = lm.target - fixed_centres;
  const double scale = diagonal_of(base);
  const int n = static_cast<int>(base.rows());
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<int> region(n, -1);
  for(int v = 0; v < n; ++v)
    for(Eigen::Index k = 0; k < fixed_centres.rows(); ++k)
      distance[v] = std::min(distance[v], (base.row(v) - fixed_centres.row(k)).norm());
  std::vector<int> free;
  while(static_cast<int>(free.size()) < std::min(options.spline_centres, n))
  {
    int far = -1;
    for(int v = 0; v < n; ++v)
      if(info.loop[v] < 0 && (far < 0 || distance[v] > distance[far])) far = v;
    if(far < 0 || !(distance[far] > 1e-3 * scale)) break;
    const int index = static_cast<int>(free.size());
    free.push_back(far);
    for(int v = 0; v < n; ++v)
    {
      const double d = (base.row(v) - base.row(far)).norm();
      if(d < distance[v])
      {
        distance[v] = d;
        region[v] = index;
      }
    }
  }
  const Point_matrix free_centres = rows_of(base, free);
  const Point_matrix centres = stack({fixed_centres, free_centres});
  Point_matrix free_displacements =
    fit_spline(fixed_centres, fixed_displacements, scale).displacement(free_centres);
  Point_matrix y;
  for(int it = 0;; ++it)
  {
    const Thin_plate_spline spline = fit_spline(centres, stack({fixed_displacements, free_displacements}), scale);
    y = base + spline.displacement(base);
    if(it == options.spline_iterations) break;
    ++iterations;
    const Point_matrix pull = icp_targets(s, info, lm, y) - y;
    Point_matrix sum = Point_matrix::Zero(free.size(), 3);
    std::vector<int> count(free.size(), 0);
    for(int v = 0; v < n; ++v)
      if(region[v] >= 0)
      {
        sum.row(region[v]) += pull.row(v);
        ++count[region[v]];
      }
    for(std::size_t j = 0; j < free.size(); ++j)
      if(count[j] > 0) free_displacements.row(j) += sum.row(j) / count[j];
  }
  return y;
}

// Coarse deformable ICP in the PCA space of the segments already done:
// alternate closest points and the space's best fit to them.
Point_matrix shape_space_icp(const Surface& s, const Template_info& info, const Landmarks& lm,
                             const Shape_space& space, const Point_matrix& start,
                             const Dense_correspondence_options& options, int& iterations)
{
  Point_matrix y = start;
  for(int it = 0; it < options.spline_iterations; ++it, ++iterations)
  {
    Eigen::VectorXd coordinates;
    Rigid_motion motion;
    space.fit(icp_targets(s, info, lm, y), coordinates, motion);
    y = motion.apply(space.shape(coordinates));
  }
  return y;
}

// Fine deformable ICP: minimizes sum_v w_v |y_v - c_v|^2 +
// lambda |L (Y - Y_coarse)|^2 for decreasing lambda, so the coarse result's
// shape guides the vertices onto the surface at mesh resolution.
Point_matrix laplacian_icp(const Surface& s, const Template_info& info, const Landmarks& lm, const Point_matrix& coarse,
                           const Dense_correspondence_options& options, int& iterations)
{
  const Eigen::Index n = coarse.rows();
  std::vector<bool> constrained;
  icp_targets(s, info, lm, coarse, &constrained);
  Eigen::VectorXd w(n);
  for(Eigen::Index v = 0; v < n; ++v) w[v] = constrained[v] ? options.boundary_weight : 1.;
  Sparse weights(n, n);
  {
    std::vector<Eigen::Triplet<double>> d;
    for(Eigen::Index v = 0; v < n; ++v) d.emplace_back(v, v, w[v]);
    weights.setFromTriplets(d.begin(), d.end());
  }
  const Eigen::MatrixXd detail = info.laplacian_normal * Eigen::MatrixXd(coarse);
  Point_matrix y = coarse;
  for(double stiffness : {10., 3., 1.})
  {
    const double lambda = stiffness / info.laplacian_scale;
    Eigen::SimplicialLDLT<Sparse> solver(Sparse(weights + lambda * info.laplacian_normal));
    if(solver.info() != Eigen::Success) break;
    for(int it = 0; it < options.laplacian_iterations; ++it, ++iterations)
    {
      const Point_matrix c = icp_targets(s, info, lm, y);
      const Eigen::MatrixXd rhs = w.asDiagonal() * Eigen::MatrixXd(c) + lambda * detail;
      const Eigen::MatrixXd solution = solver.solve(rhs);
      if(!solution.allFinite()) return y;
      y = solution;
    }
  }
  return y;
}

// Interior vertices onto the surface (with the face normal), boundary
// vertices onto their matched loop (with the loop tangent). A thousandth
// of the way back keeps vertices that land on one point (a corner of the
// segment) or on one straight border edge apart, so no template triangle
// becomes degenerate.
void project(const Surface& s, const Template_info& info, const Landmarks& lm, Point_matrix& y,
             std::vector<Vec3>& frame)
{
  frame.resize(y.rows());
  for(Eigen::Index v = 0; v < y.rows(); ++v)
  {
    const int l = info.loop[v];
    const Vec3 p = y.row(v).transpose();
    const Vec3 q = l >= 0 ? s.closest_on_loop(lm.loops[l].target, p, &frame[v]) : s.closest(p, &frame[v]);
    y.row(v) = (q + 1e-3 * (p - q)).transpose();
  }
}

// Energies of eq. 4.1 with the rigid alignment of every segment to the mean
// (generalized Procrustes), so that the pose of a segment is no variance.
struct Alignment
{
  Point_matrix mean;
  std::vector<Rigid_motion> motions; // segment -> mean frame
};

Correspondence_energies evaluate(const std::vector<Point_matrix>& y, const std::vector<const Landmarks*>& landmarks,
                                 const Template_info& info, Alignment& alignment)
{
  const std::size_t m = y.size();
  alignment.mean = y.front();
  alignment.motions.assign(m, Rigid_motion());
  for(int pass = 0; pass < 4; ++pass)
  {
    Point_matrix sum = Point_matrix::Zero(y.front().rows(), 3);
    for(std::size_t i = 0; i < m; ++i)
    {
      alignment.motions[i] = fit_rigid_motion(y[i], alignment.mean);
      sum += alignment.motions[i].apply(y[i]);
    }
    alignment.mean = sum / double(m);
  }
  Correspondence_energies e;
  const Eigen::MatrixXd mean_detail = info.umbrella * Eigen::MatrixXd(alignment.mean);
  for(std::size_t i = 0; i < m; ++i)
  {
    e.trace += (alignment.motions[i].apply(y[i]) - alignment.mean).squaredNorm();
    e.sample += (info.umbrella * Eigen::MatrixXd(y[i]) - mean_detail * alignment.motions[i].rotation).squaredNorm();
    if(landmarks[i])
      for(const auto& [v, p] : landmarks[i]->vertex_targets) e.boundary += (y[i].row(v).transpose() - p).squaredNorm();
  }
  return e;
}

// Gradient descent on eq. 4.1 over the tangent spaces of the segments:
// each vertex moves at most `refinement_step` of its edge length per step,
// then goes back onto its segment (boundary vertices onto their loop).
int refine(const std::vector<std::unique_ptr<Surface>>& surfaces, const std::vector<Landmarks>& landmarks,
           const Template_info& info, int fixed, const Dense_correspondence_options& options,
           std::vector<Point_matrix>& y, Correspondence_energies& before, Correspondence_energies& after)
{
  const std::size_t m = y.size();
  std::vector<const Landmarks*> lm(m, nullptr);
  for(std::size_t i = 0; i < m; ++i)
    if(int(i) != fixed) lm[i] = &landmarks[i];
  std::vector<std::vector<Vec3>> frames(m);
  for(std::size_t i = 0; i < m; ++i)
    if(int(i) != fixed) project(*surfaces[i], info, landmarks[i], y[i], frames[i]);
  const Eigen::Index n = y.front().rows();
  // Step bound per vertex: a fraction of its mean edge length on the segment.
  std::vector<Eigen::VectorXd> bound(m, Eigen::VectorXd::Zero(n));
  for(std::size_t i = 0; i < m; ++i)
    for(Eigen::Index v = 0; v < n; ++v)
    {
      double sum = 0.;
      for(int w : info.neighbours[v]) sum += (y[i].row(v) - y[i].row(w)).norm();
      bound[i][v] = info.neighbours[v].empty() ? 0. : options.refinement_step * sum / info.neighbours[v].size();
    }

  Alignment alignment;
  Correspondence_energies current = evaluate(y, lm, info, alignment);
  before = current;
  const auto total = [&](const Correspondence_energies& e) {
    return e.total(options.sample_weight, options.boundary_weight);
  };
  double alpha = -1.;
  int accepted = 0;
  for(int it = 0; it < options.refinement_iterations && m > 1; ++it)
  {
    std::vector<Point_matrix> direction(m);
    const Eigen::MatrixXd mean_detail = info.umbrella * Eigen::MatrixXd(alignment.mean);
    double largest = 0.;
    for(std::size_t i = 0; i < m; ++i)
    {
      if(int(i) == fixed) continue;
      const Rigid_motion& a = alignment.motions[i];
      Eigen::MatrixXd g = 2. * Eigen::MatrixXd(a.apply(y[i]) - alignment.mean) * a.rotation;
      g += options.sample_weight * 2. * Eigen::MatrixXd(info.umbrella.transpose() *
             (info.umbrella * Eigen::MatrixXd(y[i]) - mean_detail * a.rotation));
      for(const auto& [v, p] : landmarks[i].vertex_targets)
        g.row(v) += options.boundary_weight * 2. * (y[i].row(v).transpose() - p).transpose();
      direction[i] = -g;
      for(Eigen::Index v = 0; v < n; ++v)
      {
        const Vec3 d = direction[i].row(v).transpose();
        const Vec3& f = frames[i][v];
        const Vec3 t = info.loop[v] >= 0 ? Vec3(f.dot(d) * f) : Vec3(d - f.dot(d) * f);
        direction[i].row(v) = t.transpose();
        if(bound[i][v] > 0) largest = std::max(largest, t.norm() / bound[i][v]);
      }
    }
    if(!(largest > 0)) break;
    if(alpha < 0) alpha = 1. / largest;
    bool improved = false;
    for(int attempt = 0; attempt < 10 && !improved; ++attempt)
    {
      std::vector<Point_matrix> trial = y;
      std::vector<std::vector<Vec3>> trial_frames = frames;
      for(std::size_t i = 0; i < m; ++i)
      {
        if(int(i) == fixed) continue;
        for(Eigen::Index v = 0; v < n; ++v)
        {
          Vec3 step = alpha * direction[i].row(v).transpose();
          if(step.norm() > bound[i][v]) step *= bound[i][v] / step.norm();
          trial[i].row(v) += step.transpose();
        }
        project(*surfaces[i], info, landmarks[i], trial[i], trial_frames[i]);
      }
      Alignment trial_alignment;
      const Correspondence_energies e = evaluate(trial, lm, info, trial_alignment);
      // trace(Sigma) is what the refinement is for: it must not grow.
      if(total(e) < total(current) && e.trace <= current.trace)
      {
        improved = total(e) < total(current) * (1. - 1e-7);
        y = std::move(trial);
        frames = std::move(trial_frames);
        alignment = std::move(trial_alignment);
        current = e;
        ++accepted;
        alpha *= 1.5;
        if(!improved) it = options.refinement_iterations; // converged
        improved = true;
      }
      else
        alpha *= 0.3;
    }
    if(!improved) break;
  }
  after = current;
  return accepted;
}

// RMS distance of the segment's vertices to the mapped template surface.
double coverage_residual(const Surface& s, const Point_matrix& y, const std::vector<Triangle>& triangles)
{
  std::vector<Kernel::Triangle_3> mapped;
  for(const Triangle& t : triangles)
  {
    const Kernel::Triangle_3 tri(to_point(y.row(t[0])), to_point(y.row(t[1])), to_point(y.row(t[2])));
    if(!tri.is_degenerate()) mapped.push_back(tri);
  }
  if(mapped.empty()) return 1.;
  Triangle_tree tree(mapped.begin(), mapped.end());
  tree.accelerate_distance_queries();
  double sum = 0.;
  for(Eigen::Index v = 0; v < s.mesh.points.rows(); ++v)
    sum += tree.squared_distance(to_point(s.mesh.points.row(v)));
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
  std::vector<bool> pinned(y.rows(), false);
  for(Eigen::Index v = 0; v < y.rows(); ++v) pinned[v] = info.loop[v] >= 0;
  for(const auto& [v, p] : lm.vertex_targets) pinned[v] = true;
  Point_matrix current = y;
  int rings = 1;
  for(int pass = 0; pass < 60 && !flipped.empty(); ++pass)
  {
    std::vector<bool> moving(y.rows(), false);
    for(int f : flipped)
      for(int v : triangles[f]) moving[v] = true;
    for(int r = 0; r < rings; ++r)
    {
      std::vector<bool> grown = moving;
      for(Eigen::Index v = 0; v < y.rows(); ++v)
        if(moving[v])
          for(int w : info.neighbours[v]) grown[w] = true;
      moving.swap(grown);
    }
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
// the nearest free template vertex moves onto it, unless that turns one of
// its triangles against the surface; a point more than three edges from
// every template vertex is a region the fit missed, not an apex, and stays.
void cover_missed_points(const Surface& s, const Template_info& info, const Landmarks& lm,
                         const std::vector<Triangle>& triangles, Point_matrix& y)
{
  const Eigen::Index n = y.rows();
  std::vector<bool> fixed(std::size_t(n), false);
  for(Eigen::Index v = 0; v < n; ++v) fixed[v] = info.loop[v] >= 0 || info.neighbours[v].empty();
  for(const auto& [v, p] : lm.vertex_targets) fixed[v] = true;
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
  const auto faces_the_surface = [&](int v) {
    for(int f : faces_of[std::size_t(v)])
    {
      const Triangle& t = triangles[std::size_t(f)];
      const Vec3 a = y.row(t[0]), b = y.row(t[1]), c = y.row(t[2]);
      Vec3 normal;
      s.closest((a + b + c) / 3., &normal);
      if((b - a).cross(c - a).dot(normal) <= 0.) return false;
    }
    return true;
  };
  for(int pass = 0; pass < 8; ++pass)
  {
    std::vector<Kernel::Triangle_3> mapped;
    for(const Triangle& t : triangles)
    {
      const Kernel::Triangle_3 tri(to_point(y.row(t[0])), to_point(y.row(t[1])), to_point(y.row(t[2])));
      if(!tri.is_degenerate()) mapped.push_back(tri);
    }
    if(mapped.empty()) return;
    Triangle_tree tree(mapped.begin(), mapped.end());
    tree.accelerate_distance_queries();
    std::vector<std::pair<double, int>> missed;
    for(Eigen::Index p = 0; p < s.mesh.points.rows(); ++p)
    {
      const double d = std::sqrt(tree.squared_distance(to_point(s.mesh.points.row(p))));
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
      const Point_matrix before = y;
      y.row(nearest) = q.transpose();
      // Its neighbours follow halfway, so that its triangles do not become slivers.
      for(int relax = 0; relax < 2; ++relax)
        for(int w : info.neighbours[std::size_t(nearest)])
        {
          if(fixed[std::size_t(w)]) continue;
          Vec3 mean = Vec3::Zero();
          for(int x : info.neighbours[std::size_t(w)]) mean += y.row(x).transpose();
          y.row(w) = s.closest(mean / double(info.neighbours[std::size_t(w)].size())).transpose();
        }
      bool sound = faces_the_surface(nearest);
      for(int w : info.neighbours[std::size_t(nearest)]) sound = sound && faces_the_surface(w);
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

std::string percent(double fraction)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.2g%%", 100. * fraction);
  return text;
}

std::string mirror_warning(const std::string& element, const std::string& segment, const std::string& template_name,
                           double residual, double mirrored_residual)
{
  return segment + " (" + element + ") looks like a mirror image of the template " + template_name +
         ": the mirrored template would cover it to " + percent(mirrored_residual) +
         " of its diagonal, the orientation-preserving fit kept only to " + percent(residual) +
         "; a reflection would turn the part inside out, so it keeps its own orientation. Give it a part type of its "
         "own (a left and a right limb) or landmarks to fit it better";
}

std::string flipped_warning(const std::string& element, const std::string& segment, int flipped, std::size_t faces,
                            double residual)
{
  return segment + " (" + element + "): " + std::to_string(flipped) + " of " + std::to_string(faces) +
         " template triangles (" + percent(double(flipped) / std::max<std::size_t>(1, faces)) +
         ") face against the segment's surface (coverage residual " + percent(residual) +
         " of its diagonal): the correspondence folds there";
}

} // namespace

std::vector<std::vector<int>> boundary_loops(const Indexed_mesh& mesh)
{
  std::vector<Loop> loops;
  for(std::vector<int>& vertices : loops_of(mesh)) loops.push_back(make_loop(mesh.points, std::move(vertices)));
  std::sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.length() > b.length(); });
  std::vector<std::vector<int>> r;
  for(Loop& l : loops) r.push_back(std::move(l.vertices));
  return r;
}

Dense_correspondence compute_dense_correspondence(const std::vector<Correspondence_segment>& segments,
                                                  const std::string& type_name,
                                                  const Dense_correspondence_options& options)
{
  const std::string element = "part type \"" + type_name + "\"";
  if(segments.empty()) throw Input_error("", element, "no segment to put in correspondence");
  const auto progress = [&](const std::string& stage, double fraction) {
    internal::throw_if_cancelled(options.cancel, "correspondence");
    if(options.progress) options.progress(stage, fraction);
  };
  Dense_correspondence result;
  const auto warn = [&](const std::string& message) {
    result.warnings.push_back(message);
    if(options.warning) options.warning(message);
  };
  const std::size_t m = segments.size();
  for(std::size_t i = 0; i < m; ++i)
  {
    const Correspondence_segment& s = segments[i];
    for(std::size_t k = 0; k < s.landmarks.size(); ++k)
      if(s.landmarks[k] < 0 || s.landmarks[k] >= s.mesh.number_of_vertices())
        throw Input_error(s.name, element + ": landmark " + std::to_string(k),
                          "vertex " + std::to_string(s.landmarks[k]) + " is out of range (the segment has " +
                            std::to_string(s.mesh.number_of_vertices()) + " vertices)");
    if(s.landmarks.size() != segments.front().landmarks.size())
      throw Input_error(s.name, element,
                        std::to_string(s.landmarks.size()) + " landmarks but " + segments.front().name + " has " +
                          std::to_string(segments.front().landmarks.size()) +
                          "; every segment of a type needs the same landmarks");
  }
  std::vector<std::unique_ptr<Surface>> surfaces;
  for(const Correspondence_segment& s : segments)
  {
    surfaces.push_back(std::make_unique<Surface>(s.mesh, type_name, s.name));
    tag_loops(*surfaces.back(), s.seam_tags);
  }
  for(std::size_t i = 1; i < m; ++i)
    if(surfaces[i]->loops.size() != surfaces[0]->loops.size())
      throw Input_error(segments[i].name, element,
                        "has " + std::to_string(surfaces[i]->loops.size()) + " boundary loops but " +
                          segments[0].name + " has " + std::to_string(surfaces[0]->loops.size()) +
                          "; segments of one type must have the same seams");

  const Surface& t = *surfaces[0];
  const Template_info info = make_template_info(t);
  // The template reflected through x = 0, triangles reversed so that it
  // stays consistently oriented.
  Indexed_mesh mirrored_template = t.mesh;
  mirrored_template.points.col(0) *= -1.;
  for(Triangle& f : mirrored_template.triangles) std::swap(f[1], f[2]);
  Surface mirror(mirrored_template, type_name, segments[0].name);
  tag_loops(mirror, segments[0].seam_tags);
  const Template_info mirror_info = make_template_info(mirror);
  result.triangles = t.mesh.triangles;
  result.segments.resize(m);
  result.segments[0].positions = result.segments[0].unrefined = t.mesh.points;

  // Most deviating (bounding-box diagonal) from the segments done first.
  std::vector<int> order{0};
  std::vector<bool> done(m, false);
  done[0] = true;
  while(order.size() < m)
  {
    int next = -1;
    double best = -1.;
    for(std::size_t i = 0; i < m; ++i)
    {
      if(done[i]) continue;
      double deviation = std::numeric_limits<double>::infinity();
      for(int j : order) deviation = std::min(deviation, std::abs(surfaces[i]->diagonal - surfaces[j]->diagonal));
      if(deviation > best)
      {
        best = deviation;
        next = static_cast<int>(i);
      }
    }
    done[next] = true;
    order.push_back(next);
  }

  std::vector<Landmarks> landmarks(m);
  std::vector<Point_matrix> positions(m);
  positions[0] = t.mesh.points;
  for(std::size_t rank = 1; rank < m; ++rank)
  {
    const int i = order[rank];
    progress("correspondence of " + type_name, double(rank - 1) / m);
    const Surface& s = *surfaces[i];
    Segment_correspondence& r = result.segments[i];
    r.order = static_cast<int>(rank);
    // One attempt with template `tmpl` (the template or its mirror image).
    struct Attempt
    {
      Segment_correspondence r;
      Landmarks lm;
      Point_matrix y;
      double residual = std::numeric_limits<double>::infinity();
    };
    const auto attempt = [&](const Surface& tmpl, const Template_info& tinfo, bool use_tilt) {
      Attempt a;
      a.r = r;
      a.lm = match_landmarks(tmpl, s, segments[0].landmarks, segments[i].landmarks, options.loop_samples, use_tilt);
      a.r.automatic_landmarks = a.lm.automatic;
      const Point_matrix base = a.lm.motion.apply(tmpl.mesh.points);
      Point_matrix coarse;
      if(options.segments_before_pca > 0 && int(rank) > options.segments_before_pca)
      {
        std::vector<Point_matrix> instances;
        for(std::size_t k = 0; k < rank; ++k) instances.push_back(positions[order[k]]);
        Shape_space_options so;
        so.explained_variance = 1.;
        const Shape_space space = learn_shape_space(instances, so);
        const Point_matrix start =
          base + fit_spline(a.lm.motion.apply(a.lm.source), a.lm.target - a.lm.motion.apply(a.lm.source), s.diagonal)
                   .displacement(base);
        coarse = shape_space_icp(s, tinfo, a.lm, space, start, options, a.r.iterations);
        a.r.used_shape_space = true;
      }
      else
        coarse = spline_icp(s, tinfo, a.lm, base, options, a.r.iterations);
      a.y = laplacian_icp(s, tinfo, a.lm, coarse, options, a.r.iterations);
      std::vector<Vec3> frame;
      project(s, tinfo, a.lm, a.y, frame);
      for(const auto& [v, p] : a.lm.vertex_targets) a.y.row(v) = p.transpose();
      a.residual = coverage_residual(s, a.y, t.mesh.triangles);
      return a;
    };
    // The lean of a lone seam is a cue at a mitred joint but arbitrary at a
    // hand-made cut: with one loop, both are tried and the one covering the
    // segment better wins (the lean on near ties: within a quarter). A poor
    // fit with more loops gets the second try as well.
    const auto best_of = [&](const Surface& tmpl, const Template_info& tinfo) {
      Attempt best = attempt(tmpl, tinfo, true);
      if(tmpl.loops.size() == 1 || best.residual > options.mirror_check_residual)
      {
        Attempt other = attempt(tmpl, tinfo, false);
        other.r.iterations += best.r.iterations;
        if(other.residual < 0.75 * best.residual) best = std::move(other);
      }
      return best;
    };
    Attempt chosen = best_of(t, info);
    // A poor fit may be a mirror image (a left and a right limb). The
    // mirrored template is tried only to say so: its positions would carry
    // the template's triangles inside out, so the orientation-preserving
    // fit is kept whatever the mirror covers.
    if(chosen.residual > options.mirror_check_residual)
    {
      const Attempt reflected = best_of(mirror, mirror_info);
      if(reflected.residual < 0.75 * chosen.residual)
      {
        chosen.r.mirrored = true;
        warn(mirror_warning(element, segments[i].name, segments[0].name, chosen.residual, reflected.residual));
      }
    }
    r = chosen.r;
    r.unrefined = positions[i] = chosen.y;
    landmarks[i] = chosen.lm;
  }

  std::vector<Point_matrix> unrefined = positions;
  if(options.refine && m > 1)
  {
    progress("refinement of " + type_name, double(m - 1) / m);
    result.refinement_iterations = refine(surfaces, landmarks, info, 0, options, positions, result.before, result.after);
  }
  else
  {
    std::vector<const Landmarks*> lm(m, nullptr);
    for(std::size_t i = 1; i < m; ++i) lm[i] = &landmarks[i];
    Alignment alignment;
    result.before = result.after = evaluate(positions, lm, info, alignment);
  }
  for(std::size_t i = 0; i < m; ++i)
  {
    if(i > 0)
    {
      unfold(*surfaces[i], info, landmarks[i], result.triangles, positions[i]);
      cover_missed_points(*surfaces[i], info, landmarks[i], result.triangles, positions[i]);
    }
    result.segments[i].positions = positions[i];
    result.segments[i].unrefined = unrefined[i];
    result.segments[i].residual = i == 0 ? 0. : coverage_residual(*surfaces[i], positions[i], result.triangles);
    result.segments[i].flipped_faces = static_cast<int>(flipped_faces(*surfaces[i], positions[i], result.triangles).size());
    const double fraction = double(result.segments[i].flipped_faces) / std::max<std::size_t>(1, result.triangles.size());
    if(fraction > options.flipped_warning_fraction)
      warn(flipped_warning(element, segments[i].name, result.segments[i].flipped_faces, result.triangles.size(),
                           result.segments[i].residual));
  }
  progress("correspondence of " + type_name, 1.);
  return result;
}

} // namespace MPM
} // namespace CGAL
