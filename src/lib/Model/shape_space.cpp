// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Shape_space.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace CGAL {
namespace MPM {

namespace {

// Shapes are stacked point by point (x0 y0 z0 x1 ...), the layout of `modes`.
Eigen::VectorXd flatten(const Point_matrix& p)
{
  Eigen::VectorXd v(3 * p.rows());
  for(Eigen::Index i = 0; i < p.rows(); ++i)
    v.segment<3>(3 * i) = p.row(i).transpose();
  return v;
}

Point_matrix unflatten(const Eigen::VectorXd& v)
{
  Point_matrix p(v.size() / 3, 3);
  for(Eigen::Index i = 0; i < p.rows(); ++i)
    p.row(i) = v.segment<3>(3 * i).transpose();
  return p;
}

double centered_norm(const Point_matrix& p)
{
  return (p.rowwise() - p.colwise().mean()).norm();
}

} // namespace

Rigid_motion fit_rigid_motion(const Point_matrix& source, const Point_matrix& target)
{
  const Eigen::RowVector3d cs = source.colwise().mean();
  const Eigen::RowVector3d ct = target.colwise().mean();
  const Eigen::Matrix3d covariance = (target.rowwise() - ct).transpose() * (source.rowwise() - cs);
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  // The reflection-safe Kabsch solution: flip the weakest axis if needed.
  if((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0)
    d(2, 2) = -1;
  Rigid_motion m;
  m.rotation = svd.matrixU() * d * svd.matrixV().transpose();
  m.translation = ct.transpose() - m.rotation * cs.transpose();
  return m;
}

double Shape_space::explained_variance(int k) const
{
  const double total = total_variance();
  if(!(total > 0)) return 1.;
  k = std::clamp(k, 0, static_cast<int>(variances.size()));
  return variances.head(k).sum() / total;
}

Point_matrix Shape_space::shape(const Eigen::VectorXd& coordinates) const
{
  if(coordinates.size() == 0 || modes.cols() == 0) return mean;
  return mean + unflatten(modes * coordinates);
}

double Shape_space::fit(const Point_matrix& points, Eigen::VectorXd& coordinates, Rigid_motion& motion) const
{
  coordinates = Eigen::VectorXd::Zero(number_of_modes());
  motion = fit_rigid_motion(mean, points);
  // Alternating rigid alignment and orthogonal projection decreases the
  // residual monotonically; a handful of steps reaches machine precision for
  // instances inside the space.
  double previous = std::numeric_limits<double>::infinity();
  double residual = 0.;
  for(int it = 0; it < 100; ++it)
  {
    const Eigen::VectorXd local = flatten(motion.inverse().apply(points)) - flatten(mean);
    coordinates = modes.transpose() * local;
    const Point_matrix model = shape(coordinates);
    motion = fit_rigid_motion(model, points);
    residual = (motion.apply(model) - points).norm();
    if(!(residual < previous * (1 - 1e-12))) break;
    previous = residual;
  }
  const double scale = centered_norm(points);
  return scale > 0 ? residual / scale : residual;
}

Shape_space learn_shape_space(const std::vector<Point_matrix>& instances, const Shape_space_options& options)
{
  if(instances.empty())
    throw Computation_error("shape space: no instances");
  const Eigen::Index n = instances.front().rows();
  for(std::size_t j = 0; j < instances.size(); ++j)
  {
    if(instances[j].rows() != n)
      throw Computation_error("shape space: instance " + std::to_string(j) + " has " +
                              std::to_string(instances[j].rows()) + " points, instance 0 has " +
                              std::to_string(n));
    if(!instances[j].allFinite())
      throw Computation_error("shape space: instance " + std::to_string(j) + " has non-finite coordinates");
  }
  const int m = static_cast<int>(instances.size());

  // Generalized Procrustes: align to the running mean, keep the mean in the
  // frame of the first instance so the gauge (a global rotation) is fixed.
  std::vector<Point_matrix> aligned(instances);
  Point_matrix mean = instances.front();
  for(int it = 0; it < options.max_procrustes_iterations; ++it)
  {
    for(int j = 0; j < m; ++j)
      aligned[j] = fit_rigid_motion(instances[j], mean).apply(instances[j]);
    Point_matrix next = Point_matrix::Zero(n, 3);
    for(const Point_matrix& a : aligned) next += a;
    next /= m;
    next = fit_rigid_motion(next, instances.front()).apply(next);
    const double change = (next - mean).norm();
    const double scale = std::max(centered_norm(next), std::numeric_limits<double>::min());
    mean = next;
    if(change <= options.procrustes_tolerance * scale) break;
  }
  for(int j = 0; j < m; ++j)
    aligned[j] = fit_rigid_motion(instances[j], mean).apply(instances[j]);

  Shape_space space;
  space.mean = mean;
  Eigen::MatrixXd deviations(3 * n, m);
  for(int j = 0; j < m; ++j) deviations.col(j) = flatten(aligned[j]) - flatten(mean);

  int kept = 0;
  Eigen::MatrixXd basis(3 * n, 0);
  if(m > 1)
  {
    // The thin SVD of the 3n x m deviation matrix costs O(n m^2): cheap even
    // for large parts because instances are few.
    Eigen::BDCSVD<Eigen::MatrixXd> svd(deviations, Eigen::ComputeThinU);
    const Eigen::VectorXd s = svd.singularValues();
    space.variances = s.array().square() / double(m - 1);
    const double total = space.variances.sum();
    // Directions with variance at round-off level carry no shape information.
    const double floor = 1e-20 * total;
    int available = 0;
    while(available < s.size() && space.variances[available] > floor && available < m - 1) ++available;
    if(options.modes > 0)
      kept = std::min(options.modes, available);
    else
    {
      while(kept < available && space.explained_variance(kept) < options.explained_variance) ++kept;
    }
    basis = svd.matrixU().leftCols(kept);
  }
  else
    space.variances = Eigen::VectorXd::Zero(0);

  space.modes = basis;
  space.sigmas = space.variances.head(kept).cwiseSqrt();
  space.instance_coordinates = basis.transpose() * deviations;
  space.instance_motions.resize(m);
  space.instance_residuals.resize(m);
  for(int j = 0; j < m; ++j)
  {
    const Point_matrix model = space.shape(space.instance_coordinates.col(j));
    space.instance_motions[j] = fit_rigid_motion(model, instances[j]);
    const double scale = centered_norm(instances[j]);
    const double residual = (space.instance_motions[j].apply(model) - instances[j]).norm();
    space.instance_residuals[j] = scale > 0 ? residual / scale : residual;
  }
  return space;
}

} // namespace MPM
} // namespace CGAL
