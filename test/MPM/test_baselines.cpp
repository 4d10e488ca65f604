// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The baselines behind the common handle API (Deformation_method): MPM,
// ARAP (original and SRE), linear Laplacian editing, thin-plate splines and
// the shape-space fit alone. Zero handle displacement gives the input back;
// a rigid motion of the handles is exact for the spline (affine part) but
// not for linear Laplacian editing (its details do not rotate); every
// method stays finite on every family; bad handles are refused.
#include <CGAL/MPM/Baselines/Deformation_method.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Editing/Laplacian_editing.h>
#include <CGAL/MPM/Baselines/Shape_space_fit.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Correspondence/Thin_plate_spline.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include "Learned_models.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

using namespace CGAL::MPM;

namespace {

using mpm_test::diagonal;
using mpm_test::Learned;
const Learned& learned(Synthetic_family family) { return mpm_test::learned(family, 2000); }

using mpm_test::max_distance;

// Fewer ARAP iterations than the default keep the suite fast; the tests
// below do not depend on ARAP's convergence.
Deformation_method_options test_options()
{
  Deformation_method_options o;
  o.arap_max_iterations = 200;
  return o;
}

class Baselines_on_family : public ::testing::TestWithParam<Synthetic_family>
{};

} // namespace

TEST_P(Baselines_on_family, zero_displacement_returns_the_input)
{
  const Learned& l = learned(GetParam());
  const Indexed_mesh mesh = to_labeled_mesh(l.model.examples[0]).mesh;
  const double d = diagonal(mesh.points);
  Handle_set handles = farthest_point_handles(mesh, 8, mesh.points);
  const Handle_set per_part = handles_per_part(l.truth.mesh, 1, mesh.points);
  for(std::size_t i = 0; i < per_part.vertices.size(); ++i)
    if(std::find(handles.vertices.begin(), handles.vertices.end(), per_part.vertices[i]) == handles.vertices.end())
    {
      handles.vertices.push_back(per_part.vertices[i]);
      handles.targets.conservativeResize(handles.targets.rows() + 1, 3);
      handles.targets.bottomRows(1) = per_part.targets.row(Eigen::Index(i));
    }
  for(const std::string& name : deformation_method_names())
  {
    SCOPED_TRACE(name);
    auto method = make_deformation_method(name, l.model, 0, test_options());
    EXPECT_EQ(method->name(), name);
    method->set_handles(handles);
    const Point_matrix result = method->deform();
    ASSERT_EQ(result.rows(), mesh.points.rows());
    EXPECT_LE(max_distance(result, mesh.points), 1e-9 * d);
  }
}

