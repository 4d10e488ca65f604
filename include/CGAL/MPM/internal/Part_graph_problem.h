// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one construction of an embedding problem's clusters from a part graph,
// shared by the editing problems (Editing.h: the graph of a training example
// over its own mesh) and by assembly (Assembly.h: any valid part graph over
// its assembled mesh).
#ifndef CGAL_MPM_INTERNAL_PART_GRAPH_PROBLEM_H
#define CGAL_MPM_INTERNAL_PART_GRAPH_PROBLEM_H

#include <CGAL/MPM/Solver/Embedding_problem.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <Eigen/Core>

#include <array>

#include <functional>
#include <string>

namespace CGAL {
namespace MPM {
namespace internal {

// What errors about a part graph name as their source.
inline constexpr const char* part_graph_source = "part graph";

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

// A node whose part gained seam vertices inserted by differently sampled
// dockings (Docking_rule::merged_seam): local vertices number_of_vertices + k
// are the inserted ones (Part_node::vertices lists them after the type's),
// each between two loop neighbours; its triangles and edges are the type's
// with the border edges split. Empty `inserted`: the type as it is.
struct Inserted_vertex
{
  int from = -1, to = -1; // local loop neighbours
  double weight = 0.;     // (1 - weight) from + weight to
};
struct Part_refinement
{
  std::vector<Inserted_vertex> inserted;
  std::vector<Triangle> triangles;
  std::vector<Cluster_edge> edges;
};

// The merged seam of a docking: the edge's own (a training observation) or
// else the rule's; empty when the seam is sampled alike on both sides.
const std::vector<Seam_vertex>& merged_seam_of(const Docking_rule& rule, const Part_edge& edge);

// The parts of a graph with the vertices its merged seams insert: per node
// its refinement, per edge and merged vertex the local vertex on each side
// (an inserted one numbered after the type's). A vertex inserted into the
// same border edge at the same weight by two dockings (a junction of three
// parts) is one vertex. Throws Input_error when a merged seam splits an
// edge that is not a border edge of the part's type.
struct Graph_refinement
{
  std::vector<Part_refinement> nodes;
  std::vector<std::vector<std::array<int, 2>>> merged_locals;
  bool empty() const;
};
Graph_refinement refine_part_graph(const Morphable_part_model& model, const Part_graph& graph);

// One mesh from the parts of a graph: identified (node, local) pairs (seam
// pairs and merged seams) become one vertex placed at the mean of their
// `placed` rows (per node: its refined local points); sets every node's
// `vertices`, appends each face's node to `face_nodes` when given. Throws
// Input_error when dockings identify two local vertices of one part.
Indexed_mesh stitch_part_graph(const Morphable_part_model& model, Part_graph& graph, const Graph_refinement& refined,
                               const std::vector<Point_matrix>& placed, std::vector<int>* face_nodes = nullptr);

// `points` (the type's local vertices) followed by the interpolated rows of
// the inserted vertices.
Point_matrix refine_points(const Point_matrix& points, const std::vector<Inserted_vertex>& inserted);

// Rows of `modes` (3 per point) likewise extended.
Eigen::MatrixXd refine_modes(const Eigen::MatrixXd& modes, const std::vector<Inserted_vertex>& inserted);

// The matched seam points of a boundary docking: row k of `on_first`
// (from the first part's points `first`) meets row k of `on_second`. Seams
// sampled alike: the pairs of `rule.seam`; a merged seam: every merged
// vertex, interpolated on the side where it is inserted.
void seam_points(const Docking_rule& rule, const std::vector<Seam_vertex>& merged, const Point_matrix& first, const Point_matrix& second,
                 Point_matrix& on_first, Point_matrix& on_second);


// Builds one part cluster per node and one pair cluster per edge over
// `mesh` (the rest / initial positions), and the coupled same-type
// neighbours. Requires every node's `vertices` (local -> mesh vertex) and
// `motion` (space frame -> rest placement), and every edge's `motion` (pair
// space frame -> rest placement). `refinements` (one per node, optional):
// parts with inserted seam vertices (their means and modes interpolated,
// their triangles split; the inserted vertices fade like the seam; with
// `keep_inserted_offsets`, as for a stitched training example whose rest
// positions are the truth, an inserted vertex's target keeps its rest offset
// from the chord it is interpolated on). Pair targets are assembled from the placed
// part targets (parts and pairs ask for the same shape), see `pair_target`.
Embedding_problem make_part_graph_problem(const Morphable_part_model& model, const Part_graph& graph,
                                          const Indexed_mesh& mesh, const Part_target_policy& policy,
                                          const Pair_sigma_policy& pair_sigmas,
                                          const std::vector<Part_refinement>* refinements = nullptr,
                                          bool keep_inserted_offsets = false);

// The pair geometry of two placed part targets (see editing.cpp's history):
// the second part is placed on the first by their shared seam (boundary
// docking); a seam too thin to fix a rotation (collinear) only fixes the
// translation and the second part keeps its rest orientation; without a
// seam (generalized docking) both keep their rest placement. Expressed in
// the pair space's frame through `pair_motion` and the pair's rest points.
Point_matrix pair_target(const Docking_rule& rule, const std::vector<Seam_vertex>& merged, const Point_matrix& first, Point_matrix second,
                         const Point_matrix& first_rest, const Point_matrix& second_rest, const Rigid_motion& pair_motion,
                         const Point_matrix& rest);

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
