// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_JOINT_CUTTING_H
#define CGAL_MPM_JOINT_CUTTING_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Options of `cut_at_vertices()`.
struct Joint_cutting_options
{
  /// Strength of the crease term of the final geodesic loop, as
  /// `Cutting_options::feature_weight`. Must be finite and >= 0.
  double feature_weight = 1.;
  /// When the section through the clicked vertex is not a small loop around
  /// the limb (it runs into the body or a neighbouring limb), how far, in
  /// limb radii, to look along the limb (and tilted by up to 40 degrees) for
  /// the narrowest, most concave small section instead; 0: never. Must be
  /// finite and >= 0.
  double search_range = 0.5;
  /// How far, in limb radii, the cut may leave the plane of the section to
  /// follow the crease: the loop through the clicked vertex once around the
  /// limb of least crease-weighted length within that distance of the
  /// plane. People cut along the crease, which is often oblique to the limb
  /// or curved (a knuckle, a finger's base on the palm); 0 keeps the planar
  /// section. Must be finite and >= 0.
  double snap_band = 0.5;
  /// Vertices of the loop kept as the cut's points; the feature-weighted
  /// shortest paths between them form the loop. At least 3.
  int anchors = 6;
  /// A section with fewer distinct vertices means the mesh is too coarse
  /// to cut there. At least 3.
  int minimum_section_vertices = 6;
  /// Leave out a vertex whose cut cannot be found (on the body, too coarse
  /// there, a joint already clicked) and report it in
  /// `Joint_cutting_result::skipped` instead of throwing, so that one bad
  /// click among many does not lose the others.
  bool skip_unfound = false;
};

/// \ingroup PkgMPMRef
/// A clicked vertex left out by `Joint_cutting_options::skip_unfound`.
/// `Vertex` names a vertex: its index in the indexed mesh (`Skipped_click`)
/// or its descriptor in the user's face graph (`Face_graph_cutting.h`).
template <class Vertex>
struct Basic_skipped_click
{
  Vertex vertex{};    ///< the clicked vertex
  std::string reason; ///< the message the error would have had
};

/// \ingroup PkgMPMRef
/// A click left out, on the indexed mesh.
using Skipped_click = Basic_skipped_click<int>;

/// \ingroup PkgMPMRef
/// One cut found from one clicked vertex; `Vertex` as for `Basic_skipped_click`.
template <class Vertex>
struct Basic_joint_cut
{
  Vertex vertex{};              ///< the clicked vertex
  std::vector<Vertex> path;     ///< closed vertex path of the cut (ends with its first vertex)
  double length = 0.;           ///< Euclidean length of `path`
  double limb_radius = 0.;      ///< mean distance of the limb's surface from its axis there
  double shift = 0.; ///< how far the chosen section moved along the limb (see `Joint_cutting_options::search_range`)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< centroid of the path's vertices
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();   ///< unit direction of the limb (sign arbitrary)
};

/// \ingroup PkgMPMRef
/// A cut found on the indexed mesh.
using Joint_cut = Basic_joint_cut<int>;

/// \ingroup PkgMPMRef
/// The cuts found at clicked vertices and the clicks left out; what cutting
/// the user's face graph returns, the labels being in its face label map.
template <class Vertex>
struct Joint_cuts
{
  std::vector<Basic_joint_cut<Vertex>> cuts; ///< one per clicked vertex found, in the given order
  /// Clicks left out (only with `Joint_cutting_options::skip_unfound`).
  std::vector<Basic_skipped_click<Vertex>> skipped;
};

/// \ingroup PkgMPMRef
/// The cuts on the indexed mesh, and the mesh labelled by them.
struct Joint_cutting_result : Joint_cuts<int>
{
  Labeled_mesh mesh; ///< input geometry, one label per face (regions numbered by their first face)
};