TEST_P(Baselines_on_family, every_method_is_finite_on_a_held_out_pose)
{
  const Learned& l = learned(GetParam());
  const Indexed_mesh mesh = to_labeled_mesh(l.model.examples[0]).mesh;
  const Point_matrix pose = l.truth.draw_pose(7);
  const double d = diagonal(pose);
  for(int count : {2, 16})
  {
    const Handle_set handles = farthest_point_handles(mesh, count, pose);
    for(const std::string& name : deformation_method_names())
    {
      SCOPED_TRACE(name + " with " + std::to_string(count) + " handles");
      auto method = make_deformation_method(name, l.model, 0, test_options());
      method->set_handles(handles);
      const Point_matrix result = method->deform();
      ASSERT_TRUE(result.allFinite());
      const double rms = std::sqrt((result - pose).rowwise().squaredNorm().mean()) / d;
      EXPECT_LT(rms, 0.5); // finite and sane: nothing flies away
      if(name == "tps" && count >= 4) EXPECT_LE(handle_rms_residual(result, handles), 1e-8 * d);
      if(name == "mpm" || name == "laplacian") EXPECT_LE(handle_rms_residual(result, handles), 0.05 * d);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(All, Baselines_on_family, ::testing::ValuesIn(all_synthetic_families()),
                         [](const ::testing::TestParamInfo<Synthetic_family>& info) {
                           std::string name = family_name(info.param);
                           for(char& c : name)
                             if(c == '-') c = '_';
                           return name;
                         });

namespace {

Point_matrix rigidly_moved(const Point_matrix& p)
{
  Rigid_motion m;
  m.rotation = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  m.translation = Eigen::Vector3d(0.5, -2, 1);
  return m.apply(p);
}

} // namespace

TEST(Thin_plate_spline, rigid_motion_of_the_handles_is_reproduced_exactly)
{
  const Learned& l = learned(Synthetic_family::hand);
  const Indexed_mesh mesh = to_labeled_mesh(l.model.examples[0]).mesh;
  const Point_matrix moved = rigidly_moved(mesh.points);
  auto tps = make_deformation_method("tps", l.model);
  tps->set_handles(farthest_point_handles(mesh, 16, moved));
  EXPECT_LE(max_distance(tps->deform(), moved), 1e-9 * diagonal(mesh.points));
}

TEST(Thin_plate_spline, interpolates_and_falls_back_to_the_mean_translation)
{
  Point_matrix centres(5, 3), moves(5, 3);
  centres << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  moves << 0.1, 0, 0, 0, 0.2, 0, 0, 0, 0.3, 0.1, 0.1, 0.1, -0.2, 0, 0.1;
  const Thin_plate_spline spline(centres, moves);
  EXPECT_FALSE(spline.is_translation());
  EXPECT_LE((spline.displacement(centres) - moves).norm(), 1e-12);
  // Kernel weights annihilate the affine functions (side conditions).
  EXPECT_LE(spline.kernel_weights().colwise().sum().norm(), 1e-12);

  // Three centres, or four on a plane: the mean translation.
  const Thin_plate_spline three(centres.topRows(3), moves.topRows(3));
  EXPECT_TRUE(three.is_translation());
  Point_matrix planar(4, 3);
  planar << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0;
  const Thin_plate_spline flat(planar, moves.topRows(4));
  EXPECT_TRUE(flat.is_translation());
  const Eigen::RowVector3d mean = moves.topRows(4).colwise().mean();
  EXPECT_LE((flat.displacement(centres).rowwise() - mean).norm(), 1e-15);

  EXPECT_THROW(Thin_plate_spline(centres, moves.topRows(4)), Input_error);
  Point_matrix twice = centres;
  twice.row(1) = twice.row(0);
  EXPECT_THROW(Thin_plate_spline(twice, moves), Input_error);
}

// Linear Laplacian editing keeps the Laplacian coordinates in their rest
// orientation: a rigid motion of all handles is not reproduced (the body
// shears between the handles), but the handles are met and the result is
// finite.
TEST(Laplacian_editing, rigid_motion_is_not_exact_but_meets_the_handles)
{
  const Learned& l = learned(Synthetic_family::hand);
  const Indexed_mesh mesh = to_labeled_mesh(l.model.examples[0]).mesh;
  const Point_matrix moved = rigidly_moved(mesh.points);
  const double d = diagonal(mesh.points);
  const Handle_set handles = farthest_point_handles(mesh, 16, moved);
  Laplacian_editing editing(mesh);
  editing.set_handles(handles);
  const Point_matrix result = editing.deform();
  ASSERT_TRUE(result.allFinite());
  const double handle_rms = handle_rms_residual(result, handles);
  const double rms = std::sqrt((result - moved).rowwise().squaredNorm().mean());
  std::cout << "Laplacian editing, rigid handle motion: handle RMS " << handle_rms / d << ", vertex RMS " << rms / d
            << " of the diagonal\n";
  EXPECT_LE(handle_rms, 0.02 * d);
  EXPECT_GT(rms, 1e-3 * d); // not exact: the details did not rotate
  EXPECT_LT(rms, 0.5 * d);
}

TEST(Laplacian_editing, cotangent_laplacian_is_symmetric_with_zero_row_sums)
{
  const Indexed_mesh mesh = to_labeled_mesh(learned(Synthetic_family::hand).model.examples[0]).mesh;
  const Eigen::SparseMatrix<double> L = cotangent_laplacian(mesh);
  EXPECT_LE((Eigen::SparseMatrix<double>(L.transpose()) - L).norm(), 1e-12 * L.norm());
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(L.cols());
  EXPECT_LE((L * ones).norm(), 1e-10 * L.norm());
  for(int k = 0; k < L.outerSize(); ++k)
    for(Eigen::SparseMatrix<double>::InnerIterator it(L, k); it; ++it)
      if(it.row() != it.col()) EXPECT_LE(it.value(), 0.);
}

TEST(Shape_space_fit, handles_on_a_part_move_it_and_others_stay)
{
  const Learned& l = learned(Synthetic_family::hand);
  const Indexed_mesh mesh = to_labeled_mesh(l.model.examples[0]).mesh;
  const Point_matrix pose = l.truth.draw_pose(3);
  const Handle_set handles = handles_per_part(l.truth.mesh, 2, pose);
  Shape_space_fit fit(l.model);
  fit.set_handles(handles);
  const Point_matrix result = fit.deform();
  ASSERT_TRUE(result.allFinite());
  const double d = diagonal(pose);
  const double rest_error = std::sqrt((mesh.points - pose).rowwise().squaredNorm().mean()) / d;
  const double error = std::sqrt((result - pose).rowwise().squaredNorm().mean()) / d;
  std::cout << "shape-space fit, two handles per part: RMS " << error << " (rest " << rest_error << ")\n";
  EXPECT_LT(error, rest_error);
  EXPECT_GT(fit.iterations(), 0);
}

TEST(Deformation_method, bad_handles_and_names_are_refused)
{
  const Learned& l = learned(Synthetic_family::hexa_grid);
  const int n = l.model.examples[0].mesh.number_of_vertices();
  const Point_matrix rest = to_labeled_mesh(l.model.examples[0]).mesh.points;
  Handle_set out_of_range;
  out_of_range.vertices = {n + 3};
  out_of_range.targets = Point_matrix::Zero(1, 3);
  Handle_set repeated;
  repeated.vertices = {1, 1};
  repeated.targets = rest.topRows(2);
  repeated.targets.row(0) = rest.row(1);
  repeated.targets.row(1) = rest.row(1);
  Handle_set not_finite;
  not_finite.vertices = {2};
  not_finite.targets = rest.row(2);
  not_finite.targets(0, 1) = std::numeric_limits<double>::quiet_NaN();
  Handle_set mismatched;
  mismatched.vertices = {1, 2};
  mismatched.targets = rest.row(1);
  const Handle_set empty;
  for(const std::string& name : deformation_method_names())
  {
    SCOPED_TRACE(name);
    auto method = make_deformation_method(name, l.model, 0, test_options());
    for(const Handle_set* bad : std::vector<const Handle_set*>{&out_of_range, &repeated, &not_finite, &mismatched, &empty})
      EXPECT_THROW(method->set_handles(*bad), Input_error);
  }
  EXPECT_THROW(make_deformation_method("rbf", l.model), Input_error);
  EXPECT_THROW(make_deformation_method("mpm", l.model, 3), Input_error);
  Laplacian_editing editing(to_labeled_mesh(l.model.examples[0]).mesh);
  EXPECT_THROW(editing.deform(), Input_error); // no handles yet
}
