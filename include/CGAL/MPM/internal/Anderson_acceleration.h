// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_ANDERSON_ACCELERATION_H
#define CGAL_MPM_INTERNAL_ANDERSON_ACCELERATION_H

#include <Eigen/Core>
#include <Eigen/QR>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// Anderson acceleration (type II) of a fixed-point iteration x <- G(x): the
// next iterate combines the last few images so as to minimize the combined
// residual G(x) - x in the least-squares sense.
class Anderson_acceleration
{
public:
  explicit Anderson_acceleration(int history) : history_(history) {}

  // Records x and its image g; returns the accelerated candidate, or g when
  // there is no history yet.
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& g)
  {
    const Eigen::VectorXd f = g - x;
    if(history_ > 0 && previous_f_.size() > 0)
    {
      delta_f_.push_back(f - previous_f_);
      delta_g_.push_back(g - previous_g_);
      if(static_cast<int>(delta_f_.size()) > history_)
      {
        delta_f_.erase(delta_f_.begin());
        delta_g_.erase(delta_g_.begin());
      }
    }
    previous_f_ = f;
    previous_g_ = g;
    const int m = static_cast<int>(delta_f_.size());
    if(m == 0) return g;
    Eigen::MatrixXd normal(m, m);
    Eigen::VectorXd rhs(m);
    for(int i = 0; i < m; ++i)
    {
      rhs[i] = delta_f_[i].dot(f);
      for(int j = 0; j < m; ++j) normal(i, j) = delta_f_[i].dot(delta_f_[j]);
    }
    const Eigen::VectorXd theta = normal.completeOrthogonalDecomposition().solve(rhs);
    Eigen::VectorXd candidate = g;
    for(int i = 0; i < m; ++i) candidate -= theta[i] * delta_g_[i];
    return candidate;
  }

  // Forgets the history (after a rejected candidate).
  void restart()
  {
    delta_f_.clear();
    delta_g_.clear();
  }

private:
  int history_;
  Eigen::VectorXd previous_f_, previous_g_;
  std::vector<Eigen::VectorXd> delta_f_, delta_g_;
};

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
