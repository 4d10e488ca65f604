// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Solver_thread.h"

#include <CGAL/MPM/Editing/Arap_deformation.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Input_error.h>

namespace mpm_demo {

namespace MPM = CGAL::MPM;

namespace {

// ARAP is a baseline shown next to MPM: enough iterations to settle a drag
// on the demo's meshes, in chunks short enough not to hold MPM's frames up.
constexpr int arap_iterations_per_chunk = 10;
constexpr int arap_iterations_per_request = 200;
constexpr double arap_tolerance = 1e-4;

} // namespace

Solver_thread::Solver_thread(QObject* parent) : QThread(parent) {}

Solver_thread::~Solver_thread() { finish(); }

void Solver_thread::post(Solve_request request)
{
  QMutexLocker lock(&mutex_);
  pending_ = std::move(request);
  has_pending_ = true;
  wake_.wakeOne();
}

void Solver_thread::finish()
{
  {
    QMutexLocker lock(&mutex_);
    stop_ = true;
    wake_.wakeOne();
  }
  wait();
}

void Solver_thread::run()
{
  std::unique_ptr<MPM::Embedding_solver> solver;
  std::unique_ptr<MPM::Arap_deformation> arap;
  std::shared_ptr<const MPM::Embedding_problem> built;
  double built_coupling = 0.;
  bool solver_has_handles = false;
  Solve_request r;      // the request being worked on
  Solve_frame f;        // its frame so far
  int arap_iterations = 0;
  bool unfinished = false; // ARAP has iterations left for `r`
  for(;;)
  {
    bool fresh = false;
    {
      QMutexLocker lock(&mutex_);
      while(!has_pending_ && !stop_ && !unfinished) wake_.wait(&mutex_);
      if(stop_) return;
      if(has_pending_)
      {
        r = std::move(pending_);
        has_pending_ = false;
        fresh = true;
      }
    }
    if(fresh)
    {
      f = Solve_frame();
      f.serial = r.serial;
      f.posted = r.posted;
      arap_iterations = 0;
      try
      {
        if(r.problem != built || r.options.coupling_weight != built_coupling)
        {
          solver.reset();
          arap.reset();
          built.reset();
          solver = std::make_unique<MPM::Embedding_solver>(*r.problem, r.options);
          // Factored once without handles: every handle set is then a
          // low-rank update (the scene's first request has no handles).
          solver->preprocess();
          built = r.problem;
          built_coupling = r.options.coupling_weight;
          solver_has_handles = false;
        }
        else if(r.restart)
        {
          solver->reset();
          if(arap) arap->reset();
        }
        const auto start = std::chrono::steady_clock::now();
        if(!r.handle_vertices.empty())
        {
          solver->set_handles(r.handle_vertices, r.handle_targets);
          solver_has_handles = true;
        }
        else if(solver_has_handles)
        {
          solver->clear_handles();
          solver_has_handles = false;
        }
        const MPM::Solve_report report = solver->solve();
        f.positions = r.unfold ? MPM::unfold_faces(r.problem->mesh, solver->positions(), r.handle_vertices)
                               : solver->positions();
        f.ms = milliseconds_since(start);
        f.iterations = report.iterations;
        f.converged = report.converged;
        f.energy = report.energy();
        if(!f.positions.allFinite())
          throw MPM::Computation_error("the solver produced non-finite positions (try smaller drags)");
      }
      catch(const std::exception& e)
      {
        f.error = QString::fromStdString(e.what());
        f.positions.resize(0, 3);
      }
    }
    // ARAP runs in short chunks, continued while no new request waits, so
    // that a drag with ARAP shown still gets MPM frames at MPM's pace.
    unfinished = false;
    if(r.arap && built)
    {
      try
      {
        if(r.handle_vertices.empty()) throw MPM::Input_error("ARAP", "handles", "there are none: pick some first");
        if(!arap) arap = std::make_unique<MPM::Arap_deformation>(r.problem->mesh);
        if(fresh)
        {
          MPM::Handle_set handles;
          handles.vertices = r.handle_vertices;
          handles.targets = r.handle_targets;
          arap->set_handles(handles);
        }
        const auto start = std::chrono::steady_clock::now();
        const int done = arap->deform(arap_iterations_per_chunk, arap_tolerance);
        arap_iterations += done;
        f.arap_iterations = arap_iterations;
        f.arap_positions = arap->positions();
        f.arap_ms = (fresh ? 0. : f.arap_ms) + milliseconds_since(start);
        unfinished = done == arap_iterations_per_chunk && arap_iterations < arap_iterations_per_request;
      }
      catch(const std::exception& e)
      {
        f.arap_error = QString::fromStdString(e.what());
        f.arap_positions.resize(0, 3);
      }
    }
    f.final = !unfinished;
    Q_EMIT frame_ready(f);
  }
}

} // namespace mpm_demo
