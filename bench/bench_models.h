// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Models and handle sets shared by the benchmarks: built once per program
// run, since making a 66k-vertex model costs more than many measured runs.
#ifndef CGAL_MPM_BENCH_MODELS_H
#define CGAL_MPM_BENCH_MODELS_H

#include <CGAL/MPM/Handle_set.h>
#include <CGAL/MPM/Synthetic_model.h>

#include <map>
#include <utility>

namespace mpm_bench {

/// The paper's yardsticks (Table 6.1): a 23k-vertex hand and a 66k-vertex
/// scorpion, for which the synthetic spider stands in.
enum class Bench_model { hand_23k, spider_66k };

/// Seed of the held-out pose all benchmark handles pull towards.
constexpr unsigned bench_pose_seed = 101;

inline const CGAL::MPM::Synthetic_model& synthetic_model(Bench_model which)
{
  // Benchmarks run one at a time, so the caches need no lock.
  static std::map<Bench_model, CGAL::MPM::Synthetic_model> cache;
  auto found = cache.find(which);
  if(found == cache.end()) {
    CGAL::MPM::Synthetic_options options;
    options.vertices = which == Bench_model::hand_23k ? 23000 : 66000;
    const auto family =
        which == Bench_model::hand_23k ? CGAL::MPM::Synthetic_family::hand : CGAL::MPM::Synthetic_family::spider;
    found = cache.emplace(which, CGAL::MPM::make_synthetic_model(family, options)).first;
  }
  return found->second;
}

inline const CGAL::MPM::Point_matrix& held_out_pose(Bench_model which)
{
  static std::map<Bench_model, CGAL::MPM::Point_matrix> cache;
  auto found = cache.find(which);
  if(found == cache.end()) found = cache.emplace(which, synthetic_model(which).draw_pose(bench_pose_seed)).first;
  return found->second;
}

/// `count` farthest-point handles targeted at the held-out pose.
inline const CGAL::MPM::Handle_set& farthest_handles(Bench_model which, int count)
{
  static std::map<std::pair<Bench_model, int>, CGAL::MPM::Handle_set> cache;
  const auto key = std::make_pair(which, count);
  auto found = cache.find(key);
  if(found == cache.end())
    found = cache.emplace(key, CGAL::MPM::farthest_point_handles(synthetic_model(which).mesh.mesh, count,
                                                                  held_out_pose(which))).first;
  return found->second;
}

} // namespace mpm_bench

#endif
