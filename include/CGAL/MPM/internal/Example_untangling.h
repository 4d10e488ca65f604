// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_EXAMPLE_UNTANGLING_H
#define CGAL_MPM_INTERNAL_EXAMPLE_UNTANGLING_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// A learned example's faces that cross each other where its input's do not
// (stitched templates meeting at a seam, a template's first ring folded
// over its border) moved apart, and its faces folded over the input
// (`folded_faces()`) turned back. Each crossing pair and folded face in
// turn: the vertices of its faces, and rings around them grown until it
// helps, go to the mean of their neighbours (the seam vertices of a fan
// along a seam counting as one) and back onto the input's faces of their
// part and of the parts it shares a seam with; a move is kept
// when it lowers the crossings around it (exact predicates, as
// `self_intersecting_faces()`) without folding more faces over the input,
// or lowers the folded faces it touches without more crossings.
// Seam vertices (of faces of two labels) stay, so the parts keep their
// seams and dockings. `mesh` and `face_labels` are the example's; `input`
// the labelled input it approximates. Returns the new positions, or an
// empty matrix when nothing could be mended (or there was nothing the
// input does not have).
Point_matrix untangled_positions(const Indexed_mesh& mesh, const std::vector<int>& face_labels,
                                 const Labeled_mesh& input);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
