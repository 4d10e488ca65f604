// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_SHAPE_SPACE_H
#define CGAL_MPM_SHAPE_SPACE_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// A rigid motion `x -> rotation * x + translation`.
struct Rigid_motion
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); ///< proper rotation
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  ///< translation

  /// Applies the motion to every row of `p`.
  Point_matrix apply(const Point_matrix& p) const
  {
    return (p * rotation.transpose()).rowwise() + translation.transpose();
  }

  /// The motion that undoes this one: `x -> rotation^T * (x - translation)`.
  Rigid_motion inverse() const
  {
    Rigid_motion r;
    r.rotation = rotation.transpose();
    r.translation = -(r.rotation * translation);
    return r;
  }
};

/// \ingroup PkgMPMRef
/// A Gaussian shape space of n corresponding points: mean `mu`, orthonormal
/// modes `b_k` and standard deviations `sigma_k`, learned by generalized
/// Procrustes alignment and PCA (see `learn_shape_space()`).
///
/// Vectors of the space have 3n entries laid out point by point
/// (x0 y0 z0 x1 y1 z1 ...). Instance j of the training set is reproduced by
/// `instance_motions[j].apply(shape(instance_coordinates.col(j)))` up to
/// `instance_residuals[j]`.
struct Shape_space
{
  Point_matrix mean;                     ///< n x 3 mean shape (in the frame of the first instance)
  Eigen::MatrixXd modes;                 ///< 3n x d orthonormal modes
  Eigen::VectorXd sigmas;                ///< d standard deviations
  Eigen::VectorXd variances;             ///< every PCA variance, decreasing (kept or not)
  Eigen::MatrixXd instance_coordinates;  ///< d x m coordinates of the training instances
  std::vector<Rigid_motion> instance_motions; ///< m motions from the mean frame to each instance
  std::vector<double> instance_residuals;     ///< m relative residuals outside the kept subspace

  /// Number of points.
  int number_of_points() const { return static_cast<int>(mean.rows()); }
  /// Number of kept modes d.
  int number_of_modes() const { return static_cast<int>(modes.cols()); }
  /// Number of training instances m.
  int number_of_instances() const { return static_cast<int>(instance_motions.size()); }
  /// Sum of all PCA variances.
  double total_variance() const { return variances.sum(); }
  /// Fraction of the total variance explained by the first `k` modes (1 when
  /// there is no variance at all).
  double explained_variance(int k) const;
  /// `mean + sum_k coordinates[k] * modes[k]`, as an n x 3 matrix.
  Point_matrix shape(const Eigen::VectorXd& coordinates) const;
  /// Coordinates and rigid motion that best fit `points` (n x 3): rigid
  /// alignment and projection iterated to convergence. Returns the relative
  /// residual `|fit - points| / |points - centroid|`.
  double fit(const Point_matrix& points, Eigen::VectorXd& coordinates, Rigid_motion& motion) const;
};

/// \ingroup PkgMPMRef
/// How many modes a shape space keeps.
struct Shape_space_options
{
  int modes = 0;                    ///< fixed number of modes; 0: by explained variance
  double explained_variance = 0.99; ///< fraction of variance to explain when `modes` is 0
  int max_procrustes_iterations = 200;    ///< cap on generalized Procrustes iterations
  double procrustes_tolerance = 1e-13;    ///< relative change of the mean that stops them
};

/// \ingroup PkgMPMRef
/// Learns a shape space from `instances` (each n x 3, points in
/// correspondence): generalized Procrustes alignment without scaling (rigid
/// alignment to the running mean, iterated), then PCA of the aligned shapes.
/// A single instance gives a space without modes whose mean is that
/// instance. Throws `Computation_error` when the instances differ in size or
/// contain non-finite values.
Shape_space learn_shape_space(const std::vector<Point_matrix>& instances,
                              const Shape_space_options& options = Shape_space_options());

/// \ingroup PkgMPMRef
/// Best rigid motion (rotation without reflection, translation) taking
/// `source` onto `target` in the least-squares sense (Kabsch/Umeyama).
Rigid_motion fit_rigid_motion(const Point_matrix& source, const Point_matrix& target);

} // namespace MPM
} // namespace CGAL

#endif
