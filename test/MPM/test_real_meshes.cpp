// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's sample meshes (Debian's libcgal-demo data, found through
// MPM_DATA_DIR at run time or the MPM_REAL_MESH_DIR define) cut with the
// example cut files of examples/MPM/data, learned and deformed. Skipped with
// a message when the data are not installed.
#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Model/Shape_space.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include "Learned_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

namespace {

using namespace CGAL::MPM;

std::string data_file(const std::string& name)
{
  const char* dir = std::getenv("MPM_DATA_DIR");
  return std::string(dir && *dir ? dir : MPM_REAL_MESH_DIR) + "/" + name;
}

std::string example_file(const std::string& name) { return std::string(MPM_EXAMPLE_DATA_DIR) + "/" + name; }

using mpm_test::diagonal;

#define MPM_REQUIRE_DATA(path)                                                                                   \
  if(!std::ifstream(path).good())                                                                              \
  GTEST_SKIP() << path << " not found: install libcgal-demo (its data.tar.gz holds CGAL's sample meshes) and " \
                  "reconfigure, or set MPM_DATA_DIR"

// A real mesh cut with its example cut file into a body (label 0) and four
// limbs (labels 1 to 4), with its example annotation.
struct Real_case
{
  const char* mesh;   // file in the data directory
  const char* prefix; // of the example files `PREFIX.cuts.json`, `PREFIX.annotation.json`
};

struct Cut_real_mesh
{
  Labeled_mesh mesh;
  Cut_specification cuts;
  Cutting_result cut;
  explicit Cut_real_mesh(const Real_case& c)
  {
    mesh.source = data_file(c.mesh);
    mesh.mesh = read_mesh_file(mesh.source).mesh;
    cuts = read_cut_specification(example_file(std::string(c.prefix) + ".cuts.json"));
    cut = cut_mesh(mesh.mesh, cuts, Cutting_options(), mesh.source);
    mesh.face_labels = cut.mesh.face_labels;
  }
};

const Real_case diplodocus{"diplodocus.off", "diplodocus_legs"};
const Real_case armadillo{"armadillo.off", "armadillo_limbs"};

TEST(Real_meshes, DiplodocusLegsAreCutOff)
{
  MPM_REQUIRE_DATA(data_file(diplodocus.mesh));
  const Cut_real_mesh d(diplodocus);
  const Indexed_mesh& m = d.mesh.mesh;
  ASSERT_EQ(d.cut.regions, 5);
  std::map<int, int> faces;
  std::map<int, double> highest; // of each part, along y (up)
  for(std::size_t f = 0; f < m.triangles.size(); ++f) {
    const int label = d.mesh.face_labels[f];
    ++faces[label];
    for(int v : m.triangles[f])
      highest[label] = std::max(highest.count(label) ? highest[label] : -1e9, m.points(v, 1));
  }
  ASSERT_EQ(faces.size(), 5u);
  const double top = m.points.col(1).maxCoeff(), bottom = m.points.col(1).minCoeff();
  std::cout << "diplodocus: body " << faces[0] << " faces; legs";
  for(int leg = 1; leg <= 4; ++leg) {
    std::cout << " " << faces[leg];
    // A leg is a few thousand faces that stay below the belly.
    EXPECT_GT(faces[leg], 2000) << "leg " << leg;
    EXPECT_LT(faces[leg], 6000) << "leg " << leg;
    EXPECT_LT(highest[leg], bottom + 0.3 * (top - bottom)) << "leg " << leg;
    EXPECT_GT(d.cut.lengths[std::size_t(leg - 1)], 0.05 * diagonal(m.points));
    EXPECT_LT(d.cut.lengths[std::size_t(leg - 1)], 0.3 * diagonal(m.points));
  }
  std::cout << "\n";
  EXPECT_GT(faces[0], 30000);
  EXPECT_EQ(highest[0], top); // the head belongs to the body

  // Concave is judged from the outside, whichever way the faces turn.
  Indexed_mesh flipped = m;
  for(Triangle& t : flipped.triangles) std::swap(t[1], t[2]);
  const Cutting_result again = cut_mesh(flipped, d.cuts, Cutting_options(), "flipped diplodocus");
  EXPECT_EQ(again.paths, d.cut.paths);
  EXPECT_EQ(again.mesh.face_labels, d.mesh.face_labels);
}

TEST(Real_meshes, ArmadilloLimbsAreCutOff)
{
  MPM_REQUIRE_DATA(data_file(armadillo.mesh));
  const Cut_real_mesh a(armadillo);
  const Indexed_mesh& m = a.mesh.mesh;
  ASSERT_EQ(a.cut.regions, 5);
  std::map<int, Eigen::RowVector3d> centroid;
  std::map<int, int> faces;
  for(std::size_t f = 0; f < m.triangles.size(); ++f) {
    const int label = a.mesh.face_labels[f];
    if(faces[label]++ == 0) centroid[label].setZero();
    centroid[label] += m.points.row(m.triangles[f][0]);
  }
  for(auto& [label, c] : centroid) c /= faces[label];
  // Legs (1, 2) hang below the body's centroid, arms (3, 4) reach out beyond it
  // along x on either side; each limb is a tenth of the mesh, give or take.
  const Eigen::RowVector3d body = centroid[0];
  const double width = m.points.col(0).maxCoeff() - m.points.col(0).minCoeff();
  EXPECT_LT(centroid[1](1), body(1));
  EXPECT_LT(centroid[2](1), body(1));
  EXPECT_LT(centroid[3](0), body(0) - 0.3 * width);
  EXPECT_GT(centroid[4](0), body(0) + 0.3 * width);
  for(int limb = 1; limb <= 4; ++limb) {
    EXPECT_GT(faces[limb], 3000) << "limb " << limb;
    EXPECT_LT(faces[limb], 8000) << "limb " << limb;
  }
  std::cout << "armadillo: body " << faces[0] << " faces; legs " << faces[1] << " " << faces[2] << "; arms "
            << faces[3] << " " << faces[4] << "\n";
}

// Leave-one-out reconstruction error of each part type with two or more
// instances: each instance fitted (rigid motion and coordinates) by the
// shape space of the others, RMS point error over the diagonal of the mean.
std::map<std::string, double> leave_one_out_errors(const Morphable_part_model& model)
{
  std::map<std::string, double> errors;
  const Training_example& example = model.examples.front();
  const Labeled_mesh labeled = to_labeled_mesh(example);
  for(std::size_t t = 0; t < model.types.size(); ++t) {
    std::vector<Point_matrix> instances;
    for(const Part_node& node : example.graph.nodes)
      if(node.type == int(t)) {
        // A stitched part lists the seam vertices inserted into it after its own.
        const std::size_t n = std::size_t(model.types[t].number_of_vertices);
        Point_matrix p(Eigen::Index(n), 3);
        for(std::size_t i = 0; i < n; ++i) p.row(Eigen::Index(i)) = labeled.mesh.points.row(node.vertices[i]);
        instances.push_back(std::move(p));
      }
    if(instances.size() < 2) continue;
    double sum = 0.;
    for(std::size_t j = 0; j < instances.size(); ++j) {
      std::vector<Point_matrix> others;
      for(std::size_t i = 0; i < instances.size(); ++i)
        if(i != j) others.push_back(instances[i]);
      Shape_space_options options;
      options.modes = int(others.size());
      const Shape_space space = learn_shape_space(others, options);
      Eigen::VectorXd coordinates;
      Rigid_motion motion;
      space.fit(instances[j], coordinates, motion);
      const Point_matrix fitted = motion.apply(space.shape(coordinates));
      sum += std::sqrt((fitted - instances[j]).rowwise().squaredNorm().mean()) / diagonal(space.mean);
    }
    errors[model.types[t].name] = sum / double(instances.size());
  }
  return errors;
}

int nearest_vertex(const Point_matrix& points, const Eigen::RowVector3d& p)
{
  Eigen::Index best = 0;
  (points.rowwise() - p).rowwise().squaredNorm().minCoeff(&best);
  return int(best);
}

class Real_mesh_learning : public ::testing::TestWithParam<Real_case>
{};

TEST_P(Real_mesh_learning, LearnsAndDeforms)
{
  const Real_case& c = GetParam();
  MPM_REQUIRE_DATA(data_file(c.mesh));
  const Cut_real_mesh cut(c);
  const Annotation annotation = read_annotation(example_file(std::string(c.prefix) + ".annotation.json"));
  // Same-type limbs are triangulated differently: learning corresponds them.
  const Morphable_part_model model = learn_morphable_part_model(cut.mesh, annotation);
  std::set<std::string> types;
  for(const auto& [label, type] : annotation.part_type_of_label) types.insert(type);
  ASSERT_EQ(model.types.size(), types.size());

  const std::map<std::string, double> errors = leave_one_out_errors(model);
  std::cout << c.mesh << " leave-one-out reconstruction error (RMS / diagonal of the mean):";
  for(const auto& [type, error] : errors) {
    std::cout << " " << type << " " << error;
    ::testing::Test::RecordProperty("leave_one_out_" + type, std::to_string(error));
    EXPECT_TRUE(std::isfinite(error));
    EXPECT_LT(error, 0.15) << type;
  }
  std::cout << "\n";
  EXPECT_EQ(errors.size(), types.size() - 1); // every type but the body has several instances

  // Hold the limb ends (the cut file's seeds) and the top of the mesh; step
  // the first limb forward and lift the top. Vertices are found by position
  // in the learned example, whose numbering learning may change.
  const Indexed_mesh rest = to_labeled_mesh(model.examples.front()).mesh;
  const double diag = diagonal(rest.points);
  const Point_matrix& input = cut.mesh.mesh.points;
  Handle_set handles;
  std::vector<Eigen::RowVector3d> targets;
  auto hold = [&](const Eigen::RowVector3d& at, const Eigen::RowVector3d& move) {
    handles.vertices.push_back(nearest_vertex(rest.points, at));
    targets.push_back(rest.points.row(handles.vertices.back()) + move);
  };
  Eigen::Index top = 0;
  input.col(1).maxCoeff(&top);
  hold(input.row(top), Eigen::RowVector3d(0.02, 0.05, 0.) * diag);
  for(std::size_t p = 0; p < cut.cuts.parts.size(); ++p)
    hold(input.row(cut.cuts.parts[p].seed), Eigen::RowVector3d(p == 0 ? 0.04 * diag : 0., p == 0 ? 0.02 * diag : 0., 0.));
  handles.targets.resize(Eigen::Index(targets.size()), 3);
  for(std::size_t i = 0; i < targets.size(); ++i) handles.targets.row(Eigen::Index(i)) = targets[i];

  Embedding_solver solver(make_deformation_problem(model));
  solver.set_handles(handles.vertices, handles.targets);
  const Solve_report report = solver.solve();
  const Point_matrix& result = solver.positions();
  ASSERT_EQ(result.rows(), rest.points.rows());
  ASSERT_TRUE(result.allFinite());
  EXPECT_TRUE(std::isfinite(report.energy()));
  const double displacement = (result - rest.points).rowwise().norm().maxCoeff();
  EXPECT_LT(displacement, 0.25 * diag);
  EXPECT_GT(displacement, 0.03 * diag); // the edit happened
  double handle_error = 0.;
  for(int h = 0; h < handles.size(); ++h)
    handle_error = std::max(handle_error, (result.row(handles.vertices[std::size_t(h)]) - handles.targets.row(h)).norm());
  EXPECT_LT(handle_error, 0.02 * diag);
  // No triangle collapses: every area keeps a fair fraction of its rest value.
  double worst = 1e9;
  for(const Triangle& t : rest.triangles) {
    auto area = [&](const Point_matrix& p) {
      return (p.row(t[1]) - p.row(t[0])).cross(p.row(t[2]) - p.row(t[0])).norm();
    };
    worst = std::min(worst, area(result) / area(rest.points));
  }
  std::cout << c.mesh << " deformation: " << report.iterations << " iterations, max displacement "
            << displacement / diag << ", handle error " << handle_error / diag << " of the diagonal, smallest area ratio "
            << worst << "\n";
  EXPECT_GT(worst, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Real_meshes, Real_mesh_learning, ::testing::Values(diplodocus, armadillo),
                         [](const ::testing::TestParamInfo<Real_case>& info) {
                           return std::string(info.param.prefix);
                         });

} // namespace
