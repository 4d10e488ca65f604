// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_CORRESPONDENCE_EVALUATION_H
#define CGAL_MPM_CORRESPONDENCE_EVALUATION_H

#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Remeshes `mesh` with CGAL's isotropic remeshing at `target_edge_length`
/// (border edges are remeshed too, staying on the border), so that its
/// connectivity no longer matches any other instance's.
Indexed_mesh remesh_isotropically(const Indexed_mesh& mesh, double target_edge_length, int iterations = 3);

/// \ingroup PkgMPMRef
/// The true corresponding point on `truth_instance` of each template point:
/// the point is located (closest point, barycentric coordinates) on
/// `truth_template`, its image has the same barycentric coordinates in the
/// same face of `truth_instance`, which shares `truth_template`'s
/// connectivity.
Point_matrix true_corresponding_points(const Indexed_mesh& truth_template, const Point_matrix& template_points,
                                       const Indexed_mesh& truth_instance);

/// \ingroup PkgMPMRef
/// Distance of each template vertex's mapped point to its true
/// corresponding point, over the bounding-box diagonal of `truth_instance`.
/// The template vertex is located (closest point, barycentric coordinates)
/// on `truth_template`; the true point has the same barycentric coordinates
/// in the same face of `truth_instance`, which shares `truth_template`'s
/// connectivity.
std::vector<double> correspondence_errors(const Indexed_mesh& truth_template, const Point_matrix& template_points,
                                          const Indexed_mesh& truth_instance, const Point_matrix& mapped);

/// \ingroup PkgMPMRef
/// The synthetic model with every part remeshed independently as in
/// `evaluate_correspondence_on_remeshed()`: parts keep their labels but no
/// longer share seam vertices (each part is its own component), and no two
/// instances of a type share connectivity.
Labeled_mesh remesh_parts_independently(const Synthetic_model& model, unsigned seed = 1);

/// \ingroup PkgMPMRef
/// Errors of one part type of a remeshed synthetic model.
struct Correspondence_type_report
{
  std::string type;              ///< part type
  int segments = 0;              ///< instances put in correspondence
  int template_vertices = 0;     ///< vertices of the remeshed template
  /// Mean and 95th percentile of the errors before refinement (fractions of the diameter).
  /// @{
  double mean_before = 0., p95_before = 0.;
  /// @}
  /// Mean and 95th percentile of the errors after refinement.
  /// @{
  double mean_after = 0., p95_after = 0.;
  /// @}
  /// Refinement energies before and after.
  /// @{
  Correspondence_energies before, after;
  /// @}
  double seconds = 0.;           ///< time of `compute_dense_correspondence()`
};

/// \ingroup PkgMPMRef
/// The ground-truth experiment: every part of `model` is remeshed
/// independently (target edge lengths drawn from `seed` between 0.75 and
/// 1.3 times the part's mean edge length), each type with at least two
/// instances is put in correspondence with automatic landmarks only, and
/// the errors against the synthetic truth are measured (template excluded).
std::vector<Correspondence_type_report>
evaluate_correspondence_on_remeshed(const Synthetic_model& model, unsigned seed = 1,
                                    const Dense_correspondence_options& options = Dense_correspondence_options());

} // namespace MPM
} // namespace CGAL

#endif
