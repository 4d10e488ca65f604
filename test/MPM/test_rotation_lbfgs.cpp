// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// L-BFGS over rotations (internal/Rotation_lbfgs.h), and the solver that
// uses it: the same minimum as the local/global steps, in fewer iterations.
#include "Learned_models.h"

#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/internal/Rotation_lbfgs.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <random>

namespace {

using namespace CGAL::MPM;
using internal::Rotation_lbfgs;

std::vector<Eigen::Matrix3d> random_rotations(int count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Matrix3d> r;
  for(int c = 0; c < count; ++c)
    r.push_back(Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix());
  return r;
}

TEST(Rotation_lbfgs, retract_and_rotation_step_are_inverse)
{
  const std::vector<Eigen::Matrix3d> from = random_rotations(5, 1), to = random_rotations(5, 2);
  const std::vector<Eigen::Matrix3d> back = internal::retract(from, internal::rotation_step(from, to));
  for(std::size_t c = 0; c < from.size(); ++c) EXPECT_LT((back[c] - to[c]).norm(), 1e-12);
}

// f(R) = -sum_c tr(R_c^T A_c), minimized by the closest rotations to A_c;
// its gradient in each rotation's frame is the skew part of R_c^T A_c.
TEST(Rotation_lbfgs, finds_the_closest_rotations)
{
  const int count = 6;
  std::vector<Eigen::Matrix3d> a = random_rotations(count, 3), r = random_rotations(count, 4);
  for(Eigen::Matrix3d& m : a) m *= Eigen::Vector3d(3., 2., 1.).asDiagonal(); // anisotropic: not a plain rotation fit
  const auto energy = [&](const std::vector<Eigen::Matrix3d>& x) {
    double e = 0.;
    for(int c = 0; c < count; ++c) e -= (x[c].transpose() * a[c]).trace();
    return e;
  };
  const auto gradient = [&](const std::vector<Eigen::Matrix3d>& x) {
    Eigen::VectorXd g(3 * count);
    for(int c = 0; c < count; ++c)
    {
      const Eigen::Matrix3d m = x[c].transpose() * a[c];
      g.segment<3>(3 * c) = -Eigen::Vector3d(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
    }
    return g;
  };
  Rotation_lbfgs lbfgs(5);
  Eigen::VectorXd g = gradient(r);
  double e = energy(r);
  int iterations = 0;
  for(; iterations < 200 && g.norm() > 1e-10; ++iterations)
  {
    const Eigen::VectorXd p = lbfgs.direction(g);
    ASSERT_LT(g.dot(p), 0.) << "not a descent direction in iteration " << iterations;
    double t = 1.;
    std::vector<Eigen::Matrix3d> next = internal::retract(r, t * p);
    while(energy(next) > e + 1e-4 * t * g.dot(p)) next = internal::retract(r, (t *= 0.5) * p);
    const Eigen::VectorXd g_next = gradient(next);
    lbfgs.remember(t * p, g_next - g);
    r = next;
    g = g_next;
    e = energy(r);
  }
  EXPECT_LT(iterations, 60);
  for(int c = 0; c < count; ++c)
  {
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a[c], Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d closest = svd.matrixU() * svd.matrixV().transpose();
    if(closest.determinant() < 0)
    {
      Eigen::Matrix3d u = svd.matrixU();
      u.col(2) *= -1.;
      closest = u * svd.matrixV().transpose();
    }
    EXPECT_LT((r[c] - closest).norm(), 1e-7) << "rotation " << c;
  }
}

// The solver with L-BFGS steps reaches the minimum the local/global steps
// reach, never raising the energy, in fewer iterations.
// The hand symmetrized: the same shape (up to the rigid motion a free piece
// keeps, anchored by one vertex) as the local/global steps reach, in fewer
// iterations.
TEST(Rotation_lbfgs, solver_reaches_the_local_global_minimum_sooner)
{
  const mpm_test::Learned& l = mpm_test::learned(Synthetic_family::hand, 3000);
  const Embedding_problem problem = make_symmetrization_problem(l.model);
  Embedding_options plain, quasi_newton;
  plain.quasi_newton = false;
  plain.newton = quasi_newton.newton = false; // L-BFGS against local/global steps alone
  plain.max_iterations = quasi_newton.max_iterations = 1000;
  plain.tolerance = quasi_newton.tolerance = 1e-8;
  Embedding_solver a(problem, plain), b(problem, quasi_newton);
  const Solve_report ra = a.solve(), rb = b.solve();
  ASSERT_TRUE(ra.converged);
  ASSERT_TRUE(rb.converged);
  // Reduced energies are exact to about 1e-14 of the data term, and the last
  // one is evaluated exactly at the final positions (see the solver tests).
  const std::size_t n = rb.energies.size();
  for(std::size_t i = 1; i + 1 < n; ++i)
    EXPECT_LE(rb.energies[i], rb.energies[i - 1] + 1e-9 * rb.energies.front()) << "iteration " << i;
  EXPECT_LE(rb.energies[n - 1], rb.energies[n - 2] + 1e-7 * rb.energies.front());
  EXPECT_LE(rb.energy(), ra.energy() + 1e-7 * rb.energies.front());
  const Eigen::Matrix3Xd pa = a.positions().transpose(), pb = b.positions().transpose();
  const Eigen::Matrix4d align = Eigen::umeyama(pb, pa, false);
  const Eigen::Matrix3Xd aligned = (align.topLeftCorner<3, 3>() * pb).colwise() + align.topRightCorner<3, 1>();
  const double diagonal = mpm_test::diagonal(l.truth.mesh.mesh.points);
  EXPECT_LT((aligned - pa).colwise().norm().maxCoeff(), 1e-5 * diagonal); // measured 1.4e-6
  EXPECT_LT(rb.iterations, ra.iterations) << "local/global " << ra.iterations << ", quasi-Newton " << rb.iterations;
}

} // namespace
