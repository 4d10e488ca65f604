// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The ARAP baseline (CGAL::Surface_mesh_deformation): time of one
// local/global iteration and of the factorization, on the paper-scale models
// with handles pulling towards a held-out pose. The second argument is the
// number of farthest-point handles.
#include "bench_models.h"

#include <CGAL/MPM/Arap_deformation.h>

#include <benchmark/benchmark.h>

namespace {

using CGAL::MPM::Arap_deformation;
using mpm_bench::Bench_model;

void set_vertex_counter(benchmark::State& state, Bench_model model)
{
  state.counters["vertices"] = mpm_bench::synthetic_model(model).mesh.mesh.number_of_vertices();
}

void BM_arap_iteration(benchmark::State& state, Bench_model model)
{
  Arap_deformation arap(mpm_bench::synthetic_model(model).mesh.mesh);
  arap.set_handles(mpm_bench::farthest_handles(model, int(state.range(0))));
  arap.preprocess();
  for(auto _ : state) arap.deform_one_iteration();
  set_vertex_counter(state, model);
}

void BM_arap_preprocess(benchmark::State& state, Bench_model model)
{
  for(auto _ : state) {
    state.PauseTiming();
    // A fresh object each time: a factorization is cached until the handle vertices change.
    Arap_deformation arap(mpm_bench::synthetic_model(model).mesh.mesh);
    arap.set_handles(mpm_bench::farthest_handles(model, int(state.range(0))));
    state.ResumeTiming();
    arap.preprocess();
  }
  set_vertex_counter(state, model);
}

} // namespace

BENCHMARK_CAPTURE(BM_arap_iteration, hand_23k, Bench_model::hand_23k)
    ->ArgName("handles")->Arg(1)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_arap_iteration, spider_66k, Bench_model::spider_66k)
    ->ArgName("handles")->Arg(1)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_arap_preprocess, hand_23k, Bench_model::hand_23k)
    ->ArgName("handles")->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_arap_preprocess, spider_66k, Bench_model::spider_66k)
    ->ArgName("handles")->Arg(16)->Unit(benchmark::kMillisecond);
