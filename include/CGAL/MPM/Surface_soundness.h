// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_SURFACE_SOUNDNESS_H
#define CGAL_MPM_SURFACE_SOUNDNESS_H

#include <CGAL/MPM/Indexed_mesh.h>

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
};

/// \ingroup PkgMPMRef
/// Checks `mesh` with CGAL's Polygon_mesh_processing (connected components,
/// self-intersections, degenerate faces). With `reference` (the same
/// connectivity at other positions, for example before an edit) also counts
/// the faces the edit flipped.
Surface_soundness check_surface(const Indexed_mesh& mesh, const Indexed_mesh* reference = nullptr);

/// \ingroup PkgMPMRef
/// Symmetric Hausdorff distance between two surfaces, approximated by
/// sampling both (CGAL's `approximate_Hausdorff_distance`), over the
/// bounding-box diagonal of `b`.
double relative_hausdorff_distance(const Indexed_mesh& a, const Indexed_mesh& b);

} // namespace MPM
} // namespace CGAL

#endif
