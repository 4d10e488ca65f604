// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm learn MESH [--labels SEG] [--annotation JSON] [MESH2 ...] -o MODEL`:
// learns a morphable part model from part-labelled meshes and saves it.
// Meshes without an annotation whose segments are not in known
// correspondence (real segmentations) get proposed part types first. With
// --auto-cut, meshes without --labels are cut at proposed joints first.
#include "cli.h"
#include "standard_streams.h"
#include "mesh_files.h"

#include <CGAL/MPM/Cutting/Joint_proposal.h>
#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <climits>
#include <functional>
#include <iostream>

namespace mpm {

namespace {

// The proposal's table: one row per segment, in breadth-first order from
// the root, then the instance count of each type.
void print_proposal(std::ostream& out, const std::string& mesh, const CGAL::MPM::Part_type_proposal& p)
{
  out << "Proposed part types for " << mesh << " (root: segment " << p.root << ")\n";
  Table table({"label", "faces", "area", "seams", "neighbours", "depth", "type", "split off because"},
              {true, true, true, true, false, true, false, false});
  for(const CGAL::MPM::Segment_proposal& s : p.segments)
  {
    std::string neighbours;
    for(int n : s.neighbours) neighbours += (neighbours.empty() ? "" : " ") + std::to_string(n);
    table.add_row({std::to_string(s.label), std::to_string(s.faces), format_number(s.area, 3),
                   std::to_string(s.seam_loops), neighbours, std::to_string(s.depth), s.type, s.reason});
  }
  table.print(out);
  out << "  instances:";
  for(const auto& [type, count] : p.instances_of_type()) out << " " << type << " x" << count;
  out << "\n\n";
}

Json proposal_json(const std::string& mesh, const CGAL::MPM::Part_type_proposal& p)
{
  Json segments = Json::array();
  for(const CGAL::MPM::Segment_proposal& s : p.segments)
    segments.push_back({{"label", s.label}, {"faces", s.faces}, {"area", s.area}, {"diameter", s.diameter},
                        {"seam_loops", s.seam_loops}, {"neighbours", s.neighbours}, {"depth", s.depth},
                        {"parent", s.parent}, {"type", s.type}, {"reason", s.reason}});
  return {{"mesh", mesh}, {"root", p.root}, {"instances", p.instances_of_type()}, {"segments", segments}};
}

// Meshes with no annotation whose segments are not in known correspondence
// (no two with identical connectivity: a real segmentation) get proposed
// part types; synthetic inputs keep the learner's grouping by connectivity.
// Returns the proposals, one per file (empty where none was made).
std::vector<CGAL::MPM::Part_type_proposal> propose_missing_types(std::vector<Mesh_files>& files,
                                                                 std::vector<CGAL::MPM::Training_input>& inputs)
{
  using namespace CGAL::MPM;
  std::vector<std::size_t> bare;
  std::vector<Labeled_mesh> meshes;
  for(std::size_t i = 0; i < files.size(); ++i)
    if(inputs[i].annotation.part_type_of_label.empty())
    {
      bare.push_back(i);
      meshes.push_back(inputs[i].mesh);
    }
  std::vector<Part_type_proposal> proposals(files.size());
  if(bare.empty() || !part_types_need_proposing(meshes)) return proposals;
  std::vector<Part_type_proposal> made = propose_part_types(meshes);
  for(std::size_t k = 0; k < bare.size(); ++k)
  {
    inputs[bare[k]].annotation.part_type_of_label = made[k].annotation.part_type_of_label;
    files[bare[k]].proposed = true;
    proposals[bare[k]] = std::move(made[k]);
  }
  return proposals;
}

// The learner groups nothing when every type has one instance: no shape
// space has modes, which a user should hear about.
void warn_if_no_type_repeats(const CGAL::MPM::Morphable_part_model& model,
                             const std::function<void(const std::string&)>& warn)
{
  std::vector<int> instances(model.types.size(), 0);
  for(const auto& e : model.examples)
    for(const auto& n : e.graph.nodes)
      if(n.type >= 0 && n.type < static_cast<int>(model.types.size())) ++instances[std::size_t(n.type)];
  if(!instances.empty() && *std::max_element(instances.begin(), instances.end()) < 2)
    warn("no part type has two instances (" + std::to_string(model.types.size()) +
         " types of one segment each): the model has no learned variation; give alike segments one type "
         "(an annotation, or no annotation so that types are proposed)");
}

// Proposes the missing part types, writes the requested annotations and
// prints the tables (text) or returns them (JSON).
Json propose_and_report(std::vector<Mesh_files>& files, std::vector<CGAL::MPM::Training_input>& inputs,
                        Context& context)
{
  using namespace CGAL::MPM;
  const std::vector<Part_type_proposal> proposals = propose_missing_types(files, inputs);
  Json proposed = Json::array();
  for(std::size_t i = 0; i < files.size(); ++i)
  {
    if(!files[i].write_annotation.empty() && !files[i].proposed)
      throw Usage_error("--write-annotation " + files[i].write_annotation + ": no part types were proposed for " +
                        files[i].mesh + " (it has an annotation, or its parts share connectivity)");
    if(!files[i].proposed) continue;
    if(!files[i].write_annotation.empty())
    {
      ensure_parent_directory(files[i].write_annotation);
      write_annotation(inputs[i].annotation, files[i].write_annotation);
    }
    if(context.json)
      proposed.push_back(proposal_json(files[i].mesh, proposals[i]));
    else
    {
      context.progress.done();
      print_proposal(std::cout, files[i].mesh, proposals[i]);
      std::cout.flush();
    }
  }
  return proposed;
}

// --auto-cut: the mesh cut at the joints cut_at_proposed_joints() proposes.
CGAL::MPM::Labeled_mesh auto_cut(const Args& args, Context& context, const std::string& path)
{
  using namespace CGAL::MPM;
  Joint_proposal_options options;
  options.sensitivity = args.real("sensitivity", options.sensitivity);
  context.progress.update("proposing joints of " + path, 0.1);
  const Joint_proposal proposal = cut_at_proposed_joints(read_mesh_file(path).mesh, options, path);
  if(!context.json) {
    context.progress.done();
    std::cout << "Cut " << path << " at " << proposal.cutting.cuts.size() << " proposed joints on " << proposal.limbs
              << " limbs (sensitivity " << format_number(options.sensitivity) << ")\n\n";
  }
  Labeled_mesh r = proposal.cutting.mesh;
  r.source = path;
  return r;
}

int run_learn(const Args& args, Context& context)
{
  using namespace CGAL::MPM;
  const auto start = std::chrono::steady_clock::now();
  if(!args.has("output")) throw Usage_error("'mpm learn' needs -o MODEL");
  const std::string output = args.text("output");
  std::vector<Mesh_files> files = collect_mesh_files(args, false, true);

  std::vector<std::string> warnings;
  auto warn = [&](const std::string& w) {
    warnings.push_back(w);
    context.progress.warning(w);
  };

  std::vector<Training_input> inputs;
  for(std::size_t i = 0; i < files.size(); ++i)
  {
    const Mesh_files& f = files[i];
    context.progress.update("reading " + f.mesh, double(i) / double(files.size()));
    Training_input input;
    std::vector<std::string> read_warnings;
    const bool cut_here = args.flag("auto-cut") && !f.labels_given;
    input.mesh = cut_here ? auto_cut(args, context, f.mesh) : read_labeled_mesh(f.mesh, f.labels, &read_warnings);
    if(cut_here) files[i].labels = "cut at proposed joints";
    input.mesh.source = as_the_user_wrote(input.mesh.source); // `-`, not its temporary copy
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

  const Json proposed = propose_and_report(files, inputs, context);
  validate_seam_counts(inputs);

  Learning_options options;
  options.progress = [&](const std::string& stage, double fraction) { context.progress.update(stage, fraction); };
  options.warning = warn;
  const Morphable_part_model model = learn_morphable_part_model(inputs, options);
  warn_if_no_type_repeats(model, warn);

  context.progress.update("saving " + output, 0.);
  ensure_parent_directory(output);
  save_model(model, output);
  context.progress.done();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  Json summary = model_summary(model, output);
  Json in = Json::array();
  for(const Mesh_files& f : files)
    in.push_back({{"mesh", f.mesh},
                  {"labels", f.labels},
                  {"annotation", f.annotation.empty() ? Json(nullptr) : Json(f.annotation)},
                  {"types_proposed", f.proposed}});
  summary["inputs"] = in;
  if(!proposed.empty()) summary["proposed_types"] = proposed;
  summary["warnings"] = warnings;
  summary["time_seconds"] = seconds;
  if(context.json)
  {
    print_json(summary);
    return exit_ok;
  }
  std::cout << "Learned " << output << " from " << files.size() << " mesh" << (files.size() == 1 ? "" : "es")
            << " in " << format_number(seconds, 3) << " s\n";
  for(const Mesh_files& f : files)
    std::cout << "  " << f.mesh << "  labels: " << f.labels
              << "  annotation: "
              << (f.proposed ? "proposed" + (f.write_annotation.empty() ? std::string() : ", written to " + f.write_annotation)
                             : f.annotation.empty() ? "none" : f.annotation)
              << "\n";
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
  c.synopsis = "MESH [--labels SEG] [--annotation JSON] [--write-annotation FILE] [MESH2 ...] -o MODEL\n"
               "       [--auto-cut [--sensitivity S]] [options]";
  c.operand = "MESH";
  c.description =
    "MESH is an OFF, OBJ, PLY or STL file. --labels and --annotation apply to the MESH\n"
    "they follow. Labels: a .seg file (one integer per face), 'components' (one part\n"
    "per connected component) or 'property:NAME' (an integer face property of a PLY\n"
    "file); default: MESH with its extension replaced by .seg if that file exists,\n"
    "else 'components'. Annotation (part types, landmarks, parameters; see\n"
    "doc/MPM/File_formats.md): default MESH's .json sibling if it exists. Without\n"
    "one, parts with identical connectivity form a type (synthetic models); when no\n"
    "two segments share connectivity (a real segmentation), part types are proposed\n"
    "from the segment graph (root: most neighbours; depth along each chain; seam\n"
    "loops) and segment areas, printed as a table and used for learning;\n"
    "--write-annotation FILE saves them for editing. With --auto-cut, meshes given\n"
    "no --labels are cut at joints proposed from their curve skeleton first (as\n"
    "'mpm cut --auto'), so a raw closed mesh becomes a model in one command.\n"
    "Parameters are taken from the first mesh's annotation; the options below\n"
    "override them.";
  c.min_positionals = 1;
  c.max_positionals = -1;
  c.options = {
    {"output", 'o', Value_kind::output_file, "MODEL", "", "model file to write (required)"},
    {"write-annotation", 0, Value_kind::output_file, "FILE", "none",
     "write the part types proposed for the preceding MESH as an annotation", -HUGE_VAL, HUGE_VAL, false, true},
    {"auto-cut", 0, Value_kind::flag, "", "off",
     "cut meshes given no --labels at proposed joints (limbs from the curve skeleton)"},
    {"sensitivity", 0, Value_kind::real, "S", "0.5",
     "with --auto-cut: 0 cuts limbs off the body only, higher proposes more joints along them", 0, 1},
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
  const std::vector<Option_spec> mesh_files = mesh_file_options();
  c.options.insert(c.options.begin() + 1, mesh_files.begin(), mesh_files.end());
  c.run = run_learn;
  return c;
}

} // namespace mpm