/// \ingroup PkgMPMRef
/// One click per joint: for each of `vertices`, finds the closed cut around
/// the limb through or next to it and labels the regions the cuts separate.
/// The limb's axis comes from CGAL's mean curvature flow curve skeleton: the
/// skeleton edges near the node the vertex contracted to whose limb surface
/// the vertex lies on (its distance to the edge within half the limb's
/// radius of that radius): the eight that fit best, and the best fitting
/// one of a limb thinner than 0.6 times the best fit's radius (at a limb's
/// base, the body's edges fit as well). The cut starts as the narrowest section of the
/// mesh through the vertex across one of these axes (the plane perpendicular
/// to it or tilted by up to 20 degrees) that is a small loop around the axis,
/// or a nearby one (see `Joint_cutting_options::search_range`). It snaps to
/// the crease as the loop through the vertex around the limb of least
/// crease-weighted length near that plane (`Joint_cutting_options::snap_band`),
/// traced as the feature-weighted geodesic loop of `cut_mesh()` through
/// `Joint_cutting_options::anchors` of its vertices, the clicked vertex
/// first. A snapped loop of fewer than `minimum_section_vertices` vertices
/// is not taken. Where a limb flares into a thicker body (the click lies
/// within 2.5 radii of the axis of a limb thinner than 0.6 times the
/// section's radius, and the section is not a small loop around that limb),
/// the narrowest section across the thinner limb within the search range is
/// snapped too, and the cheaper of the two snapped loops is the cut. When a
/// click's snapped cut runs along or crosses a cut already made (both
/// clicks snapped to one crease), the section through the click is taken
/// instead if it goes around the same limb, else the click's loop snapped
/// again kept off that cut's edges if it follows a crease of its own
/// (crease-weighted length below 0.8 of its length); when the cut made runs
/// through the click, the earlier click's loop is snapped off the new cut
/// instead, on the same condition: two cuts a ring of faces apart bound a
/// thin ring, as people cut where an arm leaves the body.
///
/// Throws `Input_error` naming the vertex for: a vertex out of range or in
/// no face; a vertex on the body (no limb axis passes under it); a section
/// that is not a small closed loop around the axis, nor any within the search
/// range; a section with fewer than `minimum_section_vertices` vertices (a
/// mesh too coarse there); a section whose points cannot be joined in order
/// by `cut_mesh()`; two vertices on one joint (the same vertex twice, or a
/// click whose cut, snapped or through the click, would cross a cut already
/// made or share an edge with it; a cut around another limb may share less
/// than a quarter of its edges). Also for a mesh with holes or several
/// components, and as `cut_mesh()` when the cuts together do not separate the
/// mesh. The result is the same on every run (the skeletonization's own
/// mesh is allocated in a fixed order, see doc/MPM/Cutting.md).
Joint_cutting_result cut_at_vertices(const Indexed_mesh& mesh, const std::vector<int>& vertices,
                                     const Joint_cutting_options& options = Joint_cutting_options(),
                                     const std::string& mesh_source = "mesh");

namespace internal {
class Joint_finder;
}

/// \ingroup PkgMPMRef
/// `cut_at_vertices()` on one mesh, click after click: the curve skeleton
/// and the crease weights are computed once, when the cutter is made, so an
/// interactive tool re-cuts the mesh at each new click without them (about a
/// second on a 7,000-vertex hand). The mesh must outlive the cutter.
class Joint_cutter
{
public:
  /// Throws `Input_error` naming the mesh for options out of range, a mesh
  /// with holes or several components, or one whose skeleton cannot be computed.
  explicit Joint_cutter(const Indexed_mesh& mesh, const Joint_cutting_options& options = Joint_cutting_options(),
                        const std::string& mesh_source = "mesh");
  ~Joint_cutter();
  /// As `cut_at_vertices()` with this cutter's mesh and options.
  Joint_cutting_result cut(const std::vector<int>& vertices) const;

private:
  std::unique_ptr<internal::Joint_finder> finder_;
};

} // namespace MPM
} // namespace CGAL

#endif
