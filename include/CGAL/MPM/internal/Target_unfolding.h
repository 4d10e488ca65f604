// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_TARGET_UNFOLDING_H
#define CGAL_MPM_INTERNAL_TARGET_UNFOLDING_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// `target` (n x 3, in any frame) with the faces it turns inside out against
// `rest` (the same triangles; measured against the rotation of each
// corner's two-ring neighbourhood, so that a bent joint is no fold) unfolded: around those faces (and a ring or
// two more, grown until no face stays inverted or the region stops
// improving) the target takes the rest's local shape, placed as rigidly as
// possible (CGAL's ARAP) between the target's positions around it. An edit
// asks for such targets when the mean of a part type carries a fold one of
// its instances does not (a correspondence fold averaged in), or when a
// caricature doubles a bend past the point where the inside of the joint
// turns over; the solver would reproduce them faithfully. The same repairs
// an edit's result (see `unfold_faces()`), whose `held` vertices (handles)
// stay where they are. Returns `target` itself when nothing is inverted.
Point_matrix unfold_target(const Point_matrix& target, const Point_matrix& rest, const std::vector<Triangle>& triangles,
                           const std::vector<int>& held = {});

// The faces of `target` turned inside out against `rest` (the same
// triangles) once each corner's two-ring rotation is taken out (see
// `locally_inverted_faces()`): what `unfold_target()` removes.
std::vector<int> locally_inverted_faces(const Point_matrix& target, const Point_matrix& rest,
                                        const std::vector<Triangle>& triangles);

// An edge of two triangles, by its faces, and the angle between their
// normals: 0 where the surface is flat, pi where it folds back on itself.
struct Edge_fold
{
  int first, second;
  double angle;
};

// The folds of the edges of `triangles` that have two faces, in an order
// that depends on the triangles alone (so that two positions of one mesh
// give matching lists).
std::vector<Edge_fold> edge_folds(const Point_matrix& points, const std::vector<Triangle>& triangles);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
