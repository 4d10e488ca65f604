// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Models, learned models, deformation problems and handle sets shared by the
// benchmarks: built once per program run, since making and learning a
// 66k-vertex model costs more than many measured runs.
#ifndef CGAL_MPM_BENCH_MODELS_H
#define CGAL_MPM_BENCH_MODELS_H

#include <CGAL/MPM/Editing.h>
#include <CGAL/MPM/Embedding_problem.h>
#include <CGAL/MPM/Handle_set.h>
#include <CGAL/MPM/Morphable_part_model.h>
#include <CGAL/MPM/Synthetic_model.h>
#include <CGAL/MPM/learn_morphable_part_model.h>

#include <cstdlib>
#if defined(__GLIBC__) || defined(__linux__)
#include <malloc.h>
#endif
#include <fstream>
#include <map>
#include <string>
#include <utility>

namespace mpm_bench {

/// The paper's yardsticks (Table 6.1): a 23k-vertex hand and a 66k-vertex
/// scorpion, for which the synthetic spider stands in; plus a 3k-vertex hand
/// small enough for the direct (reference) global step.
enum class Bench_model { hand_3k, hand_23k, spider_66k };

/// The model's name in benchmark names (`BM_iteration/hand_23k/...`).
inline const char* model_name(Bench_model which)
{
  switch(which) {
  case Bench_model::hand_3k: return "hand_3k";
  case Bench_model::hand_23k: return "hand_23k";
  default: return "spider_66k";
  }
}

/// Seed of the held-out pose all benchmark handles pull towards.
constexpr unsigned bench_pose_seed = 101;

/// Number of farthest-point handles of the MPM/ARAP comparisons.
constexpr int bench_handles = 16;

inline const CGAL::MPM::Synthetic_model& synthetic_model(Bench_model which)
{
  // Benchmarks run one at a time, so the caches need no lock.
  static std::map<Bench_model, CGAL::MPM::Synthetic_model> cache;
  auto found = cache.find(which);
  if(found == cache.end()) {
    CGAL::MPM::Synthetic_options options;
    options.vertices = which == Bench_model::hand_3k ? 3000 : which == Bench_model::hand_23k ? 23000 : 66000;
    const auto family =
        which == Bench_model::spider_66k ? CGAL::MPM::Synthetic_family::spider : CGAL::MPM::Synthetic_family::hand;
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

/// The morphable part model learned from the synthetic model (one example).
inline const CGAL::MPM::Morphable_part_model& learned_model(Bench_model which)
{
  static std::map<Bench_model, CGAL::MPM::Morphable_part_model> cache;
  auto found = cache.find(which);
  if(found == cache.end()) {
    const CGAL::MPM::Synthetic_model& s = synthetic_model(which);
    found = cache.emplace(which, CGAL::MPM::learn_morphable_part_model(s.mesh, s.annotation)).first;
  }
  return found->second;
}

/// Free-form deformation problem of the learned model's example 0.
inline const CGAL::MPM::Embedding_problem& deformation_problem(Bench_model which)
{
  static std::map<Bench_model, CGAL::MPM::Embedding_problem> cache;
  auto found = cache.find(which);
  if(found == cache.end())
    found = cache.emplace(which, CGAL::MPM::make_deformation_problem(learned_model(which))).first;
  return found->second;
}

/// Total number of shape modes over the problem's clusters.
inline int number_of_modes(const CGAL::MPM::Embedding_problem& problem)
{
  int modes = 0;
  for(const CGAL::MPM::Cluster& c : problem.clusters) modes += static_cast<int>(c.modes.cols());
  return modes;
}

/// Peak resident memory of one benchmark, from /proc/self/status: the
/// constructor resets the process's high-water mark (`/proc/self/clear_refs`,
/// Linux) and notes the resident size; `extra_peak_mb()` is the peak since
/// then above that size (so cached fixtures built before do not count), or
/// a negative value when the mark cannot be reset or read.
class Memory_probe
{
public:
  Memory_probe()
  {
#ifdef __GLIBC__
    malloc_trim(0); // hand memory freed by earlier benchmarks back, so reuse does not hide growth
#endif
    std::ofstream("/proc/self/clear_refs") << "5";
    start_kb_ = status_kb("VmRSS:");
    // The reset worked if the high-water mark came down to the resident size.
    valid_ = start_kb_ > 0 && status_kb("VmHWM:") <= start_kb_ + 1024;
  }
  double extra_peak_mb() const { return valid_ ? (status_kb("VmHWM:") - start_kb_) / 1024. : -1.; }

  static double status_kb(const char* key)
  {
    std::ifstream status("/proc/self/status");
    const std::string prefix(key);
    for(std::string line; std::getline(status, line);)
      if(line.compare(0, prefix.size(), prefix) == 0) return std::strtod(line.c_str() + prefix.size(), nullptr);
    return -1.;
  }

private:
  double start_kb_ = -1.;
  bool valid_ = false;
};

} // namespace mpm_bench

#endif
