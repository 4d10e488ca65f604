// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_FREE_SITE_CAPPING_H
#define CGAL_MPM_FREE_SITE_CAPPING_H

#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Closes the holes an assembly has where a boundary site is free (a
/// branch removed from a closed model leaves its seam loop open on the
/// part it hung from): each border loop of `a.mesh` whose vertices all lie
/// on free boundary sites (`free_sites()`) is filled by CGAL's
/// `Polygon_mesh_processing::triangulate_refine_and_fair_hole()`, so that
/// the cap continues the part's surface smoothly. The cap's vertices and
/// faces are appended to `a.mesh` (its faces belong to the node whose site
/// they close, in `a.face_nodes` and `a.face_types`); other holes (an
/// open training mesh) are left as they are. `a.problem` gets the cap's
/// vertices and faces too, and one cluster per cap after the nodes' and
/// edges' (no modes, its target the cap as made), so that the capped
/// assembly solved again (dragged, in the demo) keeps each cap's shape,
/// turned with its part. Returns the number of holes filled.
/// Throws `Input_error` when there is a free site to cap but the assembly
/// is not a manifold surface (a halfedge structure cannot hold it).
int cap_free_sites(const Morphable_part_model& model, Assembly& a);

} // namespace MPM
} // namespace CGAL

#endif
