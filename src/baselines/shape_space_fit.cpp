// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Baselines/Shape_space_fit.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace MPM {

namespace {

// A part instance in world coordinates: its rest points and its type's
// modes turned into the instance's placement.
struct Part
{
  std::vector<int> vertices;
  Point_matrix rest;        // n_c x 3
  Eigen::MatrixXd modes;    // 3 n_c x d, world orientation
  Eigen::VectorXd prior;    // d: 1 / (4 sigma_k^2)
};

Point_matrix part_shape(const Part& p, const Eigen::VectorXd& coordinates)
{
  Point_matrix s = p.rest;
  if(coordinates.size() == 0) return s;
  const Eigen::VectorXd offset = p.modes * coordinates;
  for(Eigen::Index i = 0; i < s.rows(); ++i) s.row(i) += offset.segment<3>(3 * i).transpose();
  return s;
}

// Rigid motion taking `from` onto `to` (rows correspond): Kabsch for points
// spanning a plane, the smallest rotation aligning their lines for collinear
// points, a translation for one point.
Rigid_motion fit_motion(const Point_matrix& from, const Point_matrix& to)
{
  Rigid_motion m;
  const Eigen::RowVector3d cf = from.colwise().mean(), ct = to.colwise().mean();
  if(from.rows() >= 2)
  {
    const Point_matrix a = from.rowwise() - cf, b = to.rowwise() - ct;
    // Three columns: the full V is 3 x 3 (thin V is only for dynamic columns).
    Eigen::JacobiSVD<Point_matrix> svd_a(a, Eigen::ComputeFullV), svd_b(b, Eigen::ComputeFullV);
    // Two points have two singular values.
    const Eigen::VectorXd sa = svd_a.singularValues(), sb = svd_b.singularValues();
    const bool planar = from.rows() >= 3 && sa[1] > 1e-6 * sa[0] && sb[1] > 1e-6 * sb[0];
    if(planar)
      m = fit_rigid_motion(from, to);
    else if(sa[0] > 0 && sb[0] > 0)
    {
      Eigen::Vector3d da = svd_a.matrixV().col(0), db = svd_b.matrixV().col(0);
      if((a * da).dot(b * db) < 0) db = -db;
      m.rotation = Eigen::Quaterniond::FromTwoVectors(da, db).toRotationMatrix();
    }
  }
  m.translation = ct.transpose() - m.rotation * cf.transpose();
  return m;
}

} // namespace

struct Shape_space_fit::Impl
{
  Point_matrix rest;
  std::vector<Part> parts;
  std::vector<std::vector<std::pair<int, int>>> parts_of_vertex; // (part, local index)
  double data_weight = 1.;
  Handle_set handles;
  bool has_handles = false;
  mutable int iterations = 0;
};

