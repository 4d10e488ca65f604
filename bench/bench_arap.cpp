// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The ARAP baseline (CGAL::Surface_mesh_deformation): time of one
// local/global iteration and of the factorization, on the paper-scale models
// with handles pulling towards a held-out pose. The last argument is the
// number of farthest-point handles. Names match bench_mpm.cpp, so rows read
// side by side: BM_iteration/hand_23k/arap/handles:16 next to
// BM_iteration/hand_23k/mpm_schur_ldlt/handles:16. BM_first_frame and
// BM_frame run ARAP to convergence as the demo does, for the wait after
// choosing handles and a drag frame.
#include "bench_models.h"

#include <CGAL/MPM/Editing/Arap_deformation.h>

#include <benchmark/benchmark.h>

#include <exception>
#include <optional>
#include <string>

namespace {

using CGAL::MPM::Arap_deformation;
using mpm_bench::Bench_model;

void set_mesh_counters(benchmark::State& state, Bench_model model, const mpm_bench::Memory_probe& memory)
{
  state.counters["vertices"] = mpm_bench::bench_mesh(model).mesh.number_of_vertices();
  if(memory.extra_peak_mb() >= 0.) state.counters["peak_MB"] = memory.extra_peak_mb();
}

// Builds the model's cached handles (a real mesh is read here); on failure,
// marks the benchmark as skipped with the message.
bool handles_ready(benchmark::State& state, Bench_model model)
{
  const std::string error = mpm_bench::prepare([&] { mpm_bench::farthest_handles(model, int(state.range(0))); });
  if(!error.empty()) state.SkipWithError(error.c_str());
  return error.empty();
}

void BM_arap_iteration(benchmark::State& state, Bench_model model)
{
  if(!handles_ready(state, model)) return;
  const auto& handles = mpm_bench::farthest_handles(model, int(state.range(0)));
  const mpm_bench::Memory_probe memory;
  try {
    Arap_deformation arap(mpm_bench::bench_mesh(model).mesh);
    arap.set_handles(handles);
    arap.preprocess();
    for(auto _ : state) arap.deform_one_iteration();
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  set_mesh_counters(state, model, memory);
}

void BM_arap_preprocess(benchmark::State& state, Bench_model model)
{
  if(!handles_ready(state, model)) return;
  const auto& handles = mpm_bench::farthest_handles(model, int(state.range(0)));
  const mpm_bench::Memory_probe memory;
  try {
    for(auto _ : state) {
      state.PauseTiming();
      // A fresh object each time: a factorization is cached until the handle vertices change.
      Arap_deformation arap(mpm_bench::bench_mesh(model).mesh);
      arap.set_handles(handles);
      state.ResumeTiming();
      arap.preprocess();
    }
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  set_mesh_counters(state, model, memory);
}

// ARAP run as the demo runs it: until an iteration moves no vertex by more
// than 1e-4 of the bounding-box diagonal, at most 200 iterations.
constexpr int converged_iterations = 200;
constexpr double converged_tolerance = 1e-4;

// The wait after choosing handles: the deformation object is made when the
// mesh is loaded (not timed); set_handles(), preprocess(), deform() from
// rest to convergence and positions() are.
void BM_arap_first_frame(benchmark::State& state, Bench_model model)
{
  if(!handles_ready(state, model)) return;
  const auto& handles = mpm_bench::farthest_handles(model, int(state.range(0)));
  const mpm_bench::Memory_probe memory;
  double iterations = 0.;
  try {
    for(auto _ : state) {
      state.PauseTiming();
      std::optional<Arap_deformation> arap;
      arap.emplace(mpm_bench::bench_mesh(model).mesh);
      state.ResumeTiming();
      arap->set_handles(handles);
      arap->preprocess();
      iterations += arap->deform(converged_iterations, converged_tolerance);
      benchmark::DoNotOptimize(arap->positions().data());
      state.PauseTiming(); // not the destruction
      arap.reset();
      state.ResumeTiming();
    }
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["iterations_per_frame"] = benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
  set_mesh_counters(state, model, memory);
}

// A drag frame as bench_mpm.cpp's BM_frame has it: from a converged state
// the first handle moves by 1% of the diagonal (back and forth every 10
// frames), then deform() to convergence and positions().
void BM_arap_frame(benchmark::State& state, Bench_model model)
{
  if(!handles_ready(state, model)) return;
  CGAL::MPM::Handle_set handles = mpm_bench::farthest_handles(model, int(state.range(0)));
  const Eigen::RowVector3d drag = mpm_bench::frame_drag(mpm_bench::bench_mesh(model).mesh.points);
  const mpm_bench::Memory_probe memory;
  double iterations = 0.;
  try {
    Arap_deformation arap(mpm_bench::bench_mesh(model).mesh);
    arap.set_handles(handles);
    arap.deform(converged_iterations, converged_tolerance);
    int frame = 0;
    for(auto _ : state) {
      handles.targets.row(0) += mpm_bench::frame_direction(frame++) * drag;
      arap.set_handles(handles);
      iterations += arap.deform(converged_iterations, converged_tolerance);
      benchmark::DoNotOptimize(arap.positions().data());
    }
  } catch(const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["iterations_per_frame"] = benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
  set_mesh_counters(state, model, memory);
}

const bool arap_benchmarks_registered = [] {
  for(Bench_model model : mpm_bench::all_models()) {
    const std::string name = mpm_bench::model_name(model);
    auto* iteration = benchmark::RegisterBenchmark(("BM_iteration/" + name + "/arap").c_str(), BM_arap_iteration, model)
                          ->ArgName("handles")->Unit(benchmark::kMillisecond);
    if(model == Bench_model::hand_23k || model == Bench_model::spider_66k) iteration->Arg(1);
    iteration->Arg(mpm_bench::bench_handles);
    benchmark::RegisterBenchmark(("BM_factor/" + name + "/arap").c_str(), BM_arap_preprocess, model)
        ->ArgName("handles")->Arg(mpm_bench::bench_handles)->Unit(benchmark::kMillisecond);
    // Converging takes ARAP seconds on the large models: few runs.
    benchmark::RegisterBenchmark(("BM_first_frame/" + name + "/arap").c_str(), BM_arap_first_frame, model)
        ->ArgName("handles")->Arg(mpm_bench::bench_handles)->Unit(benchmark::kMillisecond)->Iterations(2);
    benchmark::RegisterBenchmark(("BM_frame/" + name + "/arap").c_str(), BM_arap_frame, model)
        ->ArgName("handles")->Arg(mpm_bench::bench_handles)->Unit(benchmark::kMillisecond)->Iterations(5);
  }
  return true;
}();

} // namespace
