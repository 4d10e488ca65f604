// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm compare MODEL --handles H.json`: runs MPM and its baselines (ARAP,
// ARAP-SRE, linear Laplacian editing, thin-plate splines, the shape-space
// fit alone) on a training example with the same handles, writes each
// method's mesh and prints their times, handle residuals and, against a
// known pose, their errors.
#include "cli.h"

#include <CGAL/MPM/Baselines/Deformation_method.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <chrono>
#include <climits>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace mpm {

namespace {

using Clock = std::chrono::steady_clock;

std::vector<std::string> parse_methods(const std::string& text)
{
  const std::vector<std::string> known = CGAL::MPM::deformation_method_names();
  std::vector<std::string> methods;
  std::stringstream s(text);
  for(std::string item; std::getline(s, item, ',');)
  {
    if(item.empty()) continue;
    if(std::find(known.begin(), known.end(), item) == known.end())
    {
      std::string valid;
      for(const std::string& n : known) valid += (valid.empty() ? "" : ",") + n;
      throw Usage_error("option --methods: unknown method '" + item + "' (valid: " + valid + ")");
    }
    if(std::find(methods.begin(), methods.end(), item) != methods.end())
      throw Usage_error("option --methods: '" + item + "' is listed twice");
    methods.push_back(item);
  }
  if(methods.empty()) throw Usage_error("option --methods: no method given");
  return methods;
}

int run_compare(const Args& args, Context& context)
{
  using namespace CGAL::MPM;
  const std::string model_path = args.positionals().front();
  if(!args.has("handles")) throw Usage_error("'mpm compare' needs --handles H.json");
  const std::vector<std::string> methods =
    parse_methods(args.text("methods", "mpm,arap,arap-sre,laplacian,tps,pca"));
  const std::string directory = args.text("output");
  const int example = static_cast<int>(args.integer("example", 0));
  Deformation_method_options options;
  options.arap_max_iterations = static_cast<int>(args.integer("arap-iterations", options.arap_max_iterations));

  context.progress.update("loading " + model_path, 0.);
  const Morphable_part_model model = load_model(model_path);
  if(example >= static_cast<int>(model.examples.size()))
    throw Input_error(model_path, "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " example" +
                        (model.examples.size() == 1 ? "" : "s") + ")");
  const Indexed_mesh mesh = to_labeled_mesh(model.examples[std::size_t(example)]).mesh;
  const std::string handles_file = args.text("handles");
  const Handle_set handles = read_handles(handles_file, mesh.points);

  const std::string truth_file = args.text("truth");
  Point_matrix truth;
  if(!truth_file.empty())
  {
    truth = read_mesh_file(truth_file).mesh.points;
    if(truth.rows() != mesh.points.rows())
      throw Input_error(truth_file, "", "has " + std::to_string(truth.rows()) + " vertices, example " +
                                          std::to_string(example) + " of the model has " +
                                          std::to_string(mesh.points.rows()));
  }
  const double d = CGAL::MPM::internal::bounding_box_diagonal(mesh.points);
  const double truth_d = CGAL::MPM::internal::bounding_box_diagonal(truth);

  Json rows = Json::array();
  for(std::size_t m = 0; m < methods.size(); ++m)
  {
    const std::string& name = methods[m];
    const double from = 0.05 + 0.9 * double(m) / double(methods.size()), to = from + 0.9 / double(methods.size());
    context.progress.update("running " + name, from);
    // The iterative methods advance within their share as they approach their cap.
    Deformation_method_options method_options = options;
    const int cap = name == "mpm" ? options.mpm.max_iterations : options.arap_max_iterations;
    const std::function<void(int, double)> advance = iteration_progress(context.progress, "running " + name, from, to, cap);
    method_options.iteration_callback = [advance](int iteration) { advance(iteration, 0.); };
    const Clock::time_point start = Clock::now();
    auto method = make_deformation_method(name, model, example, method_options);
    method->set_handles(handles);
    const Point_matrix result = method->deform();
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if(!result.allFinite()) throw Computation_error("method " + name + " produced non-finite positions");
    Json row = {{"method", name},
                {"time_ms", ms},
                {"iterations", method->iterations() >= 0 ? Json(method->iterations()) : Json(nullptr)},
                {"handle_rms", d > 0 ? handle_rms_residual(result, handles) / d : 0.}};
    if(truth.rows() > 0)
    {
      const Eigen::VectorXd error = (result - truth).rowwise().norm();
      row["rms_error"] = std::sqrt(error.squaredNorm() / double(error.size())) / truth_d;
      row["max_error"] = error.maxCoeff() / truth_d;
    }
    if(!directory.empty())
    {
      const std::string path = (std::filesystem::path(directory) / (name + ".ply")).string();
      ensure_parent_directory(path);
      Indexed_mesh out;
      out.points = result;
      out.triangles = mesh.triangles;
      write_mesh_file(out, path, nullptr, context.meshes);
      row["output"] = path;
    }
    rows.push_back(row);
  }
  context.progress.done();

  if(context.json)
  {
    print_json({{"command", "compare"},
                {"model", model_path},
                {"example", example},
                {"vertices", mesh.number_of_vertices()},
                {"handles", handles.size()},
                {"handles_file", handles_file},
                {"truth", truth_file.empty() ? Json(nullptr) : Json(truth_file)},
                {"methods", rows}});
    return exit_ok;
  }
  std::cout << "Compared " << methods.size() << " method" << (methods.size() == 1 ? "" : "s") << " on example "
            << example << " of " << model_path << ": " << mesh.number_of_vertices() << " vertices, "
            << handles.size() << " handles (" << handles_file << ")\n";
  std::vector<std::string> headers = {"method", "time ms", "iterations", "handle RMS"};
  std::vector<bool> numeric = {false, true, true, true};
  if(truth.rows() > 0)
  {
    headers.insert(headers.end(), {"RMS error", "max error"});
    numeric.insert(numeric.end(), {true, true});
  }
  Table table(headers, numeric);
  for(const Json& row : rows)
  {
    std::vector<std::string> cells = {row["method"].get<std::string>(), format_number(row["time_ms"].get<double>(), 4),
                                      row["iterations"].is_null() ? "-" : std::to_string(row["iterations"].get<int>()),
                                      format_number(row["handle_rms"].get<double>(), 3)};
    if(truth.rows() > 0)
    {
      cells.push_back(format_number(row["rms_error"].get<double>(), 3));
      cells.push_back(format_number(row["max_error"].get<double>(), 3));
    }
    table.add_row(cells);
  }
  table.print(std::cout);
  std::cout << "  (handle RMS and errors are fractions of the bounding-box diagonal"
            << (truth.rows() > 0 ? "; errors against " + truth_file : std::string()) << ")\n";
  if(!directory.empty()) std::cout << "Wrote " << methods.size() << " meshes to " << directory << "\n";
  return exit_ok;
}

} // namespace