Shape_space_fit::Shape_space_fit(const Morphable_part_model& model, int example) : impl_(std::make_unique<Impl>())
{
  if(example < 0 || example >= static_cast<int>(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  const Training_example& ex = model.examples[std::size_t(example)];
  Impl& d = *impl_;
  d.rest = rest_positions(ex);
  const double sigma_sub = model.parameters.sigma_sub;
  d.data_weight = sigma_sub > 0 && std::isfinite(sigma_sub) ? 1. / (sigma_sub * sigma_sub) : 1.;
  d.parts_of_vertex.resize(std::size_t(d.rest.rows()));
  for(const Part_node& node : ex.graph.nodes)
  {
    const Shape_space& space = model.types[std::size_t(node.type)].space;
    Part p;
    p.vertices = node.vertices;
    p.rest.resize(Eigen::Index(node.vertices.size()), 3);
    for(std::size_t i = 0; i < node.vertices.size(); ++i) p.rest.row(Eigen::Index(i)) = d.rest.row(node.vertices[i]);
    p.modes = space.modes;
    for(Eigen::Index i = 0; i < p.rest.rows() && p.modes.cols() > 0; ++i)
      p.modes.middleRows(3 * i, 3) = node.motion.rotation * p.modes.middleRows(3 * i, 3);
    p.prior.resize(space.sigmas.size());
    for(Eigen::Index k = 0; k < space.sigmas.size(); ++k)
      p.prior[k] = space.sigmas[k] > 0 ? 1. / (4. * space.sigmas[k] * space.sigmas[k]) : 1e30;
    const int index = static_cast<int>(d.parts.size());
    for(std::size_t i = 0; i < p.vertices.size(); ++i)
      d.parts_of_vertex[std::size_t(p.vertices[i])].emplace_back(index, static_cast<int>(i));
    d.parts.push_back(std::move(p));
  }
}

Shape_space_fit::~Shape_space_fit() = default;
Shape_space_fit::Shape_space_fit(Shape_space_fit&&) noexcept = default;
Shape_space_fit& Shape_space_fit::operator=(Shape_space_fit&&) noexcept = default;

void Shape_space_fit::set_handles(const Handle_set& handles)
{
  validate_handles(handles, static_cast<int>(impl_->rest.rows()), "handle set");
  if(handles.size() == 0) throw Input_error("handle set", "", "no handles");
  impl_->handles = handles;
  impl_->has_handles = true;
}

int Shape_space_fit::iterations() const { return impl_->iterations; }

Point_matrix Shape_space_fit::deform() const
{
  const Impl& d = *impl_;
  if(!d.has_handles) throw Input_error("shape-space fit", "", "no handles are set");
  // Handles of each part: (local index, target row).
  std::vector<std::vector<std::pair<int, int>>> held(d.parts.size());
  for(int h = 0; h < d.handles.size(); ++h)
    for(const auto& [part, local] : d.parts_of_vertex[std::size_t(d.handles.vertices[std::size_t(h)])])
      held[std::size_t(part)].emplace_back(local, h);

  Point_matrix sum = Point_matrix::Zero(d.rest.rows(), 3);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(d.rest.rows());
  d.iterations = 0;
  for(std::size_t c = 0; c < d.parts.size(); ++c)
  {
    const Part& p = d.parts[c];
    Point_matrix placed = p.rest;
    if(!held[c].empty())
    {
      const int k = static_cast<int>(held[c].size());
      const Eigen::Index modes = p.modes.cols();
      Point_matrix targets(k, 3);
      for(int h = 0; h < k; ++h) targets.row(h) = d.handles.targets.row(held[c][std::size_t(h)].second);
      Rigid_motion motion;
      Eigen::VectorXd coordinates = Eigen::VectorXd::Zero(modes);
      double previous = std::numeric_limits<double>::infinity();
      for(int it = 0; it < 100; ++it)
      {
        ++d.iterations;
        // Coordinates and translation for the fixed rotation, in the part's
        // frame: minimize w |m_h + B_h lambda + u - R^T y_h|^2 + prior.
        Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(modes + 3, modes + 3);
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(modes + 3);
        for(int h = 0; h < k; ++h)
        {
          const int local = held[c][std::size_t(h)].first;
          Eigen::MatrixXd J(3, modes + 3);
          if(modes > 0) J.leftCols(modes) = p.modes.middleRows(3 * local, 3);
          J.rightCols(3) = Eigen::Matrix3d::Identity();
          const Eigen::Vector3d z =
            motion.rotation.transpose() * targets.row(h).transpose() - p.rest.row(local).transpose();
          normal += d.data_weight * J.transpose() * J;
          rhs += d.data_weight * J.transpose() * z;
        }
        for(Eigen::Index m = 0; m < modes; ++m) normal(m, m) += p.prior[m];
        const Eigen::VectorXd x = normal.ldlt().solve(rhs);
        coordinates = x.head(modes);
        const Point_matrix shape = part_shape(p, coordinates);
        Point_matrix model(k, 3);
        for(int h = 0; h < k; ++h) model.row(h) = shape.row(held[c][std::size_t(h)].first);
        motion = fit_motion(model, targets);
        const double energy = d.data_weight * (motion.apply(model) - targets).squaredNorm() +
                              (modes > 0 ? coordinates.cwiseAbs2().dot(p.prior) : 0.);
        if(!(energy < previous * (1 - 1e-12)) || energy <= 1e-300) break;
        previous = energy;
      }
      placed = motion.apply(part_shape(p, coordinates));
    }
    for(std::size_t i = 0; i < p.vertices.size(); ++i)
    {
      sum.row(p.vertices[i]) += placed.row(Eigen::Index(i));
      count[p.vertices[i]] += 1.;
    }
  }
  Point_matrix result = d.rest;
  for(Eigen::Index v = 0; v < result.rows(); ++v)
    if(count[v] > 0) result.row(v) = sum.row(v) / count[v];
  if(!result.allFinite()) throw Computation_error("shape-space fit produced non-finite positions");
  return result;
}

} // namespace MPM
} // namespace CGAL
