// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_LEARN_MORPHABLE_PART_MODEL_H
#define CGAL_MPM_LEARN_MORPHABLE_PART_MODEL_H

#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Model_parameters.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// A labelled mesh and what the user says about it.
struct Training_input
{
  Labeled_mesh mesh;     ///< geometry and per-face part labels
  Annotation annotation; ///< part types, landmarks, parameters
};

/// \ingroup PkgMPMRef
/// Options of the learning step.
struct Learning_options
{
  /// Called with a stage name and the fraction done (0..1) on long work.
  std::function<void(const std::string& stage, double fraction)> progress;
  /// Called with one line per warning (for example an isolated part).
  std::function<void(const std::string& warning)> warning;
  /// Options of the dense correspondence run for part types whose
  /// instances have different triangulations.
  Dense_correspondence_options correspondence;
  /// Checked at each stage (and by the correspondence, before each
  /// segment): raised, learning throws `Operation_cancelled`.
  Cancellation_flag cancel = nullptr;
};

/// \ingroup PkgMPMRef
/// Training inputs whose same-type parts were given one connectivity.
struct Corresponded_training
{
  /// The inputs rebuilt: every corresponded part has its type's template
  /// connectivity (its own vertices, no longer shared with its neighbours),
  /// other parts are unchanged; landmarks are renumbered.
  std::vector<Training_input> inputs;
  /// Per corresponded type: the correspondence of its segments.
  std::map<std::string, Dense_correspondence> types;
  /// Per corresponded type: (input, label) of each segment, in the order of
  /// `Dense_correspondence::segments`.
  std::map<std::string, std::vector<std::pair<int, int>>> segments;
  /// Per input: the label pairs that shared a seam (a vertex) before the
  /// rebuild. A rebuilt part that had seams is stitched to its seam
  /// neighbours and docks to nothing else, however near.
  std::vector<std::set<std::pair<int, int>>> seams;
  /// Per input: the labels of the rebuilt parts.
  std::vector<std::set<int>> detached;
  /// Per input: the input vertex of each vertex of the rebuilt mesh, -1 for
  /// the vertices of rebuilt parts.
  std::vector<std::vector<int>> original_vertex;
};

/// \ingroup PkgMPMRef
/// Runs `compute_dense_correspondence()` on every annotated part type whose
/// instances do not share connectivity (or, with `all_types`, on every type
/// with at least two instances) and rebuilds the inputs with the template
/// connectivity. Seams tag the boundary loops with the neighbouring part's
/// type, and annotation landmarks take priority over automatic ones.
/// Throws `Input_error` as `learn_morphable_part_model()` and
/// `compute_dense_correspondence()` do.
Corresponded_training correspond_training_inputs(const std::vector<Training_input>& inputs,
                                                 const Learning_options& options = Learning_options(),
                                                 bool all_types = false);

/// \ingroup PkgMPMRef
/// Learns a morphable part model from one or more labelled meshes. Parts of
/// one type that share connectivity are in known correspondence (within
/// each part, vertices are numbered by first appearance in its faces, in
/// face order); annotated types whose parts are triangulated differently are
/// first put in dense correspondence (`correspond_training_inputs()`), and
/// each rebuilt part is stitched back to its neighbours: the union of the
/// two border samplings along the original seam, each side's border edges
/// split at the other's vertices, is a boundary docking with a merged seam
/// (`Part_edge::merged_seam`), so that the example is one surface again. Finds boundary dockings (shared seam edges) and generalized
/// dockings (parts of different connected components within the docking
/// radius), learns a shape space per part type and per docking rule, and
/// collects the grammar. Instances and rules are pooled across all inputs;
/// parameters are taken from the first input's annotation.
///
/// Throws `Input_error` for invalid input (naming the mesh and element: a
/// part type without instances, instances of one type with different
/// connectivity without an annotation naming its type, an empty part, bad
/// geometry, segments that cannot be put in correspondence).
Morphable_part_model learn_morphable_part_model(const std::vector<Training_input>& inputs,
                                                const Learning_options& options = Learning_options());

/// \ingroup PkgMPMRef
/// Convenience overload for a single labelled mesh.
Morphable_part_model learn_morphable_part_model(const Labeled_mesh& mesh, const Annotation& annotation,
                                                const Learning_options& options = Learning_options());

/// \ingroup PkgMPMRef
/// Learns from any triangulated `FaceGraph` (`CGAL::Surface_mesh`, OpenMesh,
/// `Polyhedron_3`, ...) with one part label per face read from
/// `face_labels` (a readable property map, face descriptor to integer).
/// Vertices and faces are numbered in `vertices(g)` and `faces(g)` order.
/// Named parameters come last, as in CGAL.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `g`}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, g)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class FaceGraph, class FaceLabelMap, class NamedParameters = parameters::Default_named_parameters>
Morphable_part_model learn_morphable_part_model(const FaceGraph& g, FaceLabelMap face_labels,
                                                const Annotation& annotation,
                                                const Learning_options& options = Learning_options(),
                                                const NamedParameters& np = parameters::default_values())
{
  return learn_morphable_part_model(to_labeled_mesh(g, face_labels, "face graph", np), annotation, options);
}

} // namespace MPM
} // namespace CGAL

#endif
