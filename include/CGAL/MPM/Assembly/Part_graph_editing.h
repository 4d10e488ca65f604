// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_PART_GRAPH_EDITING_H
#define CGAL_MPM_PART_GRAPH_EDITING_H

#include <CGAL/MPM/Model/Morphable_part_model.h>
#include <CGAL/MPM/Model/Part_graph.h>

#include <random>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// \name Derived rules
/// A chain of distinct part types (proximal - middle - distal) never shows
/// a segment docked to a copy of itself, so the learned grammar cannot
/// lengthen a chain. A *repetition rule* docks the two boundary sites of a
/// two-site part type to each other (middle's distal end to another
/// middle's proximal end). It is derived, not observed: the seam
/// correspondence matches the two boundary loops (same vertex count,
/// opposite orientations, the cyclic shift that fits the type's mean best),
/// the pair points are those within the docking radius of either loop, and
/// the pair space has no modes: its mean is two copies of the type's mean
/// docked on the seam.
/// @{

/// The repetition rule of type `type` between its sites `site_a` < `site_b`
/// (`derive_docking_rule()` of the two sites). Throws `Input_error` when the
/// sites are not two boundary loops.
Docking_rule derive_repetition_rule(const Morphable_part_model& model, int type, int site_a, int site_b);

/// A derived rule docking boundary site `a` (side 0) to boundary site `b`
/// (side 1), of any part types (the same type too), each site's vertices
/// forming one closed loop on its type's border. Loops of the same size are
/// matched one to one as for repetition rules. Loops of different sizes get
/// a merged seam (`Docking_rule::merged_seam`, see doc/MPM/Part_graphs.md,
/// "Seams sampled differently"): both loops are parametrized by arc length on
/// their types' means, `b`'s run backwards (a manifold gluing); among the
/// offsets that make a vertex of one loop meet a vertex of the other, the one
/// whose rigid fit of the two parametrized loops is best fixes the twist; the
/// merged loop is the union of both loops' vertices ordered by parameter,
/// vertices nearer than a fifth of the finer spacing identified
/// (`Docking_rule::seam`), every other one inserted on the side that lacks it,
/// between its two loop neighbours there. Pair points and the mode-less pair
/// space are as for repetition rules (`b`'s mean docked on `a`'s by the
/// merged seam). Throws `Input_error` for a site that does not exist, is not
/// a boundary site or not one simple boundary loop.
Docking_rule derive_docking_rule(const Morphable_part_model& model, const Site_ref& a, const Site_ref& b);

/// Appends `derive_docking_rule(model, a, b)` to the model's rules unless a
/// rule already docks `a` to `b` (either order). Returns the index of the
/// added rule, or of the first existing one.
int add_derived_rule(Morphable_part_model& model, const Site_ref& a, const Site_ref& b);

/// Appends the repetition rule of every part type with exactly two docking
/// sites, both simple boundary loops (of any sizes: loops of different sizes,
/// as a segment of a real mesh has, get a merged seam), that no rule docks yet. The
/// learned rules keep their indices. Returns the indices of the added rules
/// (none on a second call).
std::vector<int> add_repetition_rules(Morphable_part_model& model);

/// Appends a *bridging rule* for every segment of a training example (a
/// node docked to exactly two others, both by boundary dockings) whose two
/// neighbours' sites no rule docks to each other:
/// `derive_docking_rule(model, a, b)` of those sites, so that
/// `remove_segment()` can dock the neighbours of a removed segment (a
/// finger's proximal phalanx to its tip, a palm to a middle phalanx).
/// Pairs whose sites are not simple loops are skipped. The learned rules
/// keep their indices. Returns the indices of the added rules (none on a
/// second call).
std::vector<int> add_bridging_rules(Morphable_part_model& model);
/// @}

/// \ingroup PkgMPMRef
/// A way to dock a new edge at a node: its free site and the rule.
struct Docking_option
{
  int node = -1; ///< the node
  int site = -1; ///< its free docking site
  int rule = -1; ///< the rule docking that site to the other one
};

/// \ingroup PkgMPMRef
/// Sites of node `node` that can take another docking (used fewer times
/// than their observed degree, see `observed_site_degrees()`).
std::vector<int> free_sites(const Morphable_part_model& model, const Part_graph& graph, int node);

/// \ingroup PkgMPMRef
/// Every (node, free site, rule) that docks to site `other` (of a node
/// yet to be added), in node, site, rule order.
std::vector<Docking_option> free_dockings(const Morphable_part_model& model, const Part_graph& graph,
                                          const Site_ref& other);

/// \ingroup PkgMPMRef
/// The node placement and branches start from: the node with the most
/// dockings (the palm, the body), the first one on ties.
int root_node(const Part_graph& graph);

