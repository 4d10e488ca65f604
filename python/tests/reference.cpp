// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The C++ side of the Python tests and of the drag-overhead benchmark: the
// computations the Python suite repeats through `cgal_mpm`, through the C++
// API, printed as JSON with every digit (17 significant digits round-trip).
//
//   mpm_python_reference hand VERTICES POSE_SEED
//       learns the synthetic hand, deforms it with one handle per part to a
//       held-out pose; prints the learned types and the deformed positions.
//   mpm_python_reference drag VERTICES DRAGS
//       learns the synthetic hand, sets one handle per part, then drags the
//       first handle back and forth (1% of the diagonal per frame), one
//       converged solve and one positions() per frame; prints ms per frame.
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <string>

namespace {

using namespace CGAL::MPM;
using Json = nlohmann::json;

std::vector<double> entries(const Eigen::MatrixXd& m)
{
  std::vector<double> v;
  for(Eigen::Index i = 0; i < m.rows(); ++i)
    for(Eigen::Index j = 0; j < m.cols(); ++j) v.push_back(m(i, j));
  return v;
}

Morphable_part_model learned_hand(int vertices, Synthetic_model& hand)
{
  Synthetic_options options;
  options.vertices = vertices;
  hand = make_synthetic_model(Synthetic_family::hand, options);
  return learn_morphable_part_model(hand.mesh, hand.annotation);
}

Json hand(int vertices, unsigned pose_seed)
{
  Synthetic_model synthetic;
  const Morphable_part_model model = learned_hand(vertices, synthetic);
  Json types = Json::array();
  for(const Part_type& t : model.types)
    types.push_back({{"name", t.name}, {"sigmas", entries(t.space.sigmas)}, {"modes", entries(t.space.modes)},
                     {"mean", entries(t.space.mean)}});
  const Handle_set handles = handles_per_part(to_labeled_mesh(model.examples[0]), 1, synthetic.draw_pose(pose_seed));
  // As `cgal_mpm.Editor` does: factored when built, then the handles.
  Embedding_solver solver(make_deformation_problem(model, 0));
  solver.preprocess();
  solver.set_handles(handles.vertices, handles.targets);
  const Solve_report report = solver.solve();
  return {{"types", types},
          {"handles", handles.vertices},
          {"positions", entries(solver.positions())},
          {"energies", report.energies},
          {"iterations", report.iterations}};
}

Json drag(int vertices, int drags)
{
  Synthetic_model synthetic;
  const Morphable_part_model model = learned_hand(vertices, synthetic);
  const Labeled_mesh example = to_labeled_mesh(model.examples[0]);
  const Handle_set handles = handles_per_part(example, 1, example.mesh.points);
  Embedding_solver solver(make_deformation_problem(model, 0));
  solver.preprocess();
  solver.set_handles(handles.vertices, handles.targets);
  solver.preprocess();
  const double diagonal = internal::bounding_box_diagonal(example.mesh.points);
  const Eigen::RowVector3d step = 0.01 * diagonal * Eigen::RowVector3d(1., 1., 1.).normalized();
  Point_matrix targets = handles.targets;
  double checksum = 0.;
  int iterations = 0;
  const auto start = std::chrono::steady_clock::now();
  for(int frame = 0; frame < drags; ++frame)
  {
    targets.row(0) += ((frame / 10) % 2 == 0 ? 1. : -1.) * step;
    solver.set_handles(handles.vertices, targets);
    iterations += solver.solve().iterations;
    checksum += solver.positions()(0, 0);
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return {{"vertices", example.mesh.number_of_vertices()},
          {"drags", drags},
          {"ms_per_drag", ms / drags},
          {"iterations", iterations},
          {"checksum", checksum}};
}

} // namespace

int main(int argc, char** argv)
{
  const std::string usage = "usage: mpm_python_reference hand VERTICES POSE_SEED | drag VERTICES DRAGS";
  if(argc != 4)
  {
    std::cerr << usage << "\n";
    return 2;
  }
  const std::string what = argv[1];
  const int vertices = std::stoi(argv[2]);
  const int third = std::stoi(argv[3]);
  if(what == "hand") std::cout << hand(vertices, unsigned(third)).dump() << "\n";
  else if(what == "drag") std::cout << drag(vertices, third).dump() << "\n";
  else
  {
    std::cerr << usage << "\n";
    return 2;
  }
  return 0;
}
