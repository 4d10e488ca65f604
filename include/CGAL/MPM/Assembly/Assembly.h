// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_ASSEMBLY_H
#define CGAL_MPM_ASSEMBLY_H

#include <CGAL/MPM/Solver/Embedding_problem.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>
#include <CGAL/MPM/Model/Part_graph.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>

#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Options of `assemble()`.
struct Assembly_options
{
  Embedding_options solver; ///< options of the embedding solver
  bool solve = true;        ///< false: stop after the rigid placement (no solve)
  /// Optional, one per node: the node's target shape (any frame), replacing
  /// its type's `mean + sum coordinates * modes`. The modes still apply
  /// around it. Used to reproduce a training example from its instances.
  std::vector<Point_matrix> targets;
  /// Optional, one per node: where the node's target (in the frame it is
  /// given in) is placed initially, replacing the breadth-first placement.
  std::vector<Rigid_motion> placements;
  /// Node placed first, at its target's own frame; -1: node 0.
  int root = -1;
};

/// \ingroup PkgMPMRef
/// What assembling and embedding a part graph did, without the mesh it
/// made: what `assemble()` into the user's face graph returns, the mesh
/// being that face graph.
struct Assembly_result
{
  /// The input graph with `Part_node::vertices` (local -> vertex of the
  /// mesh, in the order the vertices were made) and the initial placements
  /// (`Part_node::motion`, `Part_edge::motion`) filled. A node docked by a
  /// differently sampled seam (`Docking_rule::merged_seam`) lists after its
  /// type's local vertices the seam vertices inserted into it.
  Part_graph graph;
  Solve_report report;            ///< what the solver did
  double residual_energy = 0.;    ///< energy of the embedding: the distortion the graph needs
  std::vector<double> part_energies;    ///< energy of each node's cluster
  std::vector<double> docking_energies; ///< energy of each edge's pair cluster
  double setup_ms = 0.;           ///< placement, stitching and solver set-up
  double solve_ms = 0.;           ///< solver iterations

  /// Residual energy divided by the number of parts.
  double energy_per_part() const
  { return graph.nodes.empty() ? 0. : residual_energy / double(graph.nodes.size()); }
  /// The mesh vertex of local vertex `local` of node `node`.
  int vertex(int node, int local) const { return graph.nodes[node].vertices[local]; }
};

/// \ingroup PkgMPMRef
/// An assembled and embedded part graph, with its mesh and what was solved.
struct Assembly : Assembly_result
{
  Indexed_mesh mesh;              ///< the embedded mesh (the initial one when not solved)
  Point_matrix initial_positions; ///< the rigid placement, seam vertices averaged
  std::vector<int> face_nodes;    ///< node of each face
  std::vector<int> face_types;    ///< part type of each face
  /// Per edge: the mesh vertex of each vertex of its rule's merged seam
  /// (empty for seams sampled alike).
  std::vector<std::vector<int>> seam_vertices;
  Embedding_problem problem;      ///< what was solved (clusters: nodes, then edges)
};

/// \ingroup PkgMPMRef
/// Assembles `graph` (validated first, see `validate_part_graph()`) and
/// embeds it:
/// - every node contributes its type's local vertices and triangles; the
///   seam vertices of boundary dockings are shared, one mesh vertex per
///   class of identified (node, local vertex) pairs (union-find over the
///   rules' seams: a cycle closes by this sharing); where a rule joins two
///   seams sampled differently (`Docking_rule::merged_seam`), each side first
///   gets the other side's vertices inserted (its border triangles split, the
///   inserted vertex's mean and modes interpolated between its two loop
///   neighbours), so that the seam is the merged loop on both sides;
/// - each node's target shape (type mean plus its coordinates, or
///   `options.targets`) is placed rigidly: the root at its own frame, then
///   breadth-first each neighbour aligned on its seam to the placed part
///   (Kabsch on the seam vertices) or, for generalized dockings and seams too
///   thin to fix a rotation, by the relative placement of the rule's pair
///   geometry (at the edge's pair coordinates); shared vertices average
///   their placed positions;
/// - the clusters are built exactly as for the editing problems (parts and
///   pair geometries, pair targets assembled from the placed part targets)
///   and the embedding solver runs without handles (weak anchors hold it).
///
/// Throws `Input_error` for an invalid graph (naming the node or edge) and
/// `Computation_error` for a non-finite result.
Assembly assemble(const Morphable_part_model& model, const Part_graph& graph,
                  const Assembly_options& options = Assembly_options());

/// \ingroup PkgMPMRef
/// How many intersecting face pairs of `a.mesh` have exactly one face in
/// node `node`: where the node crosses the rest of the assembly (an
/// inserted segment lying on its neighbour). Pairs within the node or
/// within the rest do not count.
int crossings_of_node(const Assembly& a, int node);

/// \ingroup PkgMPMRef
/// Options that make `assemble(model, part_graph_of_example(model, example))`
/// reproduce training example `example`: each node's target is its
/// instance's own rest shape and its initial placement is the instance's.
/// Exactly for parts docked by shared seams; where corresponded parts were
/// stitched along merged seams, the seam vertices inserted into a part's
/// edges are interpolated on them, and the result is within about 1% of
/// the bounding-box diagonal of the example.
Assembly_options training_assembly_options(const Morphable_part_model& model, int example = 0);

/// \ingroup PkgMPMRef
/// Options of `spawn_part_graphs()`.
struct Spawn_options
{
  int count = 8;          ///< how many graphs
  unsigned seed = 1;      ///< seeds the `std::mt19937` all draws come from
  Random_edit_options edits;  ///< the random edits of each graph
  Assembly_options assembly;  ///< how each graph is embedded (targets and placements must stay empty)
  /// Called after each graph with how many are done and `count`: progress
  /// for a long run. Empty: not called. (`assembly.solver.cancel`, checked
  /// before each graph and each iteration, stops the run.)
  std::function<void(int done, int count)> progress;
};

/// \ingroup PkgMPMRef
/// One spawned part graph, embedded.
struct Spawned_graph
{
  int index = 0;                  ///< order of drawing (0 = first drawn)
  /// A node docked by a differently sampled seam (`Docking_rule::merged_seam`)
  /// lists after its type's local vertices the seam vertices inserted into it.
  Part_graph graph;               ///< the graph
  std::vector<std::string> edits; ///< the edits that made it from the start graph
  Assembly assembly;              ///< its embedding
};

/// \ingroup PkgMPMRef
/// Draws `options.count` random valid part graphs from `start` (see
/// `random_part_graph()`, all from one generator seeded with
/// `options.seed`), embeds each, and returns them ranked by residual energy
/// per part, lowest first (ties: drawing order). Reproducible for a seed.
std::vector<Spawned_graph> spawn_part_graphs(const Morphable_part_model& model, const Part_graph& start,
                                             const Spawn_options& options = Spawn_options());

} // namespace MPM
} // namespace CGAL

#endif
