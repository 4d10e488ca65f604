// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Internal: the seams of a training mesh whose parts were rebuilt by dense
// correspondence, as merged seams (the paper's "union of the vertices",
// design notes section 5), so that the learned example is one surface again.
#ifndef CGAL_MPM_INTERNAL_SEAM_STITCHING_H
#define CGAL_MPM_INTERNAL_SEAM_STITCHING_H

#include <CGAL/MPM/Model/Docking_rule.h>
#include <CGAL/MPM/IO/Face_graph_conversion.h>

#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// The seam between the parts of two labels (`label_a` < `label_b`), side 0
// being `label_a`'s part. Local ids are the parts' (`part_vertices`).
struct Stitched_seam
{
  int label_a = -1, label_b = -1;
  std::vector<Seam_vertex> merged;
};

// Every seam of `original` (the training mesh as given) that has a rebuilt
// part on at least one side. `rebuilt` is the mesh after correspondence:
// rebuilt parts (`detached`) have vertices of their own whose border
// vertices lie on their original seams; the other parts keep the original
// vertices, `original_vertex[v]` (-1 for a rebuilt part's vertex).
// `part_vertices`: per label, local id -> vertex of `rebuilt`.
// Each part's border vertices are located on the original seam polylines;
// points closer than half the finer side's border edge are one
// vertex; a part's border edge is split at every other part's point and
// every seam junction between its two ends.
std::vector<Stitched_seam> stitch_seams(const Labeled_mesh& original, const Labeled_mesh& rebuilt,
                                        const std::vector<int>& original_vertex,
                                        const std::map<int, std::vector<int>>& part_vertices,
                                        const std::set<int>& detached);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
