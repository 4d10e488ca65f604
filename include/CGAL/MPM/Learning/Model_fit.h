// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_MODEL_FIT_H
#define CGAL_MPM_MODEL_FIT_H

#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Model_parameters.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>
#include <CGAL/MPM/Model/Shape_space.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// How the part type of a fitted segment was chosen.
enum class Fit_type_source
{
  annotation, ///< the annotation names it
  seams_and_size ///< the model type with the segment's seam-loop count whose size fits best
};

/// \ingroup PkgMPMRef
/// Options of `fit_morphable_part_model()`.
struct Model_fit_options
{
  /// Labels of the segments to fit; empty: every segment of the mesh. The
  /// other segments still tell the fitted ones what lies across their seams.
  std::vector<int> labels;
  /// Segments that cannot be fitted (a type the model does not know, a
  /// seam-loop count no type has or that differs from its type's) are
  /// listed in `Model_fit::skipped` instead of throwing `Input_error`: a
  /// leave-one-out benchmark measures what it can.
  bool skip_unfittable = false;
  /// Segments whose local connectivity is their type's (a pose of a
  /// training mesh, a synthetic model) are in known correspondence and skip
  /// the dense correspondence; false corresponds them anyway.
  bool use_known_correspondence = true;
  /// Options of the dense correspondence of a segment with its type's template.
  Dense_correspondence_options correspondence;
  /// Steps of the closest-point fit of the shape space to the segment's
  /// surface after the dense correspondence; 0 fits the corresponded
  /// vertices as they are.
  int surface_iterations = 10;
  /// Called with a stage name and the fraction done (0..1).
  std::function<void(const std::string& stage, double fraction)> progress;
  /// Called with each warning (also collected in `Model_fit::warnings`).
  std::function<void(const std::string& message)> warning;
};

/// \ingroup PkgMPMRef
/// One segment of a new mesh fitted into a part type's shape space.
struct Segment_fit
{
  int label = -1;                 ///< the segment's face label
  int type = -1;                  ///< index of its part type in the model
  Fit_type_source type_source = Fit_type_source::annotation; ///< how the type was chosen
  int seam_loops = 0;             ///< boundary loops of the segment
  bool known_correspondence = false; ///< the segment had its type's connectivity
  /// The type's template vertices on the segment (template connectivity:
  /// `Part_type::triangles`), in the mesh's frame.
  Point_matrix corresponded;
  /// The reconstruction `motion.apply(space.shape(coordinates))`: the
  /// shape space's closest shape, placed where the segment is.
  Point_matrix fitted;
  Eigen::VectorXd coordinates;    ///< shape coordinates in the type's space
  Eigen::VectorXd coordinates_in_sigmas; ///< the same over each mode's standard deviation
  Rigid_motion motion;            ///< mean frame -> the segment
  double rms = 0.;                ///< RMS distance between `corresponded` and `fitted` (mesh units)
  double segment_diagonal = 0.;   ///< bounding-box diagonal of the segment
  double rms_over_segment_diagonal = 0.; ///< `rms / segment_diagonal`
  double rms_over_mesh_diagonal = 0.;    ///< `rms` over the whole mesh's bounding-box diagonal
  /// RMS distance from the segment's vertices to the fitted surface (`fitted`
  /// with the type's triangles) over the mesh's diagonal: large when the fit
  /// leaves part of the segment uncovered.
  double segment_to_fit_over_mesh_diagonal = 0.;
  /// How well the mapped template covers the segment
  /// (`Segment_correspondence::residual`, over the segment's diagonal); 0
  /// in known correspondence.
  double coverage_residual = 0.;
  bool mirrored = false;          ///< see `Segment_correspondence::mirrored`
  int flipped_faces = 0;          ///< see `Segment_correspondence::flipped_faces`
};

/// \ingroup PkgMPMRef
/// A segment `fit_morphable_part_model()` left out (with
/// `Model_fit_options::skip_unfittable`), and why.
struct Skipped_segment
{
  int label = -1;     ///< the segment's face label
  std::string reason; ///< one line, naming the mesh and segment
};

/// \ingroup PkgMPMRef
/// The fit errors of one part type, over the segments fitted to it.
struct Type_fit_error
{
  int type = -1;                  ///< index of the part type in the model
  std::string name;               ///< its name
  int segments = 0;               ///< segments fitted to it
  /// RMS over all their vertices, over the mesh's bounding-box diagonal
  /// (every segment has the template's vertex count, so this is the root
  /// mean square of the segments' `rms_over_mesh_diagonal`).
  double rms_over_mesh_diagonal = 0.;
  /// The same with each segment's error over its own diagonal.
  double rms_over_segment_diagonal = 0.;
  double worst_over_mesh_diagonal = 0.; ///< largest `Segment_fit::rms_over_mesh_diagonal`
  /// RMS of the segments' `Segment_fit::segment_to_fit_over_mesh_diagonal`
  /// (segments of one type differ in vertex count: each counts once).
  double segment_to_fit_over_mesh_diagonal = 0.;
  double worst_coverage_residual = 0.;  ///< largest `Segment_fit::coverage_residual`
  /// Largest `Segment_fit::segment_to_fit_over_mesh_diagonal`.
  double worst_segment_to_fit_over_mesh_diagonal = 0.;
};