Command make_compare_command()
{
  Command c;
  c.name = "compare";
  c.summary = "run MPM and the baseline deformations with the same handles, side by side";
  c.synopsis = "MODEL --handles H.json [--methods LIST] [-o DIR] [--truth POSE.off] [--example N]";
  c.operand = "MODEL";
  c.description =
    "Runs each method on training example --example of MODEL with the same handles:\n"
    "mpm (the embedding solver on the free-form deformation problem), arap and\n"
    "arap-sre (CGAL's Surface_mesh_deformation), laplacian (linear Laplacian\n"
    "editing), tps (thin-plate-spline space deformation) and pca (each part's\n"
    "shape space fitted to its handles, without elastic coupling). Prints each\n"
    "method's time (set-up and solve), iterations and handle RMS residual; with\n"
    "--truth (a mesh with the example's vertices, e.g. from 'mpm synth FAMILY\n"
    "--pose-seed N') also the RMS and maximum vertex error. Residuals and errors\n"
    "are fractions of the bounding-box diagonal. With -o DIR, writes DIR/METHOD.ply.";
  c.min_positionals = c.max_positionals = 1;
  c.options = {
    {"handles", 0, Value_kind::input_file, "H.json", "", "handle file (required)"},
    {"methods", 0, Value_kind::text, "LIST", "mpm,arap,arap-sre,laplacian,tps,pca", "comma-separated methods to run"},
    {"output", 'o', Value_kind::output_prefix, "DIR", "none", "directory for the meshes (METHOD.ply)"},
    {"truth", 0, Value_kind::input_file, "POSE", "none", "mesh of the true pose (same vertices) to measure errors against"},
    {"example", 0, Value_kind::integer, "N", "0", "training example to deform", 0, INT_MAX},
    {"arap-iterations", 0, Value_kind::integer, "N", "1000", "iteration cap of ARAP", 1, INT_MAX},
  };
  c.run = run_compare;
  return c;
}

} // namespace mpm
