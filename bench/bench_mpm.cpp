// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The MPM solver on the paper-scale models (design.md, section 7), named to
// read side by side with the ARAP baseline of bench_arap.cpp:
//   BM_iteration/<model>/mpm_<step>_<solver>/handles:16  one iterate()
//   BM_factor/<model>/mpm_<step>_<solver>/handles:16     solver construction + set_handles + first iterate()
//   BM_frame/<model>/mpm_<step>_<solver>/handles:16      drag one handle by 1% of the bbox diagonal, solve(), positions()
//   BM_first_frame/<model>/mpm_reduced_<solver>/handles:16  set_handles() on a solver built and preprocessed
//                                                        without handles, solve() from rest, positions()
//   BM_handle_set/<model>/mpm_reduced_<solver>/handles:16   set_handles() and preprocess() on a solver built and
//                                                        preprocessed without handles (a new handle set)
//   BM_learn/<model>                                     learn_morphable_part_model()
// <step> is every Global_step (direct only on the 3k hand: it refactors every
// iteration), <solver> is ldlt (Eigen SimplicialLDLT) or cholmod (when the
// library is built with CHOLMOD). <model> is a synthetic model or, when their
// files are found (bench_models.h), a real mesh learned as one part.
// Handles: 16 farthest-point handles pulling towards a held-out pose (real
// meshes: a smooth bend), the same as ARAP's. Counters: vertices, clusters,
// modes, peak_MB (peak resident memory above the start of the benchmark);
// BM_iteration also has the mean phase times of one iterate() from
// Embedding_solver::last_iteration_timings(): local_step_ms, rhs_ms,
// schur_ms, back_substitution_ms, direct_ms, energy_ms.
#include "bench_models.h"

#include <CGAL/MPM/Solver/Embedding_solver.h>

#include <benchmark/benchmark.h>

#include <Eigen/Core>

#include <exception>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using CGAL::MPM::Embedding_options;
using CGAL::MPM::Embedding_problem;
using CGAL::MPM::Embedding_solver;
using CGAL::MPM::Global_step;
using CGAL::MPM::Sparse_solver;
using mpm_bench::Bench_model;

// Global_step::reduced is being added to the library: use it when the header has it.
template <class Step, class = void>
struct Has_reduced_step : std::false_type
{};
template <class Step>
struct Has_reduced_step<Step, std::void_t<decltype(Step::reduced)>> : std::true_type
{};

template <class Step>
std::vector<std::pair<std::string, Step>> global_steps()
{
  std::vector<std::pair<std::string, Step>> steps{{"direct", Step::direct}, {"schur", Step::schur}};
  if constexpr(Has_reduced_step<Step>::value) steps.emplace_back("reduced", Step::reduced);
  return steps;
}

std::vector<std::pair<std::string, Sparse_solver>> sparse_solvers()
{
  std::vector<std::pair<std::string, Sparse_solver>> solvers{{"ldlt", Sparse_solver::simplicial_ldlt}};
#ifdef CGAL_MPM_HAS_CHOLMOD
  solvers.emplace_back("cholmod", Sparse_solver::cholmod);
#endif
  return solvers;
}

Embedding_options options_of(Global_step step, Sparse_solver solver)
{
  Embedding_options options;
  options.global_step = step;
  options.sparse_solver = solver;
  return options;
}

void set_counters(benchmark::State& state, Bench_model model, const mpm_bench::Memory_probe& memory)
{
  const Embedding_problem& problem = mpm_bench::deformation_problem(model);
  state.counters["vertices"] = problem.mesh.number_of_vertices();
  state.counters["clusters"] = double(problem.clusters.size());
  state.counters["modes"] = mpm_bench::number_of_modes(problem);
  if(memory.extra_peak_mb() >= 0.) state.counters["peak_MB"] = memory.extra_peak_mb();
}

// Frames to convergence: iterations per frame, and the share that converged.
void set_frame_counters(benchmark::State& state, double iterations, double converged)
{
  state.counters["iterations_per_frame"] = benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
  state.counters["converged"] = benchmark::Counter(converged, benchmark::Counter::kAvgIterations);
}

// Builds the model's cached problem and handles (a real mesh is read and
// learned here); on failure, marks the benchmark as skipped with the message.
bool fixtures_ready(benchmark::State& state, Bench_model model)
{
  const std::string error = mpm_bench::prepare([&] {
    mpm_bench::deformation_problem(model);
    mpm_bench::farthest_handles(model, int(state.range(0)));
  });
  if(!error.empty()) state.SkipWithError(error.c_str());
  return error.empty();
}

