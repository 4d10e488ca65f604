// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Correspondence/Thin_plate_spline.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <vector>

namespace CGAL {
namespace MPM {

Thin_plate_spline::Thin_plate_spline(const Point_matrix& centres, const Point_matrix& displacements)
{
  const char* const source = "thin-plate spline";
  if(centres.rows() != displacements.rows())
    throw Input_error(source, "", std::to_string(centres.rows()) + " centres but " +
                                    std::to_string(displacements.rows()) + " displacements");
  if(centres.rows() == 0) throw Input_error(source, "", "no centres");
  if(!centres.allFinite() || !displacements.allFinite())
    throw Input_error(source, "", "centres and displacements must be finite");

  // Coincident centres: one centre when they agree, an error when they do not.
  const Eigen::Index given = centres.rows();
  const double scale = internal::bounding_box_diagonal(centres);
  std::vector<Eigen::Index> kept;
  for(Eigen::Index i = 0; i < given; ++i)
  {
    bool duplicate = false;
    for(Eigen::Index j : kept)
      if((centres.row(i) - centres.row(j)).norm() <= 1e-12 * scale)
      {
        if((displacements.row(i) - displacements.row(j)).norm() > 1e-12 * (1. + displacements.row(j).norm()))
          throw Input_error(source, "centre " + std::to_string(i),
                            "coincides with centre " + std::to_string(j) + " but moves differently");
        duplicate = true;
        break;
      }
    if(!duplicate) kept.push_back(i);
  }
  const Eigen::Index k = static_cast<Eigen::Index>(kept.size());
  centres_.resize(k, 3);
  Point_matrix d(k, 3);
  for(Eigen::Index i = 0; i < k; ++i)
  {
    centres_.row(i) = centres.row(kept[std::size_t(i)]);
    d.row(i) = displacements.row(kept[std::size_t(i)]);
  }

  weights_ = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(k, 3);
  affine_.setZero();
  translation_only_ = true;
  bool spatial = k >= 4;
  if(spatial)
  {
    // Centres on (or near) one plane leave the affine part undetermined.
    const Point_matrix centred = centres_.rowwise() - centres_.colwise().mean();
    const Eigen::Vector3d s = Eigen::JacobiSVD<Point_matrix>(centred).singularValues();
    spatial = s[2] > 1e-6 * s[0];
  }
  if(!spatial)
  {
    affine_.row(0) = d.colwise().mean();
    return;
  }

  // [K P; P^T 0] [w; a] = [d; 0], K_ij = |c_i - c_j|, P = (1, c).
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(k + 4, k + 4);
  for(Eigen::Index i = 0; i < k; ++i)
  {
    for(Eigen::Index j = 0; j < k; ++j) system(i, j) = (centres_.row(i) - centres_.row(j)).norm();
    system(i, k) = system(k, i) = 1.;
    for(int c = 0; c < 3; ++c) system(i, k + 1 + c) = system(k + 1 + c, i) = centres_(i, c);
  }
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(k + 4, 3);
  rhs.topRows(k) = d;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
  const Eigen::MatrixXd solution = lu.solve(rhs);
  if(!lu.isInvertible() || !solution.allFinite())
    throw Computation_error("thin-plate spline: the interpolation system is singular");
  weights_ = solution.topRows(k);
  affine_ = solution.bottomRows(4);
  translation_only_ = false;
}

Point_matrix Thin_plate_spline::displacement(const Point_matrix& points) const
{
  Point_matrix result(points.rows(), 3);
  for(Eigen::Index v = 0; v < points.rows(); ++v)
  {
    Eigen::RowVector3d r = affine_.row(0) + points.row(v) * affine_.bottomRows(3);
    for(Eigen::Index j = 0; j < weights_.rows(); ++j)
      r += (points.row(v) - centres_.row(j)).norm() * weights_.row(j);
    result.row(v) = r;
  }
  return result;
}

Thin_plate_spline_deformation::Thin_plate_spline_deformation(const Indexed_mesh& mesh) : rest_(mesh.points)
{
  if(!rest_.allFinite())
    throw Input_error("thin-plate spline", "rest positions", "contain non-finite coordinates");
}

void Thin_plate_spline_deformation::set_handles(const Handle_set& handles)
{
  validate_handles(handles, static_cast<int>(rest_.rows()), "handle set");
  if(handles.size() == 0) throw Input_error("handle set", "", "no handles");
  Point_matrix centres(handles.size(), 3);
  for(int h = 0; h < handles.size(); ++h) centres.row(h) = rest_.row(handles.vertices[std::size_t(h)]);
  spline_ = Thin_plate_spline(centres, handles.targets - centres);
}

Point_matrix Thin_plate_spline_deformation::deform() const { return rest_ + spline_.displacement(rest_); }

} // namespace MPM
} // namespace CGAL
