// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_SURFACE_MESH_REPAIR_H
#define CGAL_MPM_INTERNAL_SURFACE_MESH_REPAIR_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <string>

namespace CGAL {
namespace MPM {
namespace internal {

// Makes `mesh` one that a `Surface_mesh` can hold, as a model keeps its
// training examples: at a non-manifold edge or vertex the faces are pulled
// apart by copies of its vertices (appended, so the indices of the others
// stay), and faces oriented against their neighbours are turned
// (`PMP::orient_polygon_soup()`). Faces keep their order, hence their labels.
// Returns a sentence saying what was changed, or "" when nothing was. Throws
// Input_error naming `source` and the face when the result still cannot be held.
std::string make_surface_mesh_compatible(Indexed_mesh& mesh, const std::string& source);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
