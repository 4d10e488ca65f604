// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one construction of an embedding problem's clusters from a part graph,
// shared by the editing problems (Editing.h: the graph of a training example
// over its own mesh) and by assembly (Assembly.h: any valid part graph over
// its assembled mesh).
#ifndef CGAL_MPM_INTERNAL_PART_GRAPH_PROBLEM_H
#define CGAL_MPM_INTERNAL_PART_GRAPH_PROBLEM_H

#include <CGAL/MPM/Embedding_problem.h>
#include <CGAL/MPM/Morphable_part_model.h>

#include <Eigen/Core>

#include <functional>
#include <string>

namespace CGAL {
namespace MPM {
namespace internal {

// What a part cluster is attracted to: its target shape at zero coordinates
// (in the frame of its type's shape space) and the deviations of its modes.
struct Part_target
{
  Point_matrix mean;
  Eigen::VectorXd sigmas;
};

// Target of node `node` given its type's space, its coordinates and its rest
// geometry expressed in the space's frame (through `Part_node::motion`).
using Part_target_policy =
  std::function<Part_target(int node, const Shape_space& space, const Eigen::VectorXd& coordinates,
                            const Point_matrix& rest_in_space_frame, const std::string& type_name)>;

// Deviations of a pair cluster's modes.
using Pair_sigma_policy = std::function<Eigen::VectorXd(const Shape_space& space)>;

// Builds one part cluster per node and one pair cluster per edge over
// `mesh` (the rest / initial positions), and the coupled same-type
// neighbours. Requires every node's `vertices` (local -> mesh vertex) and
// `motion` (space frame -> rest placement), and every edge's `motion` (pair
// space frame -> rest placement). Pair targets are assembled from the placed
// part targets (parts and pairs ask for the same shape), see `pair_target`.
Embedding_problem make_part_graph_problem(const Morphable_part_model& model, const Part_graph& graph,
                                          const Indexed_mesh& mesh, const Part_target_policy& policy,
                                          const Pair_sigma_policy& pair_sigmas);

// The pair geometry of two placed part targets (see editing.cpp's history):
// the second part is placed on the first by their shared seam (boundary
// docking); a seam too thin to fix a rotation (collinear) only fixes the
// translation and the second part keeps its rest orientation; without a
// seam (generalized docking) both keep their rest placement. Expressed in
// the pair space's frame through `pair_motion` and the pair's rest points.
Point_matrix pair_target(const Docking_rule& rule, const Point_matrix& first, Point_matrix second,
                         const Point_matrix& second_rest, const Rigid_motion& pair_motion, const Point_matrix& rest);

// True when the seam points `p` (k x 3) are too close to a line to fix a
// rotation about it.
bool seam_is_collinear(const Point_matrix& p);

// Rows `vertices` of `points`.
Point_matrix gather_rows(const Point_matrix& points, const std::vector<int>& vertices);

// `points` seen from the frame that `motion` maps to the world.
Point_matrix to_space_frame(const Rigid_motion& motion, const Point_matrix& points);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
