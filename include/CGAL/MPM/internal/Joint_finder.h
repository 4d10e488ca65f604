// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_JOINT_FINDER_H
#define CGAL_MPM_INTERNAL_JOINT_FINDER_H

#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/internal/Curve_skeleton.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// The limb around a point: a point on the skeleton, its direction and the
// limb's radius there.
struct Limb_axis
{
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), direction = Eigen::Vector3d::UnitZ();
  double radius = 0.;
};

// A closed section of the mesh by a plane, as the vertices on the plane's
// positive side of its crossing edges, in order (consecutive ones share an edge).
struct Section
{
  std::vector<int> loop;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double spread = 0.;   // largest distance of a loop vertex from the axis point
  double weighted = 0.; // crease-weighted length: lower for a narrow section along a concave crease
  double off_axis = 0.; // distance of the centre from the axis point
  Limb_axis axis;       // the limb it goes around
  double shift = 0.;    // how far its plane was moved along the axis from the vertex
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // of its plane
};

// Sections across the limbs of a closed, connected mesh, from CGAL's curve
// skeleton: what one click per joint (`cut_at_vertices()`) and the proposed
// joints (`propose_joints()`) look for.
class Joint_finder
{
public:
  using Vector = Eigen::Vector3d;

  // Throws Input_error naming the mesh for holes, several components or a
  // skeleton that cannot be computed.
  Joint_finder(const Indexed_mesh& m, const Joint_cutting_options& options, const std::string& source);

  // The section for a click at `v`: through it across the limb under it, or
  // a nearby one within the search range. Throws Input_error naming `v`.
  Section find(int v) const;

  // The loop through `v` once around the limb of `s` (a section through
  // `v`) of least crease-weighted length, within `band` limb radii of the
  // section's plane and one and a half times its reach from the axis: the
  // crease a person follows when cutting there, which may be oblique to
  // the limb or curved. `s` itself when no loop there is cheaper. The loop
  // does not step along an edge of the closed path `avoid` (a cut made).
  Section snapped(int v, const Section& s, double band, const std::vector<int>& avoid = {}) const;

  // The closed section by the plane through `v` moved by `t` along the axis,
  // with the given normal: the loop through `v` when `through_click` and there
  // is one, else the loop centred nearest the axis.
  Section section(int v, const Limb_axis& axis, double t, const Vector& normal, bool through_click) const;

  // Where a limb flares into a thicker body (a finger's base on the palm),
  // the click lies off the limb's own axis and the body fits it better: the
  // narrowest small section across the limb much thinner than `found`'s that
  // passes near `v`, within the search range. Empty loop: none.
  Section thinner_limb_section(int v, const Section& found) const;

  // A small closed loop around its limb's axis, with enough vertices.
  bool acceptable(const Section& s) const;

  // `direction` and directions tilted from it by each angle (degrees)
  // towards eight directions around it.
  static std::vector<Vector> tilted(const Vector& direction, const std::vector<double>& angles);

  // The limb axis along skeleton edge `e` (see `skeleton_edges()`) at the
  // foot of `p` on it, its direction smoothed over about a limb radius.
  Limb_axis edge_axis(std::size_t e, const Vector& p) const;

  [[noreturn]] void fail(int v, const std::string& problem) const;

  const Curve_skeleton& skeleton() const { return skeleton_; }
  // Node pairs of the skeleton's edges (smaller first) and the limb's radius around each.
  const std::vector<std::pair<int, int>>& skeleton_edges() const { return skeleton_edges_; }
  const std::vector<double>& edge_radius() const { return edge_radius_; }
  const Indexed_mesh& mesh() const { return m_; }
  const std::string& source() const { return source_; }
  const Joint_cutting_options& options() const { return options_; }

private:
  void check_closed_and_connected() const;
  Vector point(int v) const { return m_.points.row(v).transpose(); }
  std::vector<Limb_axis> limb_axes(int v) const;
  Section narrowest_within_range(int v, const Limb_axis& axis) const;
  double edge_misfit(std::size_t e, const Vector& p) const;
  void measure_skeleton_edges();
  std::vector<char> nodes_within(int node, int hops) const;
  Vector walk(int from, int previous, double length) const;
  template <class Crossing>
  Section trace(Indexed_surface_mesh::Halfedge_index start, const Crossing& crossing,
                const std::vector<char>& positive, std::vector<char>& visited) const;
  double edge_weight(int a, int b) const;

  const Indexed_mesh& m_;
  Joint_cutting_options options_;
  std::string source_;
  Indexed_surface_mesh surface_;
  Curve_skeleton skeleton_;
  std::vector<std::pair<int, int>> skeleton_edges_;
  std::vector<double> edge_radius_;
  std::vector<double> weight_; // crease weights at feature weight 1, for ranking sections
};

// `cut_at_vertices()` with the finder of its mesh (and its options) already built.
Joint_cutting_result cut_at_vertices(const Joint_finder& finder, const std::vector<int>& vertices);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
