// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_DENSE_CORRESPONDENCE_H
#define CGAL_MPM_DENSE_CORRESPONDENCE_H

#include <CGAL/MPM/Solver/Cancellation.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Shape_space.h>

#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// One segment of a part type with its own triangulation.
struct Correspondence_segment
{
  Indexed_mesh mesh;          ///< the segment (vertices numbered locally)
  std::vector<int> landmarks; ///< optional user landmarks (local vertex ids), in the same order on every segment
  std::string name;           ///< names the segment in errors (`hand.off label 7`)
  /// Optional, per vertex: what lies across the seam at a boundary vertex
  /// (for example the neighbouring part's type), -1 for unknown. A boundary
  /// loop takes its vertices' most frequent tag and is only matched to loops
  /// with the same tag: the two ends of a tube look alike, their neighbours
  /// tell them apart.
  std::vector<int> seam_tags;
};

/// \ingroup PkgMPMRef
/// Options of `compute_dense_correspondence()`. Lengths are relative to
/// each segment's bounding-box diagonal or edge length, so the defaults fit
/// any scale.
struct Dense_correspondence_options
{
  int loop_samples = 24;          ///< automatic landmarks per boundary loop (arc-length samples)
  int spline_centres = 40;        ///< free centres of the coarse thin-plate-spline regularizer
  int spline_iterations = 8;      ///< ICP iterations with the spline regularizer
  int laplacian_iterations = 3;   ///< ICP iterations per stiffness of the Laplacian regularizer
  /// Segments corresponded (with splines) before the PCA space of those
  /// replaces the spline as the coarse regularizer; 0 never uses it.
  int segments_before_pca = 3;
  /// A learned space of shapes with the first segment's connectivity (a
  /// model's `Part_type::space`), the coarse regularizer of every other
  /// segment when it has modes: fitting a new shape into a model follows
  /// the shapes the model knows. Empty (no modes): not used.
  Shape_space prior;
  bool refine = true;             ///< run the refinement (paper eq. 4.1-4.2)
  int refinement_iterations = 40; ///< gradient steps of the refinement
  /// Largest move of a vertex per refinement step, as a fraction of its mean
  /// edge length on the segment.
  double refinement_step = 0.2;
  double sample_weight = 0.1;     ///< weight of E_sample against trace(Sigma)
  double boundary_weight = 10.;   ///< weight of E_boundary against trace(Sigma)
  /// Coverage residual (fraction of the diagonal) above which a segment is
  /// also matched against the mirrored template, to warn when only a
  /// reflection would cover it (`Segment_correspondence::mirrored`).
  double mirror_check_residual = 0.02;
  /// Fraction of a segment's mapped template triangles that may face
  /// against its surface (`Segment_correspondence::flipped_faces`) before a
  /// warning names it.
  double flipped_warning_fraction = 0.02;
  /// Called with a stage name and the fraction done (0..1).
  std::function<void(const std::string& stage, double fraction)> progress;
  /// Checked before each segment: raised, it throws `Operation_cancelled`.
  Cancellation_flag cancel = nullptr;
  /// Called with each warning as it arises (they are also collected in
  /// `Dense_correspondence::warnings`): a segment only a mirror image of the
  /// template would cover, or one on which the correspondence folds.
  std::function<void(const std::string& message)> warning;
};

/// \ingroup PkgMPMRef
/// The refinement energies (paper eq. 4.1), summed over segments.
struct Correspondence_energies
{
  double boundary = 0.; ///< E_boundary: user landmarks off their targets (boundary vertices stay on their loops)
  /// E_sample: uniform-Laplacian (sampling) differences against the mean
  /// shape, scaled by (bounding-box diagonal / mean edge length)^2 of the
  /// template so that it weighs alike at every resolution.
  double sample = 0.;
  double trace = 0.;    ///< trace(Sigma) after rigid alignment to the mean (eq. 4.2)
  /// The weighted sum minimized.
  double total(double sample_weight, double boundary_weight) const
  {
    return trace + sample_weight * sample + boundary_weight * boundary;
  }
};

