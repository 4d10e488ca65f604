// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_SEAM_SMOOTHING_H
#define CGAL_MPM_INTERNAL_SEAM_SMOOTHING_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// A stitched example's seams straightened on the surface it approximates.
// A merged seam alternates between one part's own border vertices and
// points on the other part's border chords, so it zigzags across the
// input's seam, and the fans of slivers that join the two sides fold over
// and cross each other there. Each vertex of a merged seam (edges between
// faces of two labels that are a pair in `merged`, smaller label first) with
// two such seam neighbours moves halfway to their midpoint, `iterations`
// times, each time back onto `surface` (its closest point), which keeps the
// seam on the input without shrinking it; junctions and the seams between
// parts kept as they were stay. A move that folds more faces over `surface`
// (`folded_faces()`) is not made: a seam vertex moved across a neighbour's
// chord turns the sliver between them over. Then each seam vertex of a face
// still folded moves towards the mean of its neighbours where that unfolds
// faces, and last the seam corners of each face still folded move so
// together. Returns the new positions of `mesh`.
Point_matrix smoothed_seams(const Indexed_mesh& mesh, const std::vector<int>& face_labels,
                            const std::set<std::pair<int, int>>& merged, const Indexed_mesh& surface,
                            int iterations = 8);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
