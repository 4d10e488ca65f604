// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_CREASE_WEIGHTS_H
#define CGAL_MPM_INTERNAL_CREASE_WEIGHTS_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// Cost of each edge of `surface` (indexed by edge index) for cuts that snap
// to creases: length / (1 + feature_weight * concave bending angle / mean
// absolute bending angle). `mesh` holds the same geometry as `surface`.
std::vector<double> crease_edge_weights(const Indexed_surface_mesh& surface, const Indexed_mesh& mesh,
                                        double feature_weight);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
