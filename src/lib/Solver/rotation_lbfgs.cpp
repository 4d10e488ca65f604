// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Rotation_lbfgs.h>

#include <Eigen/Geometry>

namespace CGAL {
namespace MPM {
namespace internal {

Eigen::VectorXd Rotation_lbfgs::direction(const Eigen::VectorXd& gradient) const
{
  Eigen::VectorXd q = gradient;
  const std::size_t m = steps_.size();
  std::vector<double> alpha(m), rho(m);
  for(std::size_t i = m; i-- > 0;)
  {
    rho[i] = 1. / changes_[i].dot(steps_[i]);
    alpha[i] = rho[i] * steps_[i].dot(q);
    q -= alpha[i] * changes_[i];
  }
  if(m > 0) q *= steps_.back().dot(changes_.back()) / changes_.back().squaredNorm();
  for(std::size_t i = 0; i < m; ++i)
  {
    const double beta = rho[i] * changes_[i].dot(q);
    q += (alpha[i] - beta) * steps_[i];
  }
  return -q;
}

void Rotation_lbfgs::remember(const Eigen::VectorXd& step, const Eigen::VectorXd& gradient_change)
{
  const double curvature = step.dot(gradient_change);
  if(!(curvature > 1e-12 * step.norm() * gradient_change.norm())) return;
  steps_.push_back(step);
  changes_.push_back(gradient_change);
  if(static_cast<int>(steps_.size()) > memory_)
  {
    steps_.pop_front();
    changes_.pop_front();
  }
}

void Rotation_lbfgs::forget()
{
  steps_.clear();
  changes_.clear();
}

std::vector<Eigen::Matrix3d> retract(const std::vector<Eigen::Matrix3d>& rotations, const Eigen::VectorXd& step)
{
  std::vector<Eigen::Matrix3d> r(rotations.size());
  for(std::size_t c = 0; c < rotations.size(); ++c)
  {
    const Eigen::Vector3d omega = step.segment<3>(3 * Eigen::Index(c));
    const double angle = omega.norm();
    r[c] = angle > 0. ? Eigen::Matrix3d(rotations[c] * Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix())
                      : rotations[c];
  }
  return r;
}

Eigen::VectorXd rotation_step(const std::vector<Eigen::Matrix3d>& from, const std::vector<Eigen::Matrix3d>& to)
{
  Eigen::VectorXd step(3 * Eigen::Index(from.size()));
  for(std::size_t c = 0; c < from.size(); ++c)
  {
    const Eigen::AngleAxisd a(Eigen::Matrix3d(from[c].transpose() * to[c]));
    step.segment<3>(3 * Eigen::Index(c)) = a.angle() * a.axis();
  }
  return step;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
