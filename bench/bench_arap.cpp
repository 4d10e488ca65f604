// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The ARAP baseline (CGAL::Surface_mesh_deformation): time of one
// local/global iteration and of the factorization, on the paper-scale models
// with handles pulling towards a held-out pose. The last argument is the
// number of farthest-point handles. Names match bench_mpm.cpp, so rows read
// side by side: BM_iteration/hand_23k/arap/handles:16 next to
// BM_iteration/hand_23k/mpm_schur_ldlt/handles:16.
#include "bench_models.h"

#include <CGAL/MPM/Arap_deformation.h>

#include <benchmark/benchmark.h>

#include <exception>
#include <string>

namespace {

using CGAL::MPM::Arap_deformation;
using mpm_bench::Bench_model;

void set_counters(benchmark::State& state, Bench_model model, const mpm_bench::Memory_probe& memory)
{
  state.counters["vertices"] = mpm_bench::bench_mesh(model).mesh.number_of_vertices();
  if(memory.extra_peak_mb() >= 0.) state.counters["peak_MB"] = memory.extra_peak_mb();
}

void BM_arap_iteration(benchmark::State& state, Bench_model model)
{
  if(const std::string error = mpm_bench::prepare([&] { mpm_bench::farthest_handles(model, int(state.range(0))); });
     !error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
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
  set_counters(state, model, memory);
}

void BM_arap_preprocess(benchmark::State& state, Bench_model model)
{
  if(const std::string error = mpm_bench::prepare([&] { mpm_bench::farthest_handles(model, int(state.range(0))); });
     !error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
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
  set_counters(state, model, memory);
}

const bool registered = [] {
  for(Bench_model model : mpm_bench::all_models()) {
    const std::string name = mpm_bench::model_name(model);
    auto* iteration = benchmark::RegisterBenchmark(("BM_iteration/" + name + "/arap").c_str(), BM_arap_iteration, model)
                          ->ArgName("handles")->Unit(benchmark::kMillisecond);
    if(model == Bench_model::hand_23k || model == Bench_model::spider_66k) iteration->Arg(1);
    iteration->Arg(mpm_bench::bench_handles);
    benchmark::RegisterBenchmark(("BM_factor/" + name + "/arap").c_str(), BM_arap_preprocess, model)
        ->ArgName("handles")->Arg(mpm_bench::bench_handles)->Unit(benchmark::kMillisecond);
  }
  return true;
}();

} // namespace
