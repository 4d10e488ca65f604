// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Models, learned models, deformation problems and handle sets shared by the
// benchmarks: built once per program run, since making and learning a
// 66k-vertex model costs more than many measured runs.
#ifndef CGAL_MPM_BENCH_MODELS_H
#define CGAL_MPM_BENCH_MODELS_H

#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_problem.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <cstdlib>
#include <exception>
#if defined(__GLIBC__) || defined(__linux__)
#include <malloc.h>
#endif
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>
#include <unistd.h>

namespace mpm_bench {

/// The paper's yardsticks (Table 6.1): a 23k-vertex hand and a 66k-vertex
/// scorpion, for which the synthetic spider stands in; plus a 3k-vertex hand
/// small enough for the direct (reference) global step. And real meshes from
/// CGAL's data (Debian's libcgal-demo: diplodocus 24k, armadillo 26k, refined
/// elephant 44k vertices), each learned as one part: no shape modes, pure
/// elastic MPM, the fair speed comparison with ARAP. And segmented scans
/// from the Princeton Segmentation Benchmark (`../shared/data/psb`): a hand
/// and an octopus with a person's segmentation, part types proposed,
/// learned and stitched into one surface, as users bring them.
enum class Bench_model {
  hand_3k, spine_16k, hand_23k, spider_66k, diplodocus, armadillo, refined_elephant, psb_hand_181, psb_octopus_124
};

/// The synthetic models.
inline std::vector<Bench_model> synthetic_models()
{
  return {Bench_model::hand_3k, Bench_model::spine_16k, Bench_model::hand_23k, Bench_model::spider_66k};
}

/// Whether the model is a real mesh read from `data_directory()`.
inline bool is_real_mesh(Bench_model which)
{
  return which == Bench_model::diplodocus || which == Bench_model::armadillo || which == Bench_model::refined_elephant;
}

/// Whether the model is a segmented scan read from `psb_directory()`.
inline bool is_segmented_scan(Bench_model which)
{
  return which == Bench_model::psb_hand_181 || which == Bench_model::psb_octopus_124;
}

/// The model's name in benchmark names (`BM_iteration/hand_23k/...`); for a
/// real mesh also its file name without `.off`.
inline const char* model_name(Bench_model which)
{
  switch(which) {
  case Bench_model::hand_3k: return "hand_3k";
  case Bench_model::spine_16k: return "spine_16k";
  case Bench_model::hand_23k: return "hand_23k";
  case Bench_model::spider_66k: return "spider_66k";
  case Bench_model::diplodocus: return "diplodocus";
  case Bench_model::armadillo: return "armadillo";
  case Bench_model::psb_hand_181: return "psb_hand_181";
  case Bench_model::psb_octopus_124: return "psb_octopus_124";
  default: return "refined_elephant";
  }
}

/// Where the real meshes are: `$MPM_DATA_DIR`, else `data/` in the build
/// directory (next to `bench/`, where `bench/run_benchmarks.sh` extracts
/// them from `/usr/share/doc/libcgal-dev/data.tar.gz`).
inline std::string data_directory()
{
  if(const char* dir = std::getenv("MPM_DATA_DIR"); dir && *dir) return dir;
  char exe[4096];
  const ssize_t size = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
  if(size <= 0) return "data";
  std::string path(exe, std::size_t(size)); // <build>/bench/mpm_bench
  for(int up = 0; up < 2 && path.find('/') != std::string::npos; ++up) path.erase(path.rfind('/'));
  return path + "/data";
}

inline std::string real_mesh_path(Bench_model which) { return data_directory() + "/" + model_name(which) + ".off"; }

/// Where the segmented scans are: `$MPM_PSB_DIR`, else `../shared/data/psb`
/// beside the source tree, as CI lays it out.
inline std::string psb_directory()
{
  if(const char* dir = std::getenv("MPM_PSB_DIR"); dir && *dir) return dir;
  return MPM_BENCH_PSB_DIR;
}

/// A segmented scan's file without extension (`.../hand_181`).
inline std::string psb_path(Bench_model which) { return psb_directory() + "/" + (model_name(which) + 4); }

/// The real meshes whose files exist; says once on stderr which are skipped.
inline std::vector<Bench_model> available_real_meshes()
{
  static const std::vector<Bench_model> available = [] {
    std::vector<Bench_model> found;
    for(Bench_model m : {Bench_model::diplodocus, Bench_model::armadillo, Bench_model::refined_elephant}) {
      if(std::ifstream(real_mesh_path(m)).good()) found.push_back(m);
      else
        std::cerr << "mpm_bench: " << real_mesh_path(m) << " not found, skipping the " << model_name(m)
                  << " benchmarks (set MPM_DATA_DIR, or let bench/run_benchmarks.sh extract CGAL's data)\n";
    }
    return found;
  }();
  return available;
}

/// The segmented scans whose files exist; says once on stderr when they are not.
inline std::vector<Bench_model> available_segmented_scans()
{
  static const std::vector<Bench_model> available = [] {
    std::vector<Bench_model> found;
    for(Bench_model m : {Bench_model::psb_hand_181, Bench_model::psb_octopus_124}) {
      if(std::ifstream(psb_path(m) + ".off").good() && std::ifstream(psb_path(m) + ".seg").good()) found.push_back(m);
      else
        std::cerr << "mpm_bench: " << psb_path(m) << ".off/.seg not found, skipping the " << model_name(m)
                  << " benchmarks (set MPM_PSB_DIR)\n";
    }
    return found;
  }();
  return available;
}

/// Synthetic models, then the real meshes and segmented scans that are available.
inline std::vector<Bench_model> all_models()
{
  std::vector<Bench_model> models = synthetic_models();
  for(Bench_model m : available_real_meshes()) models.push_back(m);
  for(Bench_model m : available_segmented_scans()) models.push_back(m);
  return models;
}

/// Seed of the held-out pose all benchmark handles pull towards.
constexpr unsigned bench_pose_seed = 101;

/// Number of farthest-point handles of the MPM/ARAP comparisons.
constexpr int bench_handles = 16;

/// The frame benchmarks' drag of the first handle, MPM's and ARAP's alike:
/// 1% of the bounding-box diagonal of `rest` along (1, 1, 1) per frame,
/// times `frame_direction()`.
inline Eigen::RowVector3d frame_drag(const CGAL::MPM::Point_matrix& rest)
{
  const double diagonal = CGAL::MPM::internal::bounding_box_diagonal(rest);
  return 0.01 * diagonal * Eigen::RowVector3d(1., 1., 1.).normalized();
}

/// Back and forth every 10 frames (`frame` from 0).
inline double frame_direction(int frame) { return (frame / 10) % 2 == 0 ? 1. : -1.; }

inline const CGAL::MPM::Synthetic_model& synthetic_model(Bench_model which)
{
  // Benchmarks run one at a time, so the caches need no lock.
  static std::map<Bench_model, CGAL::MPM::Synthetic_model> cache;
  auto found = cache.find(which);
  if(found == cache.end()) {
    CGAL::MPM::Synthetic_options options;
    options.vertices = which == Bench_model::hand_3k     ? 3000
                       : which == Bench_model::spine_16k ? 16000
                       : which == Bench_model::hand_23k  ? 23000
                                                         : 66000;
    const auto family = which == Bench_model::spider_66k  ? CGAL::MPM::Synthetic_family::spider
                        : which == Bench_model::spine_16k ? CGAL::MPM::Synthetic_family::spine
                                                          : CGAL::MPM::Synthetic_family::hand;
    found = cache.emplace(which, CGAL::MPM::make_synthetic_model(family, options)).first;
  }
  return found->second;
}

inline const CGAL::MPM::Morphable_part_model& learned_model(Bench_model which);

/// The labelled mesh a model is learned from: the synthetic model's, a real
/// mesh read from `real_mesh_path()` with every face labelled 0 (one part),
/// or a segmented scan with its segmentation. Throws `Input_error` when a
/// file cannot be read.
inline const CGAL::MPM::Labeled_mesh& training_mesh(Bench_model which)
{
  if(is_segmented_scan(which)) {
    static std::map<Bench_model, CGAL::MPM::Labeled_mesh> scans;
    auto found = scans.find(which);
    if(found == scans.end())
      found = scans.emplace(which, CGAL::MPM::read_labeled_mesh(psb_path(which) + ".off", psb_path(which) + ".seg")).first;
    return found->second;
  }
  if(!is_real_mesh(which)) return synthetic_model(which).mesh;
  static std::map<Bench_model, CGAL::MPM::Labeled_mesh> cache;
  auto found = cache.find(which);
  if(found == cache.end()) {
    CGAL::MPM::Labeled_mesh labeled;
    labeled.source = real_mesh_path(which);
    labeled.mesh = CGAL::MPM::read_mesh_file(labeled.source).mesh;
    labeled.face_labels.assign(labeled.mesh.triangles.size(), 0);
    found = cache.emplace(which, std::move(labeled)).first;
  }
  return found->second;
}

/// The mesh the edits work on: the training mesh, except for a segmented
/// scan, whose learned example is its stitched surface (the corresponded
/// parts rebuilt with their types' connectivity).
inline const CGAL::MPM::Labeled_mesh& bench_mesh(Bench_model which)
{
  if(!is_segmented_scan(which)) return training_mesh(which);
  static std::map<Bench_model, CGAL::MPM::Labeled_mesh> cache;
  auto found = cache.find(which);
  if(found == cache.end()) {
    const CGAL::MPM::Training_example& example = learned_model(which).examples.front();
    found = cache.emplace(which, CGAL::MPM::to_labeled_mesh(example)).first;
  }
  return found->second;
}

/// Annotation of a model: the synthetic model's, the proposed part types of
/// a segmented scan, or none (one part, default parameters).
inline const CGAL::MPM::Annotation& bench_annotation(Bench_model which)
{
  static const CGAL::MPM::Annotation none;
  if(is_segmented_scan(which)) {
    static std::map<Bench_model, CGAL::MPM::Annotation> proposed;
    auto found = proposed.find(which);
    if(found == proposed.end())
      found = proposed.emplace(which, CGAL::MPM::propose_part_types(training_mesh(which)).annotation).first;
    return found->second;
  }
  return is_real_mesh(which) ? none : synthetic_model(which).annotation;
}

/// A smooth displacement of a real mesh: a bend along its longest bounding-box
/// axis, the ends moving by 5% of the bounding-box diagonal along the second
/// longest axis (quadratic in the position along the longest one).
inline CGAL::MPM::Point_matrix bent_pose(const CGAL::MPM::Point_matrix& rest)
{
  const Eigen::RowVector3d low = rest.colwise().minCoeff(), high = rest.colwise().maxCoeff();
  const Eigen::RowVector3d extent = high - low;
  int along = 0;
  extent.maxCoeff(&along);
  const int across = extent((along + 1) % 3) >= extent((along + 2) % 3) ? (along + 1) % 3 : (along + 2) % 3;
  const double amplitude = 0.05 * extent.norm();
  CGAL::MPM::Point_matrix pose = rest;
  for(Eigen::Index v = 0; v < rest.rows(); ++v) {
    const double s = 2. * (rest(v, along) - low(along)) / extent(along) - 1.; // -1 .. 1
    pose(v, across) += amplitude * s * s;
  }
  return pose;
}

/// Where the handles pull to: the synthetic model's held-out pose, or the
/// real mesh bent by `bent_pose()`.
inline const CGAL::MPM::Point_matrix& held_out_pose(Bench_model which)
{
  static std::map<Bench_model, CGAL::MPM::Point_matrix> cache;
  auto found = cache.find(which);
  if(found == cache.end())
    found = cache.emplace(which, is_real_mesh(which) || is_segmented_scan(which) ? bent_pose(bench_mesh(which).mesh.points)
                                                     : synthetic_model(which).draw_pose(bench_pose_seed)).first;
  return found->second;
}

/// `count` farthest-point handles targeted at the held-out pose.
inline const CGAL::MPM::Handle_set& farthest_handles(Bench_model which, int count)
{
  static std::map<std::pair<Bench_model, int>, CGAL::MPM::Handle_set> cache;
  const auto key = std::make_pair(which, count);
  auto found = cache.find(key);
  if(found == cache.end())
    found = cache.emplace(key, CGAL::MPM::farthest_point_handles(bench_mesh(which).mesh, count,
                                                                  held_out_pose(which))).first;
  return found->second;
}

/// The morphable part model learned from the model's mesh (one example).
inline const CGAL::MPM::Morphable_part_model& learned_model(Bench_model which)
{
  static std::map<Bench_model, CGAL::MPM::Morphable_part_model> cache;
  auto found = cache.find(which);
  if(found == cache.end())
    found = cache.emplace(which, CGAL::MPM::learn_morphable_part_model(training_mesh(which), bench_annotation(which))).first;
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

/// Runs `build` (reading, learning: the cached fixtures of a benchmark) and
/// returns the message of what it threw, or an empty string.
template <class Build>
std::string prepare(Build build)
{
  try {
    build();
    return {};
  } catch(const std::exception& e) {
    return e.what();
  }
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
