// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_PART_TYPE_PROPOSAL_H
#define CGAL_MPM_PART_TYPE_PROPOSAL_H

#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Model_parameters.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Settings of `propose_part_types()`.
struct Part_type_proposal_options
{
  /// A class of segments (same position in the segment graph, same seam
  /// count) whose largest area is more than this many times its smallest is
  /// split at the largest ratio between consecutive areas, recursively. Area
  /// grows with the square of length, so the default 3 allows a segment
  /// about 1.7 times as long as another of its type (a thumb base against a
  /// little finger's) but not three times as long.
  double max_area_ratio = 3.;
};

/// \ingroup PkgMPMRef
/// One segment of a labelled mesh as `propose_part_types()` saw it: one row
/// of the table the `mpm learn` command prints.
struct Segment_proposal
{
  int label = -1;              ///< the segment's face label
  int faces = 0;               ///< number of faces
  double area = 0.;            ///< surface area
  double diameter = 0.;        ///< largest distance between two of its vertices (double sweep, a lower bound)
  int seam_loops = 0;          ///< boundary loops of the segment as a surface (`boundary_loops()`)
  std::vector<int> neighbours; ///< labels of the segments sharing an edge with it, ascending
  int depth = 0;               ///< steps from the root in the segment graph (root: 0)
  int parent = -1;             ///< label of the neighbour one step nearer the root (-1 for the root)
  int children = 0;            ///< neighbours one step farther from the root whose parent it is
  std::string type;            ///< proposed part type name
  std::string reason;          ///< why it was split from the class its position suggests (empty if not)
};

/// \ingroup PkgMPMRef
/// The part types proposed for one labelled mesh.
struct Part_type_proposal
{
  /// `part_type_of_label` filled with the proposed types; everything else
  /// default (parameters, no landmarks). Ready for `learn_morphable_part_model()`
  /// and `write_annotation()`.
  Annotation annotation;
  std::vector<Segment_proposal> segments; ///< one per label, by depth, then type, then label
  int root = -1;                          ///< label of the root segment

  /// Number of segments per proposed type.
  std::map<std::string, int> instances_of_type() const;
};

/// \ingroup PkgMPMRef
/// Proposes part types for a labelled mesh from its segment graph and the
/// segments' sizes, for meshes nobody has annotated.
///
/// - **Segment graph.** Two segments are neighbours when they share an edge.
/// - **Root.** The segment with the most neighbours, ties broken by the
///   larger area: the palm of a hand, the body of an octopus, the thorax of an
///   ant (where the legs attach, although the abdomen is larger). The
///   largest segment alone is not robust: the abdomen would be the root and
///   every leg would hang one step farther down than it is.
/// - **Chains.** A breadth-first search from the root gives each segment a
///   depth and a parent (the neighbour nearest the root sharing the longest
///   seam). A segment is a `tip` (no child), a `chain` piece (one child) or
///   a `branch` (several children).
/// - **Names.** The root is `root`; any other segment is its kind followed by
///   its depth: `chain1`, `chain2`, `tip3` for the phalanges of a finger.
///   Segments below a branch that is not the root carry the branch's name
///   as a prefix (`branch1_s3.chain2`: an ant's antenna hangs from the
///   head, its legs from the thorax). A segment whose seam-loop count is
///   not the one its kind implies (1 for a tip, 2 for a chain piece) gets
///   `_sN` (N loops) appended, branches always do: dense correspondence
///   needs the same number of loops in every segment of a type.
/// - **Size.** Within a class named so, areas are sorted; while the largest
///   is more than `max_area_ratio` times the smallest, the class is cut at
///   the largest ratio between consecutive areas. The part with the most
///   segments (ties: the larger areas) keeps the name; the others get
///   `_large`, `_large2`, ... or `_small`, `_small2`, ... by their areas,
///   and their `reason` says why.
///
/// The same rules give the same names on every mesh of a kind, so types
/// pool across meshes (see the overload for several meshes).
///
/// Throws `Input_error` as `validate_segmentation()` does.
Part_type_proposal propose_part_types(const Labeled_mesh& mesh,
                                      const Part_type_proposal_options& options = Part_type_proposal_options());

