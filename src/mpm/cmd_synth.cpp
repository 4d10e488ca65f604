// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm synth FAMILY -o PREFIX`: writes a synthetic part-structured model
// (mesh, per-face labels, annotation) with known variation.
#include "cli.h"

#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <climits>
#include <iostream>
#include <set>

namespace mpm {

namespace {

std::string family_list()
{
  std::string r;
  for(CGAL::MPM::Synthetic_family f : CGAL::MPM::all_synthetic_families())
    r += (r.empty() ? "" : ", ") + CGAL::MPM::family_name(f);
  return r;
}

int run_synth(const Args& args, Context& context)
{
  using namespace CGAL::MPM;
  const std::string name = args.positionals().front();
  Synthetic_family family{};
  try
  {
    family = parse_family(name);
  }
  catch(const Input_error& e) // a wrong word on the command line: a usage error
  {
    throw Usage_error(e.what());
  }
  if(!args.has("output")) throw Usage_error("'mpm synth' needs -o PREFIX");
  const std::string prefix = args.text("output");

  Synthetic_options options;
  options.seed = static_cast<unsigned>(args.integer("seed", 1));
  options.vertices = static_cast<int>(args.integer("vertices", 0));
  // Measured: about 160 bytes per vertex at the peak (synth hand, 400,000 vertices).
  check_memory("vertices", std::to_string(options.vertices), 200. * options.vertices);
  if(args.has("pose-seed"))
  {
    options.held_out_pose = true;
    options.pose_seed = static_cast<unsigned>(args.integer("pose-seed", 0));
  }

  context.progress.update("generating " + name, 0.);
  const Synthetic_model model = make_synthetic_model(family, options);
  context.progress.update("writing files", 0.5);

  const std::string mesh_file = prefix + ".off", seg_file = prefix + ".seg", annotation_file = prefix + ".json";
  ensure_parent_directory(mesh_file);
  write_mesh_file(model.mesh.mesh, mesh_file, nullptr, context.meshes);
  write_seg_file(model.mesh.face_labels, seg_file);
  write_annotation(model.annotation, annotation_file);
  context.progress.done();

  Json types = Json::array();
  for(const Synthetic_type& t : model.types)
  {
    int instances = 0;
    for(const Synthetic_instance& i : model.instances) instances += i.type == t.name ? 1 : 0;
    types.push_back({{"name", t.name}, {"instances", instances}, {"true_modes", t.modes}, {"linear", t.linear}});
  }
  int boundary = 0;
  for(const Synthetic_connection& c : model.connections) boundary += c.boundary ? 1 : 0;
  const std::set<int> labels(model.mesh.face_labels.begin(), model.mesh.face_labels.end());

  Json summary = {
    {"family", family_name(model.family)},
    {"seed", options.seed},
    {"held_out_pose", options.held_out_pose},
    {"pose_seed", options.held_out_pose ? Json(options.pose_seed) : Json(nullptr)},
    {"vertices", model.mesh.mesh.number_of_vertices()},
    {"faces", model.mesh.mesh.number_of_faces()},
    {"parts", labels.size()},
    {"types", types},
    {"connections",
     {{"total", model.connections.size()},
      {"boundary", boundary},
      {"generalized", static_cast<int>(model.connections.size()) - boundary}}},
    {"expected_rules", model.expected_rules},
    {"files", {{"mesh", mesh_file}, {"labels", seg_file}, {"annotation", annotation_file}}},
  };
  if(context.json)
  {
    print_json(summary);
    return exit_ok;
  }

  std::cout << "Synthetic " << name << " (seed " << options.seed;
  if(options.held_out_pose) std::cout << ", held-out pose " << options.pose_seed;
  std::cout << "): " << summary["vertices"] << " vertices, " << summary["faces"] << " faces, "
            << summary["parts"] << " parts\n\n";
  Table table({"type", "instances", "true modes", "linear"}, {false, true, true, false});
  for(const auto& t : types)
    table.add_row({t["name"], std::to_string(t["instances"].get<int>()), std::to_string(t["true_modes"].get<int>()),
                   t["linear"].get<bool>() ? "yes" : "no"});
  table.print(std::cout);
  std::cout << "\nConnections: " << model.connections.size() << " (" << boundary << " boundary, "
            << model.connections.size() - boundary << " generalized); expected rules: " << model.expected_rules
            << "\nWrote " << mesh_file << ", " << seg_file << ", " << annotation_file << "\n";
  return exit_ok;
}

} // namespace

Command make_synth_command()
{
  Command c;
  c.name = "synth";
  c.summary = "write a synthetic part-structured model (mesh, labels, annotation)";
  c.synopsis = "FAMILY [--seed N] [--vertices N] [--pose-seed N] -o PREFIX";
  c.operand = "FAMILY";
  c.description =
    "FAMILY is one of: " + family_list() + ".\n"
    "Writes PREFIX.off (mesh), PREFIX.seg (one part label per face) and PREFIX.json\n"
    "(annotation: part type per label, model parameters); creates PREFIX's directory.";
  c.min_positionals = c.max_positionals = 1;
  c.options = {
    {"output", 'o', Value_kind::output_prefix, "PREFIX", "", "output prefix (required)"},
    {"seed", 0, Value_kind::integer, "N", "1", "seed of the training model's latent parameters", 0, UINT_MAX},
    {"vertices", 0, Value_kind::integer, "N", "0 = the family's default",
     "approximate number of vertices", 0, INT_MAX},
    {"pose-seed", 0, Value_kind::integer, "N", "none: the training pose",
     "draw a held-out pose from this seed instead", 0, UINT_MAX},
  };
  c.prefix_extensions = {".off", ".seg", ".json"};
  c.positionals_are_files = false;
  c.run = run_synth;
  return c;
}

} // namespace mpm
