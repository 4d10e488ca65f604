// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_THIN_PLATE_SPLINE_H
#define CGAL_MPM_THIN_PLATE_SPLINE_H

#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// A 3D thin-plate spline displacement field
/// `d(x) = sum_j w_j |x - c_j| + A^T (1, x)`: the kernel `phi(r) = r` is the
/// fundamental solution of the biharmonic operator in 3D, and the affine
/// part `A` (4 x 3) makes the spline reproduce affine motions exactly.
///
/// It interpolates displacements given at `k` centres. With fewer than 4
/// centres, or centres (nearly) on one plane, the affine part is not
/// determined; the spline then falls back to the translation by the mean
/// displacement (`is_translation()` is true). That fallback does not
/// interpolate.
class Thin_plate_spline
{
public:
  /// An empty spline: zero displacement everywhere.
  Thin_plate_spline() = default;

  /// Fits the spline to `displacements` (k x 3) at `centres` (k x 3).
  /// Throws `Input_error` when the sizes disagree, there are no centres,
  /// values are not finite or two centres coincide, and
  /// `Computation_error` when the system cannot be solved.
  Thin_plate_spline(const Point_matrix& centres, const Point_matrix& displacements);

  /// Displacement at every row of `points`.
  Point_matrix displacement(const Point_matrix& points) const;

  /// True when the spline is the mean-translation fallback.
  bool is_translation() const { return translation_only_; }

  /// Kernel weights (k x 3), zero for the fallback.
  const Eigen::Matrix<double, Eigen::Dynamic, 3>& kernel_weights() const { return weights_; }
  /// Affine part (4 x 3): row 0 the translation, rows 1-3 the linear map.
  const Eigen::Matrix<double, 4, 3>& affine_part() const { return affine_; }

private:
  Point_matrix centres_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> weights_;
  Eigen::Matrix<double, 4, 3> affine_ = Eigen::Matrix<double, 4, 3>::Zero();
  bool translation_only_ = true;
};

/// \ingroup PkgMPMRef
/// Thin-plate-spline space deformation of a mesh by handles: the spline
/// interpolating the handle displacements (target minus rest position)
/// moves every vertex. Connectivity plays no part.
class Thin_plate_spline_deformation
{
public:
  /// Copies the rest positions of `mesh`.
  explicit Thin_plate_spline_deformation(const Indexed_mesh& mesh);

  /// Sets the handles (see `validate_handles()`; an empty set is an error)
  /// and fits the spline.
  void set_handles(const Handle_set& handles);

  /// The deformed positions (n x 3); the rest positions when no handles are set.
  Point_matrix deform() const;

  /// The current spline.
  const Thin_plate_spline& spline() const { return spline_; }

private:
  Point_matrix rest_;
  Thin_plate_spline spline_;
};

} // namespace MPM
} // namespace CGAL

#endif