/// \ingroup PkgMPMRef
/// Inserts a segment into docking `edge` (between A at the rule's first
/// site and B at its second): a new node N of a type with two distinct
/// sites such that a rule docks A's site to one and another rule docks the
/// other to B's site. Types of A and B are tried first (`type` >= 0 forces
/// one). N takes the coordinates of a same-type neighbour (A, then B), else
/// the mean. Edge `edge` becomes A - N, the N - B edge is appended. Returns
/// N. Throws `Input_error` when no type fits.
int insert_segment(const Morphable_part_model& model, Part_graph& graph, int edge, int type = -1);

/// \ingroup PkgMPMRef
/// Gives node `node` (typically one `insert_segment()` just added) the shape
/// whose rigid placement (`assemble()` without the solve) crosses the rest
/// least: among its current coordinates, its type's mean and each training
/// instance's coordinates, the one with the fewest pairs of intersecting
/// faces (CGAL's `self_intersections`), the current one on ties. A segment
/// copied from a curled neighbour continues the curl, into the palm or
/// the next finger; a straighter instance of the same type does not.
/// Returns the number of intersecting face pairs of the placement kept.
int choose_segment_shape(const Morphable_part_model& model, Part_graph& graph, int node);

/// \ingroup PkgMPMRef
/// Removes nodes (with their edges) and renumbers the rest in order.
/// Returns old node index -> new index (-1: removed).
std::vector<int> remove_nodes(Part_graph& graph, const std::vector<int>& nodes);

/// \ingroup PkgMPMRef
/// Removes node `node`, which must have exactly two dockings, and docks its
/// two neighbours to each other at the sites they used, when a rule allows
/// it (else `Input_error`). Returns old -> new node indices.
std::vector<int> remove_segment(const Morphable_part_model& model, Part_graph& graph, int node);

/// \ingroup PkgMPMRef
/// The nodes beyond `node` seen from `root`: `node` and every node that
/// `root` reaches only through it.
std::vector<int> branch_nodes(const Part_graph& graph, int node, int root);

/// \ingroup PkgMPMRef
/// Removes node `node` and everything beyond it away from `root`
/// (`branch_nodes()`). Returns old -> new node indices.
std::vector<int> remove_branch(const Morphable_part_model& model, Part_graph& graph, int node, int root);

/// \ingroup PkgMPMRef
/// Copies the branch at `node` (seen from `root`; it must hang by one
/// docking) and docks the copy of `node` to node `target` at a free site of
/// it (`target_site`, or the first that a rule docks to the site `node`
/// hangs by). Returns the index of the copy of `node`.
int duplicate_branch(const Morphable_part_model& model, Part_graph& graph, int node, int root, int target,
                     int target_site = -1);

/// \ingroup PkgMPMRef
/// Docks nodes `a` and `b` at free sites that a rule docks, closing a cycle
/// when they are already connected. Among the dockings whose seams close
/// consistently, the one whose sites are nearest in the rigid placement of
/// the current graph wins (see `assemble()`; the first in site order when the
/// graph is in pieces). Returns the new edge's index; throws `Input_error`
/// when no rule fits.
int close_cycle(const Morphable_part_model& model, Part_graph& graph, int a, int b);

/// \ingroup PkgMPMRef
/// Scales the shape coordinates of every node and docking of `graph` about
/// their type's or rule's mean by `factor`: 0 makes every instance its
/// type's mean (the symmetrization of an assembly), a factor above 1 a
/// caricature, a negative one an anti-shape. Assemble the result to see it.
void scale_coordinates(Part_graph& graph, double factor);

/// \ingroup PkgMPMRef
/// Options of `random_part_graph()`.
struct Random_edit_options
{
  int min_edits = 1; ///< fewest edits applied
  int max_edits = 3; ///< most edits applied
  /// Which edits may be drawn: insert a segment, remove a segment, remove a
  /// branch, duplicate a branch.
  /// @{
  bool insert = true, remove_segment = true, remove_branch = true, duplicate_branch = true;
  /// @}
  int min_nodes = 2; ///< a removal never leaves fewer nodes
};

/// \ingroup PkgMPMRef
/// A uniform integer in [0, n) from `rng` (rejection sampling, the same on
/// every platform, unlike `std::uniform_int_distribution`).
int uniform_index(std::mt19937& rng, int n);

/// \ingroup PkgMPMRef
/// A random valid part graph: `start` with a random number of random valid
/// edits (insert a segment, remove a segment, remove a branch, duplicate a
/// branch onto a free site). Each applied edit is described in `log`.
/// Reproducible for a given state of `rng`.
Part_graph random_part_graph(const Morphable_part_model& model, const Part_graph& start, std::mt19937& rng,
                             const Random_edit_options& options = Random_edit_options(),
                             std::vector<std::string>* log = nullptr);

} // namespace MPM
} // namespace CGAL

#endif
