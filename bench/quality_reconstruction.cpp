// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sparse-handle reconstruction: for every synthetic family, learn the model
// from its training mesh, draw held-out poses, give every method the
// farthest-point handles of the pose (2 to 32 of them, and one per part),
// and measure how well it reconstructs the pose:
//   rms_error, max_error  vertex error relative to the pose's bounding-box diagonal;
//   detail_error          RMS change of the cotangent-Laplacian coordinates
//                         (Laplacian of the rest mesh) relative to the pose's
//                         own: |L V - L T|_rms / |L T|_rms;
//   handle_rms            handle residual relative to the diagonal.
// The row method=rest is the undeformed training mesh. CSV on stdout or --csv.
#include "quality_common.h"

#include <CGAL/MPM/Baselines/Deformation_method.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Editing/Laplacian_editing.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>

namespace {

const char* const usage =
  "Usage: quality_reconstruction [--vertices N] [--poses P] [--counts LIST] [--per-part yes|no]\n"
  "                              [--methods LIST] [--families LIST|all] [--arap-iterations N] [--csv FILE]\n"
  "Defaults: --vertices 3000 --poses 3 --counts 2,4,8,16,32 --per-part yes --methods all --families all\n"
  "          --arap-iterations 1000. Pose seeds are 101 .. 100+P.\n";

using namespace CGAL::MPM;

} // namespace

int main(int argc, char** argv)
{
  const mpm_quality::Options options(argc, argv,
                                     {{"vertices", "3000"},
                                      {"poses", "3"},
                                      {"counts", "2,4,8,16,32"},
                                      {"per-part", "yes"},
                                      {"methods", "all"},
                                      {"families", "all"},
                                      {"arap-iterations", "1000"},
                                      {"csv", ""}},
                                     usage);
  const std::vector<std::string> methods =
    options.text("methods") == "all" ? deformation_method_names() : options.list("methods");
  Deformation_method_options method_options;
  method_options.arap_max_iterations = options.integer("arap-iterations");
  mpm_quality::Csv_output csv(options.text("csv"));
  std::ostream& out = csv.stream();
  out << "family,vertices,pose_seed,handles,handle_count,method,rms_error,max_error,detail_error,handle_rms,time_ms,"
         "iterations\n";
  out.flush();
  using Clock = std::chrono::steady_clock;
  int failures = 0;

  for(const Synthetic_family family : options.families())
  {
    Synthetic_options so;
    so.vertices = options.integer("vertices");
    const Synthetic_model truth = make_synthetic_model(family, so);
    const Morphable_part_model model = learn_morphable_part_model(truth.mesh, truth.annotation);
    const Indexed_mesh mesh = to_labeled_mesh(model.examples[0]).mesh;
    const Eigen::SparseMatrix<double> laplacian = cotangent_laplacian(mesh);
    const std::string name = family_name(family);
    std::cerr << name << ": " << mesh.number_of_vertices() << " vertices\n";

    for(int p = 0; p < options.integer("poses"); ++p)
    {
      const unsigned seed = 101u + unsigned(p);
      const Point_matrix pose = truth.draw_pose(seed);
      const double d = internal::bounding_box_diagonal(pose);
      const Point_matrix pose_details = laplacian * pose;
      const double detail_scale = std::sqrt(pose_details.rowwise().squaredNorm().mean());

      std::vector<std::pair<std::string, Handle_set>> handle_sets;
      for(int count : options.integers("counts"))
        handle_sets.emplace_back(std::to_string(count), farthest_point_handles(mesh, count, pose));
      if(options.text("per-part") == "yes") handle_sets.emplace_back("per-part", handles_per_part(truth.mesh, 1, pose));

      for(const auto& [label, handles] : handle_sets)
      {
        auto row = [&](const std::string& method, const Point_matrix& result, double ms, int iterations) {
          const Eigen::VectorXd error = (result - pose).rowwise().norm();
          const Point_matrix details = laplacian * result - pose_details;
          out << name << ',' << mesh.number_of_vertices() << ',' << seed << ',' << label << ',' << handles.size()
              << ',' << method << ',' << mpm_quality::number(std::sqrt(error.squaredNorm() / double(error.size())) / d)
              << ',' << mpm_quality::number(error.maxCoeff() / d) << ','
              << mpm_quality::number(std::sqrt(details.rowwise().squaredNorm().mean()) / detail_scale) << ','
              << mpm_quality::number(handle_rms_residual(result, handles) / d) << ',' << mpm_quality::number(ms)
              << ',' << iterations << '\n';
          out.flush();
        };
        row("rest", mesh.points, 0., -1);
        for(const std::string& method : methods)
        {
          std::cerr << "  pose " << seed << ", handles " << label << ", " << method << "\n";
          try
          {
            const Clock::time_point start = Clock::now();
            auto m = make_deformation_method(method, model, 0, method_options);
            m->set_handles(handles);
            const Point_matrix result = m->deform();
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            row(method, result, ms, m->iterations());
          }
          catch(const std::exception& e)
          {
            ++failures;
            std::cerr << "error: " << name << ", pose " << seed << ", handles " << label << ", " << method << ": "
                      << e.what() << "\n";
            const double nan = std::numeric_limits<double>::quiet_NaN();
            row(method, Point_matrix::Constant(mesh.points.rows(), 3, nan), nan, -1);
          }
        }
      }
    }
  }
  return failures == 0 ? 0 : 1;
}