/// \ingroup PkgMPMRef
/// What `compute_dense_correspondence()` found for one segment.
struct Segment_correspondence
{
  Point_matrix positions;        ///< template vertices on this segment (after refinement)
  Point_matrix unrefined;        ///< the same before refinement
  int order = 0;                 ///< rank in which the segment was added (the template is 0)
  int iterations = 0;            ///< ICP iterations spent
  bool used_shape_space = false; ///< the PCA space was the coarse regularizer
  /// The segment looks like a mirror image of the template (a left and a
  /// right limb): the mirrored template covered it clearly better than any
  /// orientation-preserving fit. `positions` are nevertheless that
  /// orientation-preserving fit, never a reflection (whose triangles would
  /// face inwards), and a warning names the segment.
  bool mirrored = false;
  int automatic_landmarks = 0;   ///< landmark pairs proposed automatically
  /// Root mean square distance of the segment's vertices to the mapped
  /// template, over the bounding-box diagonal (how well the template covers it).
  double residual = 0.;
  /// Mapped template triangles whose normal points against the normal of
  /// the segment's nearest face: the correspondence folds or turns the
  /// part inside out there. About zero for a sound correspondence.
  int flipped_faces = 0;
};

/// \ingroup PkgMPMRef
/// Dense correspondence of the segments of one part type.
struct Dense_correspondence
{
  std::vector<Triangle> triangles;          ///< template connectivity (the first segment's)
  std::vector<Segment_correspondence> segments; ///< per input segment, in input order
  Correspondence_energies before; ///< energies before refinement
  Correspondence_energies after;  ///< energies after refinement (equal to `before` without it)
  int refinement_iterations = 0;  ///< accepted refinement steps
  /// Warnings, each naming the type and segment (also passed to
  /// `Dense_correspondence_options::warning`).
  std::vector<std::string> warnings;
};

/// \ingroup PkgMPMRef
/// Boundary loops of a mesh: closed chains of border edges (edges of one
/// triangle), each oriented like its triangles, longest first.
std::vector<std::vector<int>> boundary_loops(const Indexed_mesh& mesh);

/// \ingroup PkgMPMRef
/// Puts the first segment's connectivity (the template) on every segment of
/// one part type: segments are added most-deviating first (bounding-box
/// diagonal), aligned rigidly by landmarks (the user's, or automatic ones:
/// arc-length samples of the matched boundary loops with the best cyclic
/// shift and orientation, the lean of each seam's plane, and the tip of
/// segments with one loop), then fitted by deformable ICP with a coarse
/// thin-plate-spline (later: the PCA space of the segments done, or
/// `Dense_correspondence_options::prior`; a long tube is also placed along
/// its axis, which follows a bent or curled limb) and a
/// Laplacian regularizer, and finally refined by minimizing
/// `E_boundary + E_sample + trace(Sigma)` with tangent steps projected back
/// onto each segment. See `doc/MPM/Correspondence.md`.
///
/// Every fit preserves orientation (proper rigid motions, seams matched in
/// their own direction): a segment that only a mirror image of the template
/// would cover gets a warning and keeps the orientation-preserving fit
/// (`Segment_correspondence::mirrored`); template triangles facing against
/// a segment are counted (`Segment_correspondence::flipped_faces`) and a
/// warning names a segment with more than `flipped_warning_fraction` of them.
///
/// Throws `Input_error` naming the type and segment for a degenerate
/// segment (no triangle, collinear or non-finite points), landmarks out of
/// range or of different counts, and segments with different numbers of
/// boundary loops.
Dense_correspondence compute_dense_correspondence(const std::vector<Correspondence_segment>& segments,
                                                  const std::string& type_name,
                                                  const Dense_correspondence_options& options =
                                                    Dense_correspondence_options());

} // namespace MPM
} // namespace CGAL

#endif
