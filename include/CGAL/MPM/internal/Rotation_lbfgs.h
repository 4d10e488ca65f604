// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_ROTATION_LBFGS_H
#define CGAL_MPM_INTERNAL_ROTATION_LBFGS_H

#include <Eigen/Core>

#include <deque>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// Limited-memory BFGS over a product of rotations. A point moves by
// R_c <- R_c exp([omega_c]x), so steps and gradients are 3 numbers per
// rotation in each rotation's own frame; pairs of steps and gradient changes
// are kept as they are (no transport), which is what makes the method cheap.
class Rotation_lbfgs
{
public:
  explicit Rotation_lbfgs(int memory) : memory_(memory) {}

  bool empty() const { return steps_.empty(); }

  // The quasi-Newton direction -H g (two-loop recursion, initial H scaled by
  // the last pair's curvature); -g when nothing is remembered.
  Eigen::VectorXd direction(const Eigen::VectorXd& gradient) const;

  // Remembers a step and the change of the gradient over it; a pair without
  // positive curvature is dropped, keeping H positive definite.
  void remember(const Eigen::VectorXd& step, const Eigen::VectorXd& gradient_change);

  void forget();

private:
  int memory_;
  std::deque<Eigen::VectorXd> steps_, changes_;
};

// R_c exp([step_c]x) for every rotation.
std::vector<Eigen::Matrix3d> retract(const std::vector<Eigen::Matrix3d>& rotations, const Eigen::VectorXd& step);

// The step that retract() takes from `from` to `to`: log(from_c^T to_c).
Eigen::VectorXd rotation_step(const std::vector<Eigen::Matrix3d>& from, const std::vector<Eigen::Matrix3d>& to);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
