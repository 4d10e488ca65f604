// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's sample meshes (Debian's libcgal-demo data, found through
// MPM_DATA_DIR at run time or the MPM_REAL_MESH_DIR define) cut with the
// example cut files of examples/MPM/data, learned and deformed. Skipped with
// a message when the data are not installed.
#include <CGAL/MPM/Annotation_io.h>
#include <CGAL/MPM/Editing.h>
#include <CGAL/MPM/Embedding_solver.h>
#include <CGAL/MPM/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Mesh_cutting.h>
#include <CGAL/MPM/Mesh_io.h>
#include <CGAL/MPM/Shape_space.h>
#include <CGAL/MPM/learn_morphable_part_model.h>

#include <gtest/gtest.h>

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

double diagonal(const Point_matrix& p) { return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(); }

#define MPM_REQUIRE_DATA(path)                                                                                   \
  if(!std::ifstream(path).good())                                                                              \
  GTEST_SKIP() << path << " not found: install libcgal-demo (its data.tar.gz holds CGAL's sample meshes) and " \
                  "reconfigure, or set MPM_DATA_DIR"

// The diplodocus cut into a body (label 0) and four legs (labels 1 to 4).
struct Diplodocus
{
  Labeled_mesh mesh;
  Cutting_result cut;
  Diplodocus()
  {
    mesh.source = data_file("diplodocus.off");
    mesh.mesh = read_mesh_file(mesh.source).mesh;
    cut = cut_mesh(mesh.mesh, read_cut_specification(example_file("diplodocus_legs.cuts.json")), Cutting_options(),
                   mesh.source);
    mesh.face_labels = cut.mesh.face_labels;
  }
};

TEST(Real_meshes, DiplodocusLegsAreCutOff)
{
  MPM_REQUIRE_DATA(data_file("diplodocus.off"));
  const Diplodocus d;
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
}

// Leave-one-out reconstruction error of each part type with three or more
// instances: each instance fitted (rigid motion and coordinates) by the
// shape space of the others, RMS point error over the diagonal of the mean.
std::map<std::string, double> leave_one_out_errors(const Morphable_part_model& model)
{
  std::map<std::string, double> errors;
  const Training_example& example = model.examples.front();
  for(std::size_t t = 0; t < model.types.size(); ++t) {
    std::vector<Point_matrix> instances;
    for(const Part_node& node : example.graph.nodes)
      if(node.type == int(t)) {
        Point_matrix p(Eigen::Index(node.vertices.size()), 3);
        for(std::size_t i = 0; i < node.vertices.size(); ++i) p.row(Eigen::Index(i)) = example.mesh.points.row(node.vertices[i]);
        instances.push_back(std::move(p));
      }
    if(instances.size() < 3) continue;
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

TEST(Real_meshes, DiplodocusLearnsAndDeforms)
{
  MPM_REQUIRE_DATA(data_file("diplodocus.off"));
  const Diplodocus d;
  const Annotation annotation = read_annotation(example_file("diplodocus_legs.annotation.json"));
  Morphable_part_model model;
  try {
    model = learn_morphable_part_model(d.mesh, annotation);
  } catch(const Input_error& e) {
    // The four legs are triangulated differently: learning them as one type
    // needs the dense correspondence of issue 6, which is not merged yet.
    if(std::string(e.what()).find("connectivity") != std::string::npos)
      GTEST_SKIP() << "learning needs dense correspondence between differently triangulated legs: " << e.what();
    throw;
  }
  ASSERT_EQ(model.types.size(), 2u);
  ASSERT_GE(model.find_type("leg"), 0);

  const std::map<std::string, double> errors = leave_one_out_errors(model);
  ASSERT_EQ(errors.count("leg"), 1u);
  std::cout << "diplodocus leave-one-out reconstruction error (RMS / diagonal of the mean):";
  for(const auto& [type, error] : errors) {
    std::cout << " " << type << " " << error;
    ::testing::Test::RecordProperty("leave_one_out_" + type, std::to_string(error));
    EXPECT_TRUE(std::isfinite(error));
    EXPECT_LT(error, 0.1) << type;
  }
  std::cout << "\n";

  // Plant the feet and the tail tip, lift the head and step the front left
  // foot forward; in the learned example's own vertex numbering.
  const Indexed_mesh& rest = model.examples.front().mesh;
  const double diag = diagonal(rest.points);
  const Point_matrix& input = d.mesh.mesh.points;
  Handle_set handles;
  std::vector<Eigen::RowVector3d> targets;
  auto hold = [&](const Eigen::RowVector3d& at, const Eigen::RowVector3d& move) {
    handles.vertices.push_back(nearest_vertex(rest.points, at));
    targets.push_back(rest.points.row(handles.vertices.back()) + move);
  };
  Eigen::Index head = 0, tail = 0;
  input.col(1).maxCoeff(&head);
  input.col(0).minCoeff(&tail);
  hold(input.row(head), Eigen::RowVector3d(0.02, 0.05, 0.) * diag);
  hold(input.row(tail), Eigen::RowVector3d::Zero());
  for(int seed : {2036, 7175, 19355}) hold(input.row(seed), Eigen::RowVector3d::Zero());
  hold(input.row(18112), Eigen::RowVector3d(0.04, 0.02, 0.) * diag);
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
  std::cout << "diplodocus deformation: " << report.iterations << " iterations, max displacement "
            << displacement / diag << ", handle error " << handle_error / diag << " of the diagonal, smallest area ratio "
            << worst << "\n";
  EXPECT_GT(worst, 0.05);
}

} // namespace
