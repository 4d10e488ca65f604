// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm learn MESH [--labels SEG] [--annotation JSON] [MESH2 ...] -o MODEL`:
// learns a morphable part model from part-labelled meshes and saves it.
#include "cli.h"

#include <CGAL/MPM/Annotation_io.h>
#include <CGAL/MPM/Mesh_io.h>
#include <CGAL/MPM/Model_io.h>
#include <CGAL/MPM/learn_morphable_part_model.h>

#include <chrono>
#include <cmath>
#include <climits>
#include <filesystem>
#include <iostream>

namespace mpm {

namespace {

namespace fs = std::filesystem;

// One MESH argument with the --labels/--annotation that follow it.
struct Input_files
{
  std::string mesh, labels, annotation;
  bool labels_given = false, annotation_given = false;
};

std::vector<Input_files> collect_inputs(const Args& args)
{
  std::vector<Input_files> inputs;
  for(const Arg_item& item : args.items)
  {
    if(item.option.empty())
    {
      inputs.push_back({item.value, "", "", false, false});
      continue;
    }
    if(item.option != "labels" && item.option != "annotation") continue;
    if(inputs.empty()) throw Usage_error("option --" + item.option + " must follow the MESH it belongs to");
    Input_files& in = inputs.back();
    bool& given = item.option == "labels" ? in.labels_given : in.annotation_given;
    if(given) throw Usage_error("option --" + item.option + " given twice for " + in.mesh);
    given = true;
    (item.option == "labels" ? in.labels : in.annotation) = item.value;
  }
  for(Input_files& in : inputs)
  {
    std::error_code ec;
    if(!in.labels_given)
    {
      const std::string seg = fs::path(in.mesh).replace_extension(".seg").string();
      in.labels = fs::is_regular_file(seg, ec) ? seg : "components";
    }
    if(!in.annotation_given)
    {
      const std::string json = fs::path(in.mesh).replace_extension(".json").string();
      if(fs::is_regular_file(json, ec)) in.annotation = json;
    }
  }
  return inputs;
}

int run_learn(const Args& args, Context& context)
{
  using namespace CGAL::MPM;
  const auto start = std::chrono::steady_clock::now();
  if(!args.has("output")) throw Usage_error("'mpm learn' needs -o MODEL");
  const std::string output = args.text("output");
  const std::vector<Input_files> files = collect_inputs(args);

  std::vector<std::string> warnings;
  auto warn = [&](const std::string& w) {
    warnings.push_back(w);
    context.progress.warning(w);
  };

  std::vector<Training_input> inputs;
  for(std::size_t i = 0; i < files.size(); ++i)
  {
    const Input_files& f = files[i];
    context.progress.update("reading " + f.mesh, double(i) / double(files.size()));
    Training_input input;
    std::vector<std::string> read_warnings;
    input.mesh = read_labeled_mesh(f.mesh, f.labels, &read_warnings);
    for(const std::string& w : read_warnings) warn(w);
    validate_labeled_mesh(input.mesh);
    if(!f.annotation.empty())
    {
      input.annotation = read_annotation(f.annotation);
    }
    // Command-line parameters override the annotation's.
    Model_parameters& p = input.annotation.parameters;
    if(args.has("modes")) p.modes = static_cast<int>(args.integer("modes", 0));
    if(args.has("explained-variance")) p.explained_variance = args.real("explained-variance", 0.99);
    if(args.has("docking-radius")) p.docking_radius = args.real("docking-radius", -1.);
    if(args.has("sigma-sub")) p.sigma_sub = args.real("sigma-sub", -1.);
    if(args.has("sigma-bound")) p.sigma_bound = args.real("sigma-bound", -1.);
    inputs.push_back(std::move(input));
  }

  Learning_options options;
  options.progress = [&](const std::string& stage, double fraction) { context.progress.update(stage, fraction); };
  options.warning = warn;
  const Morphable_part_model model = learn_morphable_part_model(inputs, options);

  context.progress.update("saving " + output, 0.);
  ensure_parent_directory(output);
  save_model(model, output);
  context.progress.done();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  Json summary = model_summary(model, output);
  Json in = Json::array();
  for(const Input_files& f : files)
    in.push_back({{"mesh", f.mesh},
                  {"labels", f.labels},
                  {"annotation", f.annotation.empty() ? Json(nullptr) : Json(f.annotation)}});
  summary["inputs"] = in;
  summary["warnings"] = warnings;
  summary["time_seconds"] = seconds;
  if(context.json)
  {
    print_json(summary);
    return exit_ok;
  }
  std::cout << "Learned " << output << " from " << files.size() << " mesh" << (files.size() == 1 ? "" : "es")
            << " in " << format_number(seconds, 3) << " s\n";
  for(const Input_files& f : files)
    std::cout << "  " << f.mesh << "  labels: " << f.labels
              << "  annotation: " << (f.annotation.empty() ? "none" : f.annotation) << "\n";
  std::cout << "\n";
  print_model_summary(std::cout, summary);
  return exit_ok;
}

} // namespace

Command make_learn_command()
{
  Command c;
  c.name = "learn";
  c.summary = "learn a morphable part model from part-labelled meshes";
  c.synopsis = "MESH [--labels SEG] [--annotation JSON] [MESH2 [--labels SEG2] [--annotation JSON2] ...] -o MODEL [options]";
  c.operand = "MESH";
  c.description =
    "MESH is an OFF, OBJ, PLY or STL file. --labels and --annotation apply to the MESH\n"
    "they follow. Labels: a .seg file (one integer per face), 'components' (one part\n"
    "per connected component) or 'property:NAME' (an integer face property of a PLY\n"
    "file); default: MESH with its extension replaced by .seg if that file exists,\n"
    "else 'components'. Annotation (part types, landmarks, parameters; see\n"
    "doc/MPM/File_formats.md): default MESH's .json sibling if it exists, else none\n"
    "(parts with identical connectivity form a type). Parameters are taken from the\n"
    "first mesh's annotation; the options below override them.";
  c.min_positionals = 1;
  c.max_positionals = -1;
  c.options = {
    {"output", 'o', Value_kind::text, "MODEL", "", "model file to write (required)"},
    {"labels", 0, Value_kind::text, "SEG", "MESH.seg if present, else components",
     "part labels of the preceding MESH", -HUGE_VAL, HUGE_VAL, false, true},
    {"annotation", 0, Value_kind::text, "JSON", "MESH.json if present, else none",
     "annotation of the preceding MESH", -HUGE_VAL, HUGE_VAL, false, true},
    {"modes", 0, Value_kind::integer, "N", "annotation's, else 0 = by explained variance",
     "modes kept per shape space", 0, INT_MAX},
    {"explained-variance", 0, Value_kind::real, "F", "annotation's, else 0.99",
     "variance fraction the kept modes explain when --modes is 0", 0, 1, true},
    {"docking-radius", 0, Value_kind::real, "R", "annotation's, else 5% of the bounding-box diagonal",
     "influence radius of a docking (pair geometry)", 0, HUGE_VAL, true},
    {"sigma-sub", 0, Value_kind::real, "S", "annotation's, else 2% of the bounding-box diagonal",
     "flexibility outside the learned subspace", 0, HUGE_VAL, true},
    {"sigma-bound", 0, Value_kind::real, "S", "annotation's, else a third of each cluster's diameter",
     "width of the blending region at part borders", 0, HUGE_VAL, true},
  };
  c.run = run_learn;
  return c;
}

} // namespace mpm
