// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The long run: many random drags of random handles on the synthetic spider
// with the fast solver (Global_step::reduced). Each drag picks 1-4 handle
// vertices (a new set every --reset drags, which exercises the handle-set
// update) and random targets within --offset of the bounding-box diagonal
// from their rest positions, runs solve() with --iterations iterations and
// checks that the positions and the energy are finite. Every --report drags
// it prints the drags done, the mean time per drag and the resident memory
// (VmRSS). Per-drag energies go to --csv when given. Exit code 1 on any
// non-finite value or exception.
#include "quality_common.h"

#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_problem.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace {

const char* const usage =
  "Usage: long_run_drags [--vertices N] [--drags N] [--reset N] [--iterations N] [--offset F]\n"
  "                      [--report N] [--seed S] [--csv FILE]\n"
  "Defaults: --vertices 66000 --drags 10000 --reset 50 --iterations 10 --offset 0.02\n"
  "          --report 500 --seed 1 (energies per drag to --csv when given).\n";

using namespace CGAL::MPM;

// Resident set size in kB from /proc/self/status (-1 when unavailable).
long vm_rss_kb()
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

} // namespace

int main(int argc, char** argv)
{
  const mpm_quality::Options options(argc, argv,
                                     {{"vertices", "66000"},
                                      {"drags", "10000"},
                                      {"reset", "50"},
                                      {"iterations", "10"},
                                      {"offset", "0.02"},
                                      {"report", "500"},
                                      {"seed", "1"},
                                      {"csv", ""}},
                                     usage);
  using Clock = std::chrono::steady_clock;
  try {
    const auto t0 = Clock::now();
    Synthetic_options so;
    so.vertices = options.integer("vertices");
    const Synthetic_model spider = make_synthetic_model(Synthetic_family::spider, so);
    const Morphable_part_model model = learn_morphable_part_model(spider.mesh, spider.annotation);
    const Embedding_problem problem = make_deformation_problem(model);
    Embedding_options eo;
    eo.global_step = Global_step::reduced;
    eo.max_iterations = options.integer("iterations");
    Embedding_solver solver(problem, eo);
    const Point_matrix& rest = problem.mesh.points;
    const int n = int(rest.rows());
    const double diagonal = internal::bounding_box_diagonal(rest);
    const double max_offset = std::stod(options.text("offset")) * diagonal;
    const auto t1 = Clock::now();
    const long rss_start = vm_rss_kb();
    std::cout << "spider: " << n << " vertices, " << problem.clusters.size() << " clusters; setup "
              << std::chrono::duration<double>(t1 - t0).count() << " s; VmRSS at start " << rss_start << " kB"
              << std::endl;

    std::ofstream csv;
    if(!options.text("csv").empty()) {
      csv.open(options.text("csv"));
      csv << "drag,handles,new_set,energy,iterations,ms\n";
    }
    const int drags = options.integer("drags"), reset = std::max(1, options.integer("reset")),
              report = std::max(1, options.integer("report"));
    std::mt19937 rng(unsigned(options.integer("seed")));
    std::uniform_int_distribution<int> count_dist(1, 4), vertex_dist(0, n - 1);
    std::uniform_real_distribution<double> unit(-1., 1.);
    std::vector<int> handles;
    double window_ms = 0., total_ms = 0., energy_min = 1e300, energy_max = -1e300, energy_sum = 0.;
    int window = 0;
    for(int d = 0; d < drags; ++d) {
      const bool new_set = d % reset == 0;
      if(new_set) {
        const int k = count_dist(rng);
        handles.clear();
        while(int(handles.size()) < k) {
          const int v = vertex_dist(rng);
          if(std::find(handles.begin(), handles.end(), v) == handles.end()) handles.push_back(v);
        }
      }
      Point_matrix targets(Eigen::Index(handles.size()), 3);
      for(std::size_t h = 0; h < handles.size(); ++h) {
        Eigen::RowVector3d offset;
        do offset = Eigen::RowVector3d(unit(rng), unit(rng), unit(rng));
        while(offset.squaredNorm() > 1.);
        targets.row(Eigen::Index(h)) = rest.row(handles[h]) + max_offset * offset;
      }
      const auto s0 = Clock::now();
      solver.set_handles(handles, targets);
      const Solve_report r = solver.solve();
      const Point_matrix& p = solver.positions();
      const double energy = solver.energy();
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - s0).count();
      if(!p.allFinite() || !std::isfinite(energy) || !std::isfinite(r.energy())) {
        std::cerr << "drag " << d << ": non-finite " << (p.allFinite() ? "energy" : "positions")
                  << " (handles " << handles.size() << ", energy " << energy << ")\n";
        return 1;
      }
      window_ms += ms;
      total_ms += ms;
      ++window;
      energy_min = std::min(energy_min, energy);
      energy_max = std::max(energy_max, energy);
      energy_sum += energy;
      if(csv.is_open())
        csv << d << ',' << handles.size() << ',' << int(new_set) << ',' << energy << ',' << r.iterations << ','
            << ms << '\n';
      if((d + 1) % report == 0 || d + 1 == drags) {
        std::cout << "drags " << d + 1 << ": mean " << window_ms / window << " ms/drag (last " << window
                  << "), energy " << energy << ", VmRSS " << vm_rss_kb() << " kB" << std::endl;
        window_ms = 0.;
        window = 0;
      }
    }
    std::cout << "done: " << drags << " drags, mean " << (drags > 0 ? total_ms / drags : 0.)
              << " ms/drag; energy min " << energy_min << " mean " << (drags > 0 ? energy_sum / drags : 0.)
              << " max " << energy_max << "; VmRSS start " << rss_start << " kB, end " << vm_rss_kb() << " kB"
              << std::endl;
  } catch(const std::exception& e) {
    std::cerr << "long_run_drags: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