void BM_iteration(benchmark::State& state, Bench_model model, Global_step step, Sparse_solver solver)
{
  if(!fixtures_ready(state, model)) return;
  const Embedding_problem& problem = mpm_bench::deformation_problem(model);
  const auto& handles = mpm_bench::farthest_handles(model, int(state.range(0)));
  const mpm_bench::Memory_probe memory;
  try {
    Embedding_solver mpm(problem, options_of(step, solver));
    mpm.set_handles(handles.vertices, handles.targets);
    mpm.iterate(); // anything done lazily on the first iteration is factorization, timed below
    CGAL::MPM::Iteration_timings sum;
    for(auto _ : state) {
      benchmark::DoNotOptimize(mpm.iterate());
      const CGAL::MPM::Iteration_timings& t = mpm.last_iteration_timings();
      sum.local_step_ms += t.local_step_ms;
      sum.right_hand_side_ms += t.right_hand_side_ms;
      sum.schur_ms += t.schur_ms;
      sum.back_substitution_ms += t.back_substitution_ms;
      sum.direct_ms += t.direct_ms;
      sum.energy_ms += t.energy_ms;
    }
    const auto mean = [](double ms) { return benchmark::Counter(ms, benchmark::Counter::kAvgIterations); };
    state.counters["local_step_ms"] = mean(sum.local_step_ms);
    state.counters["rhs_ms"] = mean(sum.right_hand_side_ms);
    state.counters["schur_ms"] = mean(sum.schur_ms);
    state.counters["back_substitution_ms"] = mean(sum.back_substitution_ms);
    state.counters["direct_ms"] = mean(sum.direct_ms);
    state.counters["energy_ms"] = mean(sum.energy_ms);
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  set_counters(state, model, memory);
}

void BM_factor(benchmark::State& state, Bench_model model, Global_step step, Sparse_solver solver)
{
  if(!fixtures_ready(state, model)) return;
  const Embedding_problem& problem = mpm_bench::deformation_problem(model);
  const auto& handles = mpm_bench::farthest_handles(model, int(state.range(0)));
  const mpm_bench::Memory_probe memory;
  try {
    for(auto _ : state) {
      std::optional<Embedding_solver> mpm;
      mpm.emplace(problem, options_of(step, solver));
      mpm->set_handles(handles.vertices, handles.targets);
      benchmark::DoNotOptimize(mpm->iterate());
      state.PauseTiming();
      mpm.reset();
      state.ResumeTiming();
    }
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  set_counters(state, model, memory);
}

// One display frame of an interactive drag: from a state converged to the
// handle targets, the first handle (the one farthest from the centroid)
// moves by 1% of the bounding-box diagonal, back and forth every 10 frames.
void BM_frame(benchmark::State& state, Bench_model model, Global_step step, Sparse_solver solver)
{
  if(!fixtures_ready(state, model)) return;
  const Embedding_problem& problem = mpm_bench::deformation_problem(model);
  const auto& handles = mpm_bench::farthest_handles(model, int(state.range(0)));
  const mpm_bench::Memory_probe memory;
  double iterations = 0., converged = 0.;
  try {
    Embedding_solver mpm(problem, options_of(step, solver));
    mpm.set_handles(handles.vertices, handles.targets);
    mpm.solve();
    benchmark::DoNotOptimize(mpm.positions().data());
    CGAL::MPM::Point_matrix targets = handles.targets;
    const Eigen::RowVector3d drag = mpm_bench::frame_drag(problem.mesh.points);
    int frame = 0;
    for(auto _ : state) {
      targets.row(0) += mpm_bench::frame_direction(frame++) * drag;
      mpm.set_handles(handles.vertices, targets);
      const CGAL::MPM::Solve_report report = mpm.solve();
      benchmark::DoNotOptimize(mpm.positions().data());
      iterations += report.iterations;
      converged += report.converged ? 1. : 0.;
    }
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  set_frame_counters(state, iterations, converged);
  set_counters(state, model, memory);
}

// The wait after choosing handles, as the user meets it: the solver is
// built when the model is loaded (not timed); set_handles() (factorization
// and blocks), solve() from rest to convergence and positions() are.
// On a solver built and preprocessed without handles (a model just loaded),
// times `after_load(solver, handles)`; building and destroying the solver
// are not timed. False when the fixtures or the solver failed (the state says why).
template <class After_load>
bool time_on_loaded_solver(benchmark::State& state, Bench_model model, Global_step step, Sparse_solver solver,
                           After_load after_load)
{
  if(!fixtures_ready(state, model)) return false;
  const Embedding_problem& problem = mpm_bench::deformation_problem(model);
  const auto& handles = mpm_bench::farthest_handles(model, int(state.range(0)));
  const mpm_bench::Memory_probe memory;
  try {
    for(auto _ : state) {
      state.PauseTiming();
      std::optional<Embedding_solver> mpm;
      mpm.emplace(problem, options_of(step, solver));
      mpm->preprocess();
      state.ResumeTiming();
      after_load(*mpm, handles);
      state.PauseTiming(); // not the destruction
      mpm.reset();
      state.ResumeTiming();
    }
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return false;
  }
  set_counters(state, model, memory);
  return true;
}

// What a new handle set costs once the model is loaded: set_handles() and
// preprocess() (the low-rank update of the factored block and the handle
// terms). The one-time load costs about what BM_factor measures.
void BM_handle_set(benchmark::State& state, Bench_model model, Global_step step, Sparse_solver solver)
{
  time_on_loaded_solver(state, model, step, solver, [](Embedding_solver& mpm, const CGAL::MPM::Handle_set& handles) {
    mpm.set_handles(handles.vertices, handles.targets);
    mpm.preprocess();
  });
}

// The wait after choosing handles: the new handle set, solve() from rest to
// convergence, positions().
void BM_first_frame(benchmark::State& state, Bench_model model, Global_step step, Sparse_solver solver)
{
  double iterations = 0., converged = 0.;
  const bool ran = time_on_loaded_solver(state, model, step, solver,
                                         [&](Embedding_solver& mpm, const CGAL::MPM::Handle_set& handles) {
    mpm.set_handles(handles.vertices, handles.targets);
    const CGAL::MPM::Solve_report report = mpm.solve();
    benchmark::DoNotOptimize(mpm.positions().data());
    iterations += report.iterations;
    converged += report.converged ? 1. : 0.;
  });
  if(ran) set_frame_counters(state, iterations, converged);
}

void BM_learn(benchmark::State& state, Bench_model model)
{
  if(const std::string error = mpm_bench::prepare([&] { mpm_bench::deformation_problem(model); }); !error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
  // The problem is built for the counters, outside the memory probe.
  const CGAL::MPM::Labeled_mesh& mesh = mpm_bench::training_mesh(model);
  const CGAL::MPM::Annotation& annotation = mpm_bench::bench_annotation(model);
  const mpm_bench::Memory_probe memory;
  for(auto _ : state) {
    CGAL::MPM::Morphable_part_model learned = CGAL::MPM::learn_morphable_part_model(mesh, annotation);
    benchmark::DoNotOptimize(learned.types.data());
    state.PauseTiming(); // not the destruction
    { const CGAL::MPM::Morphable_part_model dropped = std::move(learned); }
    state.ResumeTiming();
  }
  set_counters(state, model, memory);
}

const bool registered = [] {
  const std::vector<Bench_model> models = mpm_bench::all_models();
  using Function = void (*)(benchmark::State&, Bench_model, Global_step, Sparse_solver);
  const std::pair<const char*, Function> kinds[] = {{"BM_iteration", BM_iteration}, {"BM_factor", BM_factor},
                                                    {"BM_frame", BM_frame}, {"BM_first_frame", BM_first_frame},
                                                    {"BM_handle_set", BM_handle_set}};
  for(const auto& [kind, function] : kinds)
    for(Bench_model model : models)
      for(const auto& [step_name, step] : global_steps<Global_step>()) {
        // The direct step assembles and factors the whole system every iteration: a
        // reference point on the small hand only (and no frames: they take seconds).
        if(step == Global_step::direct && (model != Bench_model::hand_3k || function == BM_frame)) continue;
        // The first frame and a new handle set: what users wait for, with the default step only.
        if((function == BM_first_frame || function == BM_handle_set) && step != Global_step::reduced) continue;
        for(const auto& [solver_name, solver] : sparse_solvers()) {
          const std::string name =
              std::string(kind) + "/" + mpm_bench::model_name(model) + "/mpm_" + step_name + "_" + solver_name;
          auto* b = benchmark::RegisterBenchmark(name.c_str(), function, model, step, solver)
                        ->ArgName("handles")->Arg(mpm_bench::bench_handles)->Unit(benchmark::kMillisecond);
          // A frame starts from a converged state, which costs many frames to reach: set it up once.
          if(function == BM_frame) b->Iterations(20);
          if(function == BM_first_frame || function == BM_handle_set) b->Iterations(3); // seconds each on the 66k spider
        }
      }
  for(Bench_model model : models)
    if(model != Bench_model::hand_3k)
      benchmark::RegisterBenchmark((std::string("BM_learn/") + mpm_bench::model_name(model)).c_str(), BM_learn, model)
          ->Unit(benchmark::kMillisecond);
  return true;
}();

} // namespace
