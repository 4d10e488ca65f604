// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_CORRESPONDENCE_SURFACE_H
#define CGAL_MPM_INTERNAL_CORRESPONDENCE_SURFACE_H

// The pieces of dense correspondence (dense_correspondence.cpp), shared by
// its stages: a segment with its search structures and boundary loops
// (correspondence_surface.cpp), landmark matching
// (correspondence_landmarks.cpp), the ICP fits and the refinement of eq.
// 4.1 (correspondence_fitting.cpp), and the repairs of folds and missed
// extremities (correspondence_repair.cpp, correspondence_chart.cpp).

#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Part_type.h>
#include <CGAL/MPM/Model/Shape_space.h>
#include <CGAL/MPM/Correspondence/Thin_plate_spline.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {
namespace correspondence {

using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;
using Triangle_iterator = std::vector<Kernel::Triangle_3>::const_iterator;
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, Triangle_iterator>>>;
using Segment_iterator = std::vector<Kernel::Segment_3>::const_iterator;
using Segment_tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_segment_primitive<Kernel, Segment_iterator>>>;
using Vec3 = Eigen::Vector3d;
using Sparse = Eigen::SparseMatrix<double>;

// Between Eigen and CGAL points.
inline Point_3 to_point(const Vec3& v) { return Point_3(v.x(), v.y(), v.z()); }
inline Vec3 to_vec(const Point_3& p) { return Vec3(p.x(), p.y(), p.z()); }

// A boundary loop parametrized by arc length over [0, 1).
struct Loop
{
  std::vector<int> vertices;
  Point_matrix points;
  std::vector<double> arc; // cumulative length at each vertex, closing length last
  Vec3 centroid = Vec3::Zero();

  double length() const { return arc.back(); }
  // Mean distance of the loop's vertices to its centroid.
  double mean_radius() const { return (points.rowwise() - centroid.transpose()).rowwise().norm().mean(); }
  // Sum of the cross products of consecutive vertices about the centroid:
  // along the loop's normal as its direction gives it (twice its area for
  // a planar loop).
  Vec3 area_vector() const
  {
    Vec3 sum = Vec3::Zero();
    const Eigen::Index k = points.rows();
    for(Eigen::Index i = 0; i < k; ++i)
      sum += (points.row(i).transpose() - centroid).cross(points.row((i + 1) % k).transpose() - centroid);
    return sum;
  }
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

// The boundary loops of a mesh, each as its vertices in order.
std::vector<std::vector<int>> loops_of(const Indexed_mesh& mesh);
// A loop over `vertices` (rows of `points`), parametrized by arc length.
Loop make_loop(const Point_matrix& points, std::vector<int> vertices);

class Surface;

// The tip of a segment with one loop (see correspondence_surface.cpp).
Vec3 pole_of(const Surface& s);

// One segment with its search structures.
class Surface
{
public:
  // Throws Input_error naming `name` for a degenerate segment.
  Surface(const Indexed_mesh& m, const std::string& type_name, const std::string& name);

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

// Tags each loop of `s` with the seam tag most of its vertices carry (-1: none).
void tag_loops(Surface& s, const std::vector<int>& seam_tags);

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

// The blocks (k_i x 3) one below the other.
inline Point_matrix stack(const std::vector<Point_matrix>& blocks)
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

// Rows `vertices` of `p`.
inline Point_matrix rows_of(const Point_matrix& p, const std::vector<int>& vertices)
{
  Point_matrix r(vertices.size(), 3);
  for(std::size_t i = 0; i < vertices.size(); ++i) r.row(i) = p.row(vertices[i]);
  return r;
}

// Candidate alignments of the template `t` onto the segment `s` (see correspondence_landmarks.cpp).
Landmarks match_landmarks(const Surface& t, const Surface& s, const std::vector<int>& user_t,
                          const std::vector<int>& user_s, int samples, bool use_tilt);

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

// The mean of the segments and the rigid motion of each onto it.
struct Alignment
{
  Point_matrix mean;
  std::vector<Rigid_motion> motions; // segment -> mean frame
};

// The stages of correspondence_fitting.cpp (comments there).
Thin_plate_spline fit_spline(const Point_matrix& centres, const Point_matrix& displacements, double scale);
Template_info make_template_info(const Surface& t);
Point_matrix spline_icp(const Surface& s, const Template_info& info, const Landmarks& lm, const Point_matrix& base,
                        const Dense_correspondence_options& options, int& iterations);
Point_matrix shape_space_icp(const Surface& s, const Template_info& info, const Landmarks& lm,
                             const Shape_space& space, const Point_matrix& start,
                             const Dense_correspondence_options& options, int& iterations);
Point_matrix laplacian_icp(const Surface& s, const Template_info& info, const Landmarks& lm, const Point_matrix& coarse,
                           const Dense_correspondence_options& options, int& iterations);
void project(const Surface& s, const Template_info& info, const Landmarks& lm, Point_matrix& y,
             std::vector<Vec3>& frame);
Correspondence_energies evaluate(const std::vector<Point_matrix>& y, const std::vector<const Landmarks*>& landmarks,
                                 const Template_info& info, Alignment& alignment);
int refine(const std::vector<std::unique_ptr<Surface>>& surfaces, const std::vector<Landmarks>& landmarks,
           const Template_info& info, int fixed, const Dense_correspondence_options& options,
           std::vector<Point_matrix>& y, Correspondence_energies& before, Correspondence_energies& after);

// The repairs of correspondence_repair.cpp (comments there).
std::vector<bool> pinned_vertices(const Template_info& info, const Landmarks& lm);
std::vector<bool> vertices_near(const std::vector<int>& faces, const std::vector<Triangle>& triangles,
                                const std::vector<std::vector<int>>& neighbours, int rings);
double coverage_residual(const Surface& s, const Point_matrix& y, const std::vector<Triangle>& triangles);
std::vector<int> flipped_faces(const Surface& s, const Point_matrix& y, const std::vector<Triangle>& triangles);
void unfold(const Surface& s, const Template_info& info, const Landmarks& lm, const std::vector<Triangle>& triangles,
            Point_matrix& y);
// The repair of correspondence_chart.cpp: folds unfold() leaves, opened in
// a chart of a segment with one or two loops.
void unfold_in_chart(const Surface& s, const Template_info& info, const Landmarks& lm,
                     const std::vector<Triangle>& triangles, Point_matrix& y);
// The start of correspondence_tube_chart.cpp: the template placed on a
// segment with one or two loops through a chart along both tubes (position
// along the axis, angle about it), where the rigid start and a spline
// cannot follow a bent or curled limb; with one loop the template's tip is
// pinned on the segment's (a landmark added to `lm`). False (y and lm
// untouched) unless both are tubes at least `min_slenderness` times longer
// than wide.
bool tube_chart_start(const Surface& t, const Surface& s, Landmarks& lm, double min_slenderness, Point_matrix& y);
void cover_missed_points(const Surface& s, const Template_info& info, const Landmarks& lm,
                         const std::vector<Triangle>& triangles, Point_matrix& y);

} // namespace correspondence
} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