/// \ingroup PkgMPMRef
/// A new mesh fitted into a model: per segment its part type, shape
/// coordinates and residual, and the fitted surface.
struct Model_fit
{
  std::vector<Segment_fit> segments;  ///< in ascending label order
  std::vector<Skipped_segment> skipped; ///< with `Model_fit_options::skip_unfittable`
  double mesh_diagonal = 0.;          ///< bounding-box diagonal of the whole mesh
  /// RMS of the fitted vertices against the corresponded ones over all
  /// segments, over the mesh's diagonal.
  double rms_over_mesh_diagonal = 0.;
  std::vector<std::string> warnings;  ///< each names the mesh and segment

  /// The fitted surface: every fitted segment's reconstruction with its
  /// type's connectivity, placed where the segment is. The parts are
  /// separate pieces (a seam is sampled once per side, not shared).
  /// `face_labels` are the segments' labels.
  Labeled_mesh fitted_surface(const Morphable_part_model& model) const;
  /// The errors per part type fitted, in type order.
  std::vector<Type_fit_error> errors_by_type(const Morphable_part_model& model) const;
};

/// \ingroup PkgMPMRef
/// Fits a new labelled mesh of the kind `model` was learned from (or some of
/// its segments, `Model_fit_options::labels`) into the model.
///
/// - **Part type** of a segment: the one `annotation.part_type_of_label`
///   names; for a label it does not list, the model type whose template
///   (`Part_type::space.mean` with `Part_type::triangles`) has as many
///   boundary loops as the segment and the closest size: smallest
///   `|ln(A / A_t)| + mean_i |ln(p_i / p_t,i)|` over areas `A` and loop
///   perimeters `p_i` sorted longest first.
/// - **Correspondence.** The template is put on the segment by
///   `compute_dense_correspondence()` (template first, so the result is the
///   template's vertices on the segment; each seam is tagged with the type
///   across it, from the model's docking rules on the template's side and
///   from the neighbouring segments' types on the segment's). A segment with
///   the type's own connectivity keeps its vertices (known correspondence).
/// - **Shape space fit.** Rigid alignment and orthogonal projection onto the
///   type's modes (`Shape_space::fit()`), so the residual is what the
///   learned space cannot express. The correspondence placed the template
///   without the type's space, and a template slid along the segment covers
///   it as well: `Model_fit_options::surface_iterations` closest-point steps
///   then move the template's vertices on the segment's surface (a seam
///   vertex on its own seam) toward the fitted shape and fit again, each
///   target also pulled toward the segment vertices nearest to it so that
///   the fit cannot shrink onto part of the segment; a step is kept while
///   the distance between the fitted shape and its closest points falls.
///   `Segment_fit::corresponded` are then those closest points, and
///   `Segment_fit::segment_to_fit_over_mesh_diagonal` says how far the
///   segment's own vertices lie from the fit.
///
/// Throws `Input_error` naming `mesh.source` and the segment for a type the
/// model does not know, a segment whose seam-loop count no type has or
/// differs from its type's, a label with no face, and what
/// `validate_labeled_mesh()` and `compute_dense_correspondence()` refuse.
Model_fit fit_morphable_part_model(const Morphable_part_model& model, const Labeled_mesh& mesh,
                                   const Annotation& annotation = Annotation(),
                                   const Model_fit_options& options = Model_fit_options());

/// \ingroup PkgMPMRef
/// One round of a leave-one-out test: a model learned from every input but
/// one, and that one fitted into it.
struct Leave_one_out_fit
{
  int held_out = -1;           ///< index of the held-out input
  Morphable_part_model model;  ///< learned from the others
  Model_fit fit;               ///< the held-out input fitted into it
  std::vector<Type_fit_error> errors; ///< `fit.errors_by_type(model)`
  double learning_seconds = 0.; ///< time to learn the model
  double fitting_seconds = 0.;  ///< time to fit the held-out input
};

/// \ingroup PkgMPMRef
/// Learns a model from all `inputs` but `held_out` (`learn_morphable_part_model()`)
/// and fits input `held_out` into it with its own annotation, so that its
/// residuals measure how well the model generalizes to a mesh it has not
/// seen. Part type names must agree across the inputs. Throws `Input_error`
/// for fewer than two inputs or an index out of range, and as the learner
/// and `fit_morphable_part_model()` do.
Leave_one_out_fit fit_held_out_input(const std::vector<Training_input>& inputs, int held_out,
                                     const Learning_options& learning = Learning_options(),
                                     const Model_fit_options& fitting = Model_fit_options());

/// \ingroup PkgMPMRef
/// Pools the per-type errors of several fits (the rounds of a leave-one-out
/// test, whose models number their types differently) by type name: RMS
/// over all the segments of a name, worst over all of them; `type` is -1.
/// Names in order of first appearance.
std::vector<Type_fit_error> pool_type_fit_errors(const std::vector<std::vector<Type_fit_error>>& rounds);

} // namespace MPM
} // namespace CGAL

#endif
