// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_SURFACE_SOUNDNESS_H
#define CGAL_MPM_SURFACE_SOUNDNESS_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <CGAL/number_type_config.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Whether a surface made by the package is whole and sound: what a user
/// sees as gaps at seams, parts come apart, inside-out or folded faces.
struct Surface_soundness
{
  int components = 0;          ///< face-connected pieces
  int border_edges = 0;        ///< edges of one triangle (open seams, holes)
  int non_manifold_edges = 0;  ///< edges of more than two triangles
  /// Pairs of intersecting faces; -1 when the faces do not form a polygon
  /// mesh (non-manifold or inconsistently oriented), where CGAL cannot tell.
  int self_intersections = 0;
  int degenerate_faces = 0;    ///< faces of (numerically) zero area
  /// Faces whose normal turned by more than 90 degrees against the same
  /// face of the reference (-1 without a reference).
  int flipped_faces = -1;
  /// Faces turned inside out within their group (for an edit, their part):
  /// the normal points against the reference's once the best rotation of
  /// the group (Kabsch) is taken out, so a part that turns as a whole, as a
  /// bent finger does, counts none. -1 without a reference.
  int inverted_faces = -1;
};

/// \ingroup PkgMPMRef
/// Checks `mesh` with CGAL's Polygon_mesh_processing (connected components,
/// self-intersections, degenerate faces). With `reference` (the same
/// connectivity at other positions, for example before an edit) also counts
/// the faces the edit flipped and those it turned inside out within their
/// group in `face_groups` (one group id per face, for example a model's
/// `Training_example::face_labels`; without it the mesh is one group).
Surface_soundness check_surface(const Indexed_mesh& mesh, const Indexed_mesh* reference = nullptr,
                                const std::vector<int>* face_groups = nullptr);

/// \ingroup PkgMPMRef
/// The pairs of intersecting faces of `mesh` (face indices, CGAL's
/// `self_intersections`), what `Surface_soundness::self_intersections`
/// counts. Returns false, with `pairs` empty, when the faces do not form a
/// polygon mesh (non-manifold or inconsistently oriented).
bool self_intersecting_faces(const Indexed_mesh& mesh, std::vector<std::pair<int, int>>& pairs);

/// \ingroup PkgMPMRef
/// The faces of `mesh` turned inside out against `reference` (the same
/// triangles at other positions) within their group in `face_groups` (one
/// group id per face; without it the mesh is one group): the face's normal
/// points against the reference's once the group's best rotation (Kabsch)
/// is taken out. See `Surface_soundness::inverted_faces`.
std::vector<int> inverted_faces(const Indexed_mesh& mesh, const Indexed_mesh& reference,
                                const std::vector<int>* face_groups = nullptr);

/// \ingroup PkgMPMRef
/// The faces of `mesh` folded over against `reference` (the same triangles
/// at other positions): the face's normal points against the reference's
/// once the best rotation (Kabsch) of each of its corners' two-ring
/// neighbourhoods is taken out. Unlike `inverted_faces()`, a part bent by
/// more than 90 degrees along its length counts none: only a crease where
/// the surface turns back on itself does. `unfold_faces()` takes these out.
std::vector<int> locally_inverted_faces(const Indexed_mesh& mesh, const Indexed_mesh& reference);

/// \ingroup PkgMPMRef
/// Faces of `mesh` that lie turned over on `surface`, which they
/// approximate (for example a learned example against its input): the
/// face's normal points against the normal of the face of `surface`
/// nearest to its centroid (CGAL's `AABB_tree`). These are folds of the
/// correspondence; an edit that unfolds them inverts them against the rest.
std::vector<int> folded_faces(const Indexed_mesh& mesh, const Indexed_mesh& surface);

/// \ingroup PkgMPMRef
/// Faces of `mesh` that stand out of the surface as spikes: at least
/// `sharp_edges` of their three edges fold by more than `angle` (radians;
/// the angle between the two faces' normals); with 2, also slivers creased
/// along two edges. A correspondence leaves a few next to seams; an edit
/// that flattens one turns it against its rest normal, which
/// `inverted_faces()` then counts although nothing turned inside out.
std::vector<int> spike_faces(const Indexed_mesh& mesh, double angle = CGAL_PI / 3., int sharp_edges = 3);

/// \ingroup PkgMPMRef
/// Symmetric Hausdorff distance between two surfaces, approximated by
/// sampling both (CGAL's `approximate_Hausdorff_distance`), over the
/// bounding-box diagonal of `b`.
double relative_hausdorff_distance(const Indexed_mesh& a, const Indexed_mesh& b);

} // namespace MPM
} // namespace CGAL

#endif
