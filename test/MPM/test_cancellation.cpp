// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A raised cancellation flag stops every long computation at its next
// check with Operation_cancelled, and what was interrupted stays usable.
#include "Learned_models.h"

#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Solver/Cancellation.h>
#include <CGAL/MPM/Baselines/Deformation_method.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/IO/Part_graph_io.h>

#include <gtest/gtest.h>

#include <atomic>

namespace {

using namespace CGAL::MPM;
using mpm_test::learned;
using mpm_test::rows;

// The hand pulled toward a held-out pose by one handle per part.
Handle_set pose_handles(const mpm_test::Learned& l)
{
  Handle_set h;
  for(const Synthetic_instance& i : l.truth.instances) h.vertices.push_back(i.vertices[i.vertices.size() / 2]);
  h.targets = rows(l.truth.draw_pose(7), h.vertices);
  return h;
}

TEST(Cancellation, SolveStopsAtTheNextIterationAndCanResume)
{
  const mpm_test::Learned& l = learned(Synthetic_family::hand, 3000);
  std::atomic<bool> cancel{false};
  Embedding_options options;
  options.cancel = &cancel;
  int iterations = 0, calls = 0;
  options.iteration_callback = [&](int iteration, double) {
    iterations = iteration;
    if(++calls == 2) cancel = true;
  };
  Embedding_solver solver(make_deformation_problem(l.model), options);
  const Handle_set h = pose_handles(l);
  solver.set_handles(h.vertices, h.targets);
  EXPECT_THROW(solver.solve(), Operation_cancelled);
  EXPECT_EQ(iterations, 2);
  EXPECT_TRUE(solver.positions().allFinite());

  // Resumed, it ends where an uninterrupted solve does.
  cancel = false;
  const Solve_report report = solver.solve();
  EXPECT_TRUE(report.converged);
  Embedding_solver uninterrupted(make_deformation_problem(l.model));
  uninterrupted.set_handles(h.vertices, h.targets);
  uninterrupted.solve();
  EXPECT_NEAR(solver.energy(), uninterrupted.energy(), 1e-6 * uninterrupted.energy());
  EXPECT_LT((solver.positions() - uninterrupted.positions()).norm(), 1e-4 * uninterrupted.positions().norm());
}

TEST(Cancellation, ArapAndMpmMethodsStopWhereTheFlagIsRaised)
{
  const mpm_test::Learned& l = learned(Synthetic_family::hand, 3000);
  for(const std::string name : {"arap", "mpm"})
  {
    std::atomic<bool> cancel{false};
    Deformation_method_options options;
    options.cancel = &cancel;
    int calls = 0;
    options.iteration_callback = [&](int iteration) {
      calls = iteration;
      if(iteration == 1) cancel = true;
    };
    auto method = make_deformation_method(name, l.model, 0, options);
    method->set_handles(pose_handles(l));
    EXPECT_THROW(method->deform(), Operation_cancelled) << name;
    EXPECT_EQ(calls, 1) << name;
  }
}

TEST(Cancellation, LearningAndSpawningStopWhenTheFlagIsRaised)
{
  const mpm_test::Learned& l = learned(Synthetic_family::hand, 3000);
  std::atomic<bool> cancel{false};
  Learning_options options;
  options.cancel = &cancel;
  std::vector<std::string> stages;
  options.progress = [&](const std::string& stage, double) {
    stages.push_back(stage);
    if(stage == "dockings") cancel = true;
  };
  EXPECT_THROW(learn_morphable_part_model(l.truth.mesh, l.truth.annotation, options), Operation_cancelled);
  ASSERT_FALSE(stages.empty());
  EXPECT_EQ(stages.back(), "dockings");

  Spawn_options spawn;
  spawn.count = 3;
  spawn.assembly.solver.cancel = &cancel;
  EXPECT_THROW(spawn_part_graphs(l.model, part_graph_of_example(l.model), spawn), Operation_cancelled);
}

} // namespace
