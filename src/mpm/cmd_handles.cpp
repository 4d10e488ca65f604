// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm handles MODEL -o H.json`: chooses handle vertices on a model's
// training example (per part or by farthest-point sampling) and takes their
// targets from another pose of the same mesh, for scripted comparisons; or
// bends every limb about its attachment to the root.
#include "cli.h"

#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Editing/Limb_bending.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>

#include <climits>
#include <iostream>

namespace mpm {

namespace {

int run_handles(const Args& args, Context& context)
{
  using namespace CGAL::MPM;
  const std::string model_path = args.positionals().front();
  if(!args.has("output")) throw Usage_error("'mpm handles' needs -o H.json");
  if(int(args.has("per-part")) + int(args.has("farthest")) + int(args.has("bend-limbs")) != 1)
    throw Usage_error("'mpm handles' needs exactly one of --per-part K, --farthest N and --bend-limbs MOVE");
  if(args.has("bend-limbs") && args.has("targets"))
    throw Usage_error("'mpm handles --bend-limbs' makes its own targets: --targets does not apply");
  const std::string output = args.text("output");
  const int example = static_cast<int>(args.integer("example", 0));

  context.progress.update("loading " + model_path, 0.);
  Morphable_part_model model = load_model(model_path);
  if(example >= static_cast<int>(model.examples.size()))
    throw Input_error(model_path, "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  const Labeled_mesh rest = to_labeled_mesh(model.examples[example]);
  Point_matrix targets = rest.mesh.points;
  const std::string targets_file = args.text("targets");
  if(!targets_file.empty())
  {
    // The same checks as for any other pose of the example.
    set_example_pose(model, example, read_mesh_file(targets_file).mesh, targets_file);
    targets = rest_positions(model.examples[example]);
  }

  Handle_set handles;
  if(args.has("per-part"))
  {
    handles = handles_per_part(rest, static_cast<int>(args.integer("per-part", 1)), targets);
  }
  else if(args.has("farthest"))
    handles = farthest_point_handles(rest.mesh, static_cast<int>(args.integer("farthest", 1)), targets);
  else
    handles = limb_bending_handles(model, example, args.real("bend-limbs", 0.1));
  ensure_parent_directory(output);
  write_handles(handles, output);
  context.progress.done();

  const Json summary = {{"model", model_path},
                        {"example", example},
                        {"handles", handles.size()},
                        {"targets", targets_file.empty() ? Json(nullptr) : Json(targets_file)},
                        {"output", output}};
  if(context.json)
  {
    print_json(summary);
    return exit_ok;
  }
  const std::string targets_are = args.has("bend-limbs") ? " (limbs bent about their attachment to the root)"
                                  : targets_file.empty()  ? " (targets at rest)"
                                                          : " (targets from " + targets_file + ")";
  std::cout << "Wrote " << handles.size() << " handles of example " << example << " of " << model_path << " to "
            << output << targets_are << "\n";
  return exit_ok;
}

} // namespace

Command make_handles_command()
{
  Command c;
  c.name = "handles";
  c.summary = "choose handle vertices on a model's example, with targets from another pose";
  c.synopsis = "MODEL (--per-part K | --farthest N | --bend-limbs MOVE) [--targets POSE.off] [--example N] -o H.json";
  c.operand = "MODEL";
  c.description =
    "--per-part 1 takes each part's vertex nearest to its centroid, --per-part 2 also\n"
    "the vertex farthest from it; --farthest N samples N vertices by farthest-point\n"
    "sampling. Targets are the positions of the same vertices in POSE.off (a mesh\n"
    "with the example's triangles, e.g. from 'mpm synth FAMILY --pose-seed S'), or\n"
    "the rest positions. --bend-limbs MOVE takes a handle on every limb's tip, turned\n"
    "about the limb's attachment to the root by the angle that moves it by MOVE times\n"
    "the bounding-box diagonal, and holds the root (the largest part) away from its\n"
    "seams. The file format is doc/MPM/Handles.md.";
  c.min_positionals = c.max_positionals = 1;
  c.options = {
    {"output", 'o', Value_kind::output_file, "H.json", "", "handle file to write (required)"},
    {"per-part", 0, Value_kind::integer, "K", "none", "handles per part (1 or 2)", 1, 2},
    {"farthest", 0, Value_kind::integer, "N", "none", "handles by farthest-point sampling", 1, INT_MAX},
    {"bend-limbs", 0, Value_kind::real, "MOVE", "none", "bend every limb by moving its tip MOVE x diagonal", 0., 1., true},
    {"targets", 0, Value_kind::input_file, "POSE.off", "none: rest positions", "pose giving the targets"},
    {"example", 0, Value_kind::integer, "N", "0", "training example", 0, INT_MAX},
  };
  c.run = run_handles;
  return c;
}

} // namespace mpm
