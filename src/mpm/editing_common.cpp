// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "editing_common.h"

#include <CGAL/MPM/internal/Edit_solving.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Part_colors.h>
#include <CGAL/MPM/internal/Mesh_file_checks.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <iostream>
#include <map>

namespace mpm {

using CGAL::MPM::internal::lower_extension;

namespace {

using Color_matrix = Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>;

Color_matrix part_type_colors(const CGAL::MPM::Training_example& example)
{
  std::map<int, int> type_of_label;
  for(const CGAL::MPM::Part_node& node : example.graph.nodes) type_of_label[node.label] = node.type;
  Color_matrix colors(example.mesh.number_of_faces(), 3);
  const auto labels = example.face_labels();
  Eigen::Index row = 0;
  for(const CGAL::MPM::Example_mesh::Face_index f : example.mesh.faces())
  {
    // A face whose label is no part of the example's graph gets the colour of no known type.
    const auto it = type_of_label.find(labels[f]);
    const CGAL::MPM::Rgb_color c = CGAL::MPM::part_type_color(it == type_of_label.end() ? -1 : it->second);
    colors.row(row++) << c[0], c[1], c[2];
  }
  return colors;
}

const Option_spec& find_spec(const std::vector<Option_spec>& options, const std::string& name)
{
  return *std::find_if(options.begin(), options.end(), [&](const Option_spec& o) { return o.name == name; });
}

// Root mean square vertex displacement relative to the bounding-box
// diagonal of `before`, so that values compare across models.
double relative_rms_displacement(const CGAL::MPM::Point_matrix& before, const CGAL::MPM::Point_matrix& after)
{
  const double diagonal = CGAL::MPM::internal::bounding_box_diagonal(before);
  const double rms = std::sqrt((after - before).rowwise().squaredNorm().mean());
  return diagonal > 0 ? rms / diagonal : rms;
}

std::string setting_text(const Json& value)
{
  return value.is_number() ? format_number(value.get<double>(), 6) : value.dump();
}

void print_text_summary(const Editing_command& editing, const Json& s)
{
  const std::vector<double> energies = s["energies"].get<std::vector<double>>();
  std::cout << editing.done << " example " << s["example"].get<int>() << " ("
            << s["example_name"].get<std::string>() << ") of " << s["model"].get<std::string>() << ": "
            << s["vertices"].get<int>() << " vertices, " << s["faces"].get<int>() << " faces\n";
  std::string options;
  for(const auto& [key, value] : s["options"].items()) options += (options.empty() ? "" : ", ") + key + " " + setting_text(value);
  const int handles = s["handles"].get<int>();
  const int iterations = s["iterations"].get<int>();
  std::cout << "  options           " << options << "\n"
            << "  handles           " << handles;
  if(handles > 0) std::cout << " (" << s["handles_file"].get<std::string>() << ")";
  std::cout << "\n  iterations        " << iterations
            << (s["converged"].get<bool>() ? " (converged)" : " (not converged: iteration cap)") << "\n"
            << "  energy            first " << format_number(energies.front(), 6) << ", last "
            << format_number(energies.back(), 6) << " (" << energies.size() << " values)\n"
            << "  residual energy   " << format_number(s["residual_energy"].get<double>(), 6) << "\n"
            << "  time              set-up " << format_number(s["setup_ms"].get<double>(), 4) << " ms, solve "
            << format_number(s["solve_ms"].get<double>(), 4) << " ms ("
            << format_number(s["ms_per_iteration"].get<double>(), 4) << " ms per iteration)\n"
            << "  inverted faces    " << s["inverted_faces_solved"].get<int>() << " in the solver's result, "
            << s["inverted_faces_written"].get<int>() << " written ("
            << (s["options"]["keep_folds"].get<bool>() ? "--keep-folds"
                                                       : "unfolded in " + format_number(s["unfold_ms"].get<double>(), 3) + " ms")
            << ")\n"
            << "  rms displacement  " << format_number(s["rms_displacement"].get<double>(), 4)
            << " of the bounding-box diagonal\n"
            << "Wrote " << s["output"].get<std::string>() << "\n";
}

int run_editing(const Editing_command& editing, const std::vector<Option_spec>& specs, const Args& args,
                Context& context)
{
  using namespace CGAL::MPM;
  const std::string model_path = args.positionals().front();
  if(!args.has("output")) throw Usage_error("'mpm " + editing.name + "' needs -o OUT");
  for(const std::string& name : editing.required)
    if(!args.has(name))
      throw Usage_error("'mpm " + editing.name + "' needs --" + name + " " + find_spec(specs, name).value_name);
  const std::string output = args.text("output");
  const std::string extension = lower_extension(output);
  // Refused before solving: the work would be lost at the end.
  if(extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl")
    throw Usage_error("option --output: '" + output + "' must end in .off, .obj, .ply or .stl");
  const int example = static_cast<int>(args.integer("example", 0));

  context.progress.update("loading " + model_path, 0.);
  Morphable_part_model model = load_model(model_path);
  if(example >= static_cast<int>(model.examples.size()))
    throw Input_error(model_path, "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " example" +
                        (model.examples.size() == 1 ? "" : "s") + ")");
  // Another pose of the example's mesh becomes the state the edit starts from.
  const std::string pose_file = args.text("mesh");
  if(!pose_file.empty()) set_example_pose(model, example, read_mesh_file(pose_file).mesh, pose_file);
  const Training_example& input = model.examples[example];
  const Point_matrix rest = rest_positions(input);
  const std::string handles_file = args.text("handles");
  const Handle_set handles = handles_file.empty() ? Handle_set() : read_handles(handles_file, rest);

  Edit_options edit;
  Embedding_options& options = edit.solver;
  options.max_iterations = static_cast<int>(args.integer("iterations", options.max_iterations));
  options.tolerance = args.real("tolerance", options.tolerance);
  options.handle_weight = args.real("handle-weight", options.handle_weight);
  options.coupling_weight = args.real("coupling", options.coupling_weight);
  options.iteration_callback = iteration_progress(context.progress, "solving", 0.3, 0.9, options.max_iterations);
  edit.unfold = !args.flag("keep-folds");
  edit.handles_source = handles_file;
  edit.example = example;

  context.progress.update("setting up", 0.1);
  Json settings = Json::object();
  const internal::Solved_edit solved =
    internal::solve_edit(model, editing.make_problem(args, model, example, settings), handles, edit);
  const Indexed_mesh& edited = solved.mesh;
  const Edit_result& r = solved.result;
  const Solve_report& report = r.report;

  context.progress.update("writing " + output, 0.9);
  ensure_parent_directory(output);
  const Color_matrix colors = extension == ".ply" ? part_type_colors(input) : Color_matrix();
  write_mesh_file(edited, output, extension == ".ply" ? &colors : nullptr, context.meshes);
  context.progress.done();

  settings["max_iterations"] = options.max_iterations;
  settings["tolerance"] = options.tolerance;
  settings["handle_weight"] = options.handle_weight;
  settings["coupling_weight"] = options.coupling_weight;
  settings["keep_folds"] = args.flag("keep-folds");
  const Json summary = {
    {"command", editing.name},
    {"model", model_path},
    {"example", example},
    {"example_name", input.name},
    {"vertices", input.mesh.number_of_vertices()},
    {"faces", input.mesh.number_of_faces()},
    {"options", settings},
    {"handles", handles.size()},
    {"handles_file", handles_file.empty() ? Json(nullptr) : Json(handles_file)},
    {"iterations", report.iterations},
    {"converged", report.converged},
    {"energies", report.energies},
    {"residual_energy", report.energy()},
    {"setup_ms", r.setup_ms},
    {"solve_ms", r.solve_ms},
    {"ms_per_iteration", report.iterations > 0 ? r.solve_ms / report.iterations : 0.},
    {"inverted_faces_solved", r.inverted_faces_solved},
    {"inverted_faces_written", r.inverted_faces_written},
    {"unfold_ms", r.unfold_ms},
    {"rms_displacement", relative_rms_displacement(rest, edited.points)},
    {"output", output},
  };
  if(context.json) print_json(summary);
  else print_text_summary(editing, summary);
  return exit_ok;
}

} // namespace

Command make_editing_command(const Editing_command& editing)
{
  const CGAL::MPM::Embedding_options defaults;
  const bool handles_required =
    std::find(editing.required.begin(), editing.required.end(), "handles") != editing.required.end();
  Command c;
  c.name = editing.name;
  c.summary = editing.summary;
  c.synopsis = "MODEL " + (editing.synopsis.empty() ? "" : editing.synopsis + " ") + "-o OUT [--example N]" +
               (handles_required ? "" : " [--handles H.json]") +
               " [--iterations N] [--tolerance T] [--handle-weight W] [--coupling W]";
  c.operand = "MODEL";
  c.description =
    editing.description + "\n\n"
    "MODEL is a model saved by 'mpm learn'; the edit applies to its training example\n"
    "--example. Handles (doc/MPM/Handles.md) are vertex ids of that example's mesh.\n"
    "OUT is an .off, .obj, .ply or .stl file (PLY: per-face colours by part type). The\n"
    "summary gives the energy of every iteration, the residual energy, the timings\n"
    "and the RMS displacement from the input relative to its bounding-box diagonal.";
  c.min_positionals = c.max_positionals = 1;
  c.options = editing.options;
  const std::vector<Option_spec> shared = {
    {"output", 'o', Value_kind::output_file, "OUT", "", "mesh to write: .off, .obj, .ply or .stl (required)"},
    {"example", 0, Value_kind::integer, "N", "0", "training example to edit", 0, INT_MAX},
    {"mesh", 0, Value_kind::input_file, "M.off", "none",
     "another pose of the example's mesh (same triangles) to start from"},
    {"handles", 0, Value_kind::input_file, "H.json", handles_required ? "" : "none",
     handles_required ? "handle file (required)" : "handle file"},
    {"iterations", 0, Value_kind::integer, "N", std::to_string(defaults.max_iterations),
     "maximum number of solver iterations", 1, INT_MAX},
    {"tolerance", 0, Value_kind::real, "T", format_number(defaults.tolerance),
     "stop when the energy decreases by less than this fraction", 0, HUGE_VAL},
    {"handle-weight", 0, Value_kind::real, "W", format_number(defaults.handle_weight),
     "handle stiffness relative to the mean elastic stiffness", 0, HUGE_VAL, true},
    {"coupling", 0, Value_kind::real, "W", format_number(defaults.coupling_weight),
     "weight pulling the coordinates of neighbouring same-type parts together", 0, HUGE_VAL},
    {"keep-folds", 0, Value_kind::flag, "", "off",
     "write the solver's result as it is; by default faces it turned inside out are unfolded"},
  };
  c.options.insert(c.options.end(), shared.begin(), shared.end());
  c.run = [editing, specs = c.options](const Args& args, Context& context) {
    return run_editing(editing, specs, args, context);
  };
  return c;
}

} // namespace mpm