/// \ingroup PkgMPMRef
/// `propose_part_types()` on the user's mesh: the segments are the faces of
/// the triangle mesh `g` with one label in `face_labels` (as
/// `cut_at_proposed_joints()` or `cut_mesh()` over a face graph write them).
/// The proposal's annotation goes with the same map to
/// `learn_morphable_part_model()` over `g`.
///
/// \tparam FaceGraph a model of `FaceListGraph`
/// \tparam FaceLabelMap a `ReadablePropertyMap` from the face descriptor to a type convertible to `int`
/// Named parameters: `vertex_point_map`.
///
/// Throws `Input_error` as the overload for a labelled mesh does.
template <class FaceGraph, class FaceLabelMap, class NamedParameters = parameters::Default_named_parameters>
Part_type_proposal propose_part_types(const FaceGraph& g, FaceLabelMap face_labels,
                                      const Part_type_proposal_options& options = Part_type_proposal_options(),
                                      const NamedParameters& np = parameters::default_values())
{
  return propose_part_types(to_labeled_mesh(g, face_labels, "face graph", np), options);
}

/// \ingroup PkgMPMRef
/// Proposes part types for several meshes of a kind at once, so that a name
/// means the same kind of segment in every mesh:
/// - where segments of one position name have different seam-loop counts in
///   different meshes (two roots with 5 and 6 seams), those whose count
///   differs from the first mesh's get `_sN` appended;
/// - after the size split within each mesh, the segments of each name in
///   all meshes are split again the same way with the square of
///   `max_area_ratio` (sizes vary more from one body and one person's cuts
///   to the next than within a body), each area scaled by the square of the
///   first mesh's bounding-box diagonal over its own mesh's (meshes scanned
///   at different scales): one person cuts an octopus arm at a thin ring by
///   the body, another at half its length, and both are `chain1` by position.
///
/// One mesh gets the names of the overload for one mesh.
std::vector<Part_type_proposal> propose_part_types(const std::vector<Labeled_mesh>& meshes,
                                                   const Part_type_proposal_options& options =
                                                     Part_type_proposal_options());

/// \ingroup PkgMPMRef
/// Checks that a labelled mesh is a segmentation the proposal and dense
/// correspondence can work on, after `validate_labeled_mesh()`: every edge
/// has at most two faces and every vertex one fan of faces (a manifold
/// surface, possibly with borders), and every segment is one face-connected
/// piece. Throws `Input_error` naming `mesh.source`, the segment (`segment 7`)
/// and the element at fault.
void validate_segmentation(const Labeled_mesh& mesh);

/// \ingroup PkgMPMRef
/// Number of boundary loops (seams) of each segment as a surface of its own,
/// by label, counted by `boundary_loops()` as dense correspondence counts them.
std::map<int, int> seam_loops_of_segments(const Labeled_mesh& mesh);

/// \ingroup PkgMPMRef
/// Checks that the segments of each part type have the same number of
/// seam loops, which dense correspondence requires. Labels missing from the
/// annotation are left to the learner's own checks. Throws `Input_error`
/// naming the type and listing each segment with its loop count, e.g.
/// `hand.json: part type "finger": segments have different numbers of seam loops (label 3: 2, label 9: 1) ...`.
void validate_seam_counts(const std::vector<Training_input>& inputs);

/// \ingroup PkgMPMRef
/// True when two segments (in one mesh or in two) have identical local
/// connectivity (the same triangles after numbering each segment's
/// vertices by first appearance), the case of synthetic models whose
/// same-type parts are in known correspondence. Real segmentations have
/// none: their segments need proposed types and dense correspondence.
bool segments_share_connectivity(const std::vector<Labeled_mesh>& meshes);

/// \ingroup PkgMPMRef
/// Whether meshes given without an annotation get proposed part types
/// (`propose_part_types()`) before learning: some mesh has more than one
/// segment and no two segments share connectivity
/// (`segments_share_connectivity()`), so the learner's grouping by
/// connectivity would give every segment a type of its own. What `mpm
/// learn` and the demo decide.
bool part_types_need_proposing(const std::vector<Labeled_mesh>& meshes);

} // namespace MPM
} // namespace CGAL

#endif
