// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm fit MODEL MESH [--labels SEG] [--annotation JSON] [--segment LABEL]`:
// fits a new segmented mesh (or some of its segments) into a learned model
// and reports per segment its part type, shape coordinates and residual;
// `-o FILE` writes the fitted surface. `mpm fit --leave-one-out MESH ...`
// learns from all meshes but one, fits that one, and does so for each.
#include "cli.h"
#include "standard_streams.h"
#include "mesh_files.h"

#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Learning/Model_fit.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Part_colors.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>

#include <chrono>
#include <climits>
#include <iostream>

namespace mpm {

namespace {

using namespace CGAL::MPM;

// A mesh read with its label and annotation files (`collect_mesh_files()`).
Training_input read_input(const Mesh_files& files, Context& context, std::vector<std::string>& warnings)
{
  Training_input input;
  context.progress.update("reading " + files.mesh, 0.);
  std::vector<std::string> read_warnings;
  input.mesh = read_labeled_mesh(files.mesh, files.labels, &read_warnings);
  input.mesh.source = as_the_user_wrote(input.mesh.source); // `-`, not its temporary copy
  for(const std::string& w : read_warnings)
  {
    warnings.push_back(w);
    context.progress.warning(w);
  }
  validate_labeled_mesh(input.mesh);
  if(!files.annotation.empty()) input.annotation = read_annotation(files.annotation);
  return input;
}

// A mesh without annotation gets the types `mpm learn` would propose for it,
// kept where the model has a type of that name and seam-loop count; the
// other segments are left to the library's seams-and-size rule.
void propose_types_for_fit(const Morphable_part_model& model, Training_input& input)
{
  if(!input.annotation.part_type_of_label.empty()) return;
  const Part_type_proposal proposal = propose_part_types(input.mesh);
  const std::map<int, int> loops = seam_loops_of_segments(input.mesh);
  for(const auto& [label, name] : proposal.annotation.part_type_of_label)
  {
    const int t = model.find_type(name);
    if(t < 0) continue;
    Indexed_mesh tmpl;
    tmpl.points = model.types[std::size_t(t)].space.mean;
    tmpl.triangles = model.types[std::size_t(t)].triangles;
    const auto l = loops.find(label);
    if(l != loops.end() && int(boundary_loops(tmpl).size()) == l->second) input.annotation.part_type_of_label[label] = name;
  }
}

Json vector_json(const Eigen::VectorXd& v)
{
  Json a = Json::array();
  for(Eigen::Index k = 0; k < v.size(); ++k) a.push_back(v(k));
  return a;
}

std::string coordinates_text(const Eigen::VectorXd& sigmas)
{
  std::string s;
  for(Eigen::Index k = 0; k < sigmas.size(); ++k) s += (k ? " " : "") + format_number(sigmas(k), 3);
  return s.empty() ? "-" : s;
}

Json errors_json(const std::vector<Type_fit_error>& errors)
{
  Json a = Json::array();
  for(const Type_fit_error& e : errors)
    a.push_back({{"type", e.name},
                 {"segments", e.segments},
                 {"rms_over_mesh_diagonal", e.rms_over_mesh_diagonal},
                 {"rms_over_segment_diagonal", e.rms_over_segment_diagonal},
                 {"worst_over_mesh_diagonal", e.worst_over_mesh_diagonal},
                 {"worst_coverage_residual", e.worst_coverage_residual},
                 {"segment_to_fit_over_mesh_diagonal", e.segment_to_fit_over_mesh_diagonal},
                 {"worst_segment_to_fit_over_mesh_diagonal", e.worst_segment_to_fit_over_mesh_diagonal}});
  return a;
}

Json fit_json(const Morphable_part_model& model, const Model_fit& fit)
{
  Json segments = Json::array();
  for(const Segment_fit& s : fit.segments)
    segments.push_back({{"label", s.label},
                        {"type", model.types[std::size_t(s.type)].name},
                        {"type_chosen_by", s.type_source == Fit_type_source::annotation ? "annotation" : "seams and size"},
                        {"seam_loops", s.seam_loops},
                        {"known_correspondence", s.known_correspondence},
                        {"vertices", s.corresponded.rows()},
                        {"coordinates", vector_json(s.coordinates)},
                        {"coordinates_in_sigmas", vector_json(s.coordinates_in_sigmas)},
                        {"rms", s.rms},
                        {"rms_over_segment_diagonal", s.rms_over_segment_diagonal},
                        {"rms_over_mesh_diagonal", s.rms_over_mesh_diagonal},
                        {"segment_to_fit_over_mesh_diagonal", s.segment_to_fit_over_mesh_diagonal},
                        {"coverage_residual", s.coverage_residual},
                        {"mirrored", s.mirrored},
                        {"flipped_faces", s.flipped_faces}});
  Json skipped = Json::array();
  for(const Skipped_segment& s : fit.skipped) skipped.push_back({{"label", s.label}, {"reason", s.reason}});
  return {{"mesh_diagonal", fit.mesh_diagonal},
          {"rms_over_mesh_diagonal", fit.rms_over_mesh_diagonal},
          {"segments", segments},
          {"types", errors_json(fit.errors_by_type(model))},
          {"skipped", skipped},
          {"warnings", fit.warnings}};
}

std::string percent(double fraction) { return format_number(100. * fraction, 3); }

void print_fit(std::ostream& out, const Morphable_part_model& model, const Model_fit& fit)
{
  Table table({"label", "type", "chosen by", "loops", "vertices", "coverage %", "RMS % segment", "RMS % mesh",
               "segment to fit % mesh", "coordinates (sigmas)"},
              {true, false, false, true, true, true, true, true, true, false});
  for(const Segment_fit& s : fit.segments)
    table.add_row({std::to_string(s.label), model.types[std::size_t(s.type)].name,
                   s.type_source == Fit_type_source::annotation ? "annotation" : "seams and size",
                   std::to_string(s.seam_loops), std::to_string(s.corresponded.rows()),
                   s.known_correspondence ? "known" : percent(s.coverage_residual), percent(s.rms_over_segment_diagonal),
                   percent(s.rms_over_mesh_diagonal), percent(s.segment_to_fit_over_mesh_diagonal),
                   coordinates_text(s.coordinates_in_sigmas)});
  table.print(out);
  Table types({"type", "segments", "RMS % mesh", "RMS % segment", "worst % mesh"}, {false, true, true, true, true});
  for(const Type_fit_error& e : fit.errors_by_type(model))
    types.add_row({e.name, std::to_string(e.segments), percent(e.rms_over_mesh_diagonal),
                   percent(e.rms_over_segment_diagonal), percent(e.worst_over_mesh_diagonal)});
  out << "\nPer part type\n";
  types.print(out);
  for(const Skipped_segment& s : fit.skipped) out << "  skipped: " << s.reason << "\n";
}

void write_fitted_surface(const Morphable_part_model& model, const Model_fit& fit, const std::string& path,
                          const Mesh_write_options& options)
{
  const Labeled_mesh surface = fit.fitted_surface(model);
  Eigen::Matrix<unsigned char, Eigen::Dynamic, 3> colors(surface.mesh.number_of_faces(), 3);
  int face = 0;
  for(const Segment_fit& s : fit.segments)
    for(std::size_t k = 0; k < model.types[std::size_t(s.type)].triangles.size(); ++k, ++face)
    {
      const Rgb_color c = part_type_color(s.type);
      colors.row(face) << c[0], c[1], c[2];
    }
  ensure_parent_directory(path);
  write_mesh_file(surface.mesh, path, &colors, options);
}

Model_fit_options fit_options(const Args& args, Context& context, std::vector<std::string>& warnings)
{
  Model_fit_options o;
  for(const Arg_item& item : args.items)
    if(item.option == "segment") o.labels.push_back(std::stoi(item.value));
  o.skip_unfittable = args.flag("skip-unfittable") || args.flag("leave-one-out");
  o.use_known_correspondence = !args.flag("correspond-always");
  o.correspondence.refine = !args.flag("no-refine");
  o.correspondence.refinement_iterations =
    static_cast<int>(args.integer("refinement-iterations", o.correspondence.refinement_iterations));
  o.surface_iterations = static_cast<int>(args.integer("surface-iterations", o.surface_iterations));
  o.progress = [&](const std::string& stage, double fraction) { context.progress.update(stage, fraction); };
  o.warning = [&](const std::string& w) {
    warnings.push_back(w);
    context.progress.warning(w);
  };
  return o;
}

int run_fit_model(const Args& args, Context& context)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string model_path = args.positionals().front();
  const std::vector<Mesh_files> meshes = collect_mesh_files(args, true, false);
  if(meshes.size() != 1) throw Usage_error("'mpm fit' takes one MODEL and one MESH (or --leave-one-out MESH ...)");
  std::vector<std::string> warnings;
  context.progress.update("loading " + model_path, 0.);
  const Morphable_part_model model = load_model(model_path);
  Training_input input = read_input(meshes.front(), context, warnings);
  propose_types_for_fit(model, input);
  const Model_fit fit = fit_morphable_part_model(model, input.mesh, input.annotation, fit_options(args, context, warnings));
  const std::string output = args.text("output");
  if(!output.empty())
  {
    context.progress.update("writing " + output, 0.);
    write_fitted_surface(model, fit, output, context.meshes);
  }
  context.progress.done();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(context.json)
  {
    Json summary = {{"model", model_path}, {"mesh", meshes.front().mesh}, {"labels", meshes.front().labels},
                    {"annotation", meshes.front().annotation.empty() ? Json(nullptr) : Json(meshes.front().annotation)},
                    {"fitted_surface", output.empty() ? Json(nullptr) : Json(output)}};
    summary.update(fit_json(model, fit));
    summary["read_warnings"] = warnings;
    summary["time_seconds"] = seconds;
    print_json(summary);
    return exit_ok;
  }
  std::cout << "Fitted " << fit.segments.size() << " segment" << (fit.segments.size() == 1 ? "" : "s") << " of "
            << meshes.front().mesh << " into " << model_path << " in " << format_number(seconds, 3) << " s: RMS "
            << percent(fit.rms_over_mesh_diagonal) << "% of the diagonal (" << format_number(fit.mesh_diagonal) << ")\n\n";
  print_fit(std::cout, model, fit);
  if(!output.empty())
    std::cout << "\nWrote " << output << " (the fitted parts, " << fit.segments.size()
              << " separate pieces: seams are not shared)\n";
  return exit_ok;
}

// Types must agree across the meshes: meshes without annotation get types
// proposed jointly, as `mpm learn` proposes them for several meshes.
void propose_missing_types(std::vector<Training_input>& inputs)
{
  std::vector<std::size_t> bare;
  std::vector<Labeled_mesh> meshes;
  for(std::size_t i = 0; i < inputs.size(); ++i)
    if(inputs[i].annotation.part_type_of_label.empty())
    {
      bare.push_back(i);
      meshes.push_back(inputs[i].mesh);
    }
  if(bare.empty() || segments_share_connectivity(meshes)) return;
  const std::vector<Part_type_proposal> made = propose_part_types(meshes);
  for(std::size_t k = 0; k < bare.size(); ++k)
    inputs[bare[k]].annotation.part_type_of_label = made[k].annotation.part_type_of_label;
}

int run_leave_one_out(const Args& args, Context& context)
{
  const std::vector<Mesh_files> files = collect_mesh_files(args, false, false);
  if(files.size() < 2) throw Usage_error("'mpm fit --leave-one-out' needs at least two meshes");
  std::vector<std::string> warnings;
  std::vector<Training_input> inputs;
  for(const Mesh_files& f : files) inputs.push_back(read_input(f, context, warnings));
  propose_missing_types(inputs);
  const long long only = args.integer("held-out", -1);
  if(only >= static_cast<long long>(files.size()))
    throw Usage_error("--held-out " + std::to_string(only) + ": there are only " + std::to_string(files.size()) + " meshes");
  Learning_options learning;
  learning.progress = [&](const std::string& stage, double fraction) { context.progress.update(stage, fraction); };
  learning.warning = [&](const std::string& w) { warnings.push_back(w); };
  Json rounds = Json::array();
  Table table({"held out", "type", "segments", "RMS % mesh", "RMS % segment", "worst % mesh", "learn s", "fit s"},
              {false, false, true, true, true, true, true, true});
  std::vector<std::string> skipped;
  std::vector<std::vector<Type_fit_error>> all_errors;
  for(int h = 0; h < int(files.size()); ++h)
  {
    if(only >= 0 && h != only) continue;
    const Leave_one_out_fit r = fit_held_out_input(inputs, h, learning, fit_options(args, context, warnings));
    Json round = {{"held_out", files[std::size_t(h)].mesh}};
    round.update(fit_json(r.model, r.fit));
    round["learning_seconds"] = r.learning_seconds;
    round["fitting_seconds"] = r.fitting_seconds;
    rounds.push_back(round);
    for(const Type_fit_error& e : r.errors)
      table.add_row({files[std::size_t(h)].mesh, e.name, std::to_string(e.segments), percent(e.rms_over_mesh_diagonal),
                     percent(e.rms_over_segment_diagonal), percent(e.worst_over_mesh_diagonal),
                     format_number(r.learning_seconds, 3), format_number(r.fitting_seconds, 3)});
    for(const Skipped_segment& s : r.fit.skipped) skipped.push_back(s.reason);
    all_errors.push_back(r.errors);
  }
  const std::vector<Type_fit_error> pooled = pool_type_fit_errors(all_errors);
  context.progress.done();
  if(context.json)
  {
    print_json({{"leave_one_out", rounds}, {"types", errors_json(pooled)}, {"warnings", warnings}});
    return exit_ok;
  }
  std::cout << "Leave-one-out over " << files.size() << " meshes: each learned from the others, then fitted\n\n";
  table.print(std::cout);
  for(const std::string& s : skipped) std::cout << "  skipped: " << s << "\n";
  Table types({"type", "segments", "RMS % mesh", "RMS % segment", "worst % mesh", "segment to fit RMS % mesh",
               "worst segment to fit % mesh", "worst coverage %"},
              {false, true, true, true, true, true, true, true});
  for(const Type_fit_error& e : pooled)
    types.add_row({e.name, std::to_string(e.segments), percent(e.rms_over_mesh_diagonal),
                   percent(e.rms_over_segment_diagonal), percent(e.worst_over_mesh_diagonal),
                   percent(e.segment_to_fit_over_mesh_diagonal), percent(e.worst_segment_to_fit_over_mesh_diagonal),
                   percent(e.worst_coverage_residual)});
  // The RMS is against the template's vertices on the segment: a fit that
  // covers only part of the segment (segment to fit) or a correspondence
  // that misses it (coverage) makes it say little.
  std::cout << "\nPer part type, over all held-out meshes (segment to fit: RMS distance of the segment's "
               "vertices to the fitted surface; worst coverage: how far the segment lies from the template put on "
               "it, % of the segment's diagonal)\n";
  types.print(std::cout);
  return exit_ok;
}

int run_fit(const Args& args, Context& context)
{
  if(args.flag("leave-one-out"))
  {
    if(args.has("output") || args.has("segment"))
      throw Usage_error("--leave-one-out takes neither -o nor --segment");
    return run_leave_one_out(args, context);
  }
  if(args.has("held-out")) throw Usage_error("--held-out goes with --leave-one-out");
  if(args.positionals().size() != 2) throw Usage_error("'mpm fit' takes MODEL MESH (or --leave-one-out MESH MESH2 ...)");
  return run_fit_model(args, context);
}

} // namespace

Command make_fit_command()
{
  Command c;
  c.name = "fit";
  c.summary = "fit a new segmented mesh into a model: types, shape coordinates, residuals";
  c.synopsis = "MODEL MESH [--labels SEG] [--annotation JSON] [--segment LABEL] [-o FITTED] [options]\n"
               "       mpm fit --leave-one-out MESH [--labels SEG] [--annotation JSON] MESH2 ... [options]";
  c.operand = "MODEL MESH";
  c.description =
    "Each segment of MESH (or each --segment) gets a part type of the model: the\n"
    "annotation's; without one, the type `mpm learn` would propose when the model has\n"
    "it; else the type with as many seam loops and the closest area and loop lengths.\n"
    "The type's template (its mean shape) is put on the segment by dense\n"
    "correspondence and fitted into the type's shape space (rigid alignment and\n"
    "projection onto the modes), then closer to the segment's surface by closest-point\n"
    "steps. Prints per segment the shape coordinates (in standard deviations), the\n"
    "RMS distance between the template's vertices on the segment and the fitted\n"
    "points, over the segment's and over the mesh's bounding-box diagonal, the RMS\n"
    "distance of the segment's vertices to the fitted surface, and per type the RMS.\n"
    "-o writes the fitted parts (PLY faces coloured by type), one separate piece per\n"
    "segment.\n\n"
    "--leave-one-out learns from all meshes but one, fits that one (segments that\n"
    "cannot be fitted are skipped and listed) and repeats for each mesh (or only\n"
    "--held-out K): the RMS per type says how well a model of this kind generalizes.\n"
    "Labels and annotation default to MESH's .seg and .json siblings.";
  c.min_positionals = 1;
  c.max_positionals = -1;
  c.options = {
    {"output", 'o', Value_kind::output_file, "FITTED", "none", "write the fitted surface (OFF, OBJ, PLY or STL)"},
    {"segment", 0, Value_kind::integer, "LABEL", "every segment", "fit only this segment (repeatable)", 0, INT_MAX,
     false, true},
    {"skip-unfittable", 0, Value_kind::flag, "", "", "list segments that cannot be fitted instead of failing"},
    {"correspond-always", 0, Value_kind::flag, "", "",
     "dense correspondence even for segments with their type's connectivity"},
    {"no-refine", 0, Value_kind::flag, "", "", "skip the correspondence refinement (trace(Sigma) minimization)"},
    {"refinement-iterations", 0, Value_kind::integer, "N", "40", "gradient steps of the refinement", 0, INT_MAX},
    {"surface-iterations", 0, Value_kind::integer, "N", "10",
     "closest-point steps fitting the shape space to the segment's surface (0: to the corresponded vertices)", 0,
     INT_MAX},
    {"leave-one-out", 0, Value_kind::flag, "", "", "positionals are meshes: learn from all but one, fit that one"},
    {"held-out", 0, Value_kind::integer, "K", "each in turn", "with --leave-one-out: hold out only mesh K (from 0)",
     0, INT_MAX},
  };
  const std::vector<Option_spec> mesh_files = mesh_file_options();
  c.options.insert(c.options.begin() + 1, mesh_files.begin(), mesh_files.end());
  c.run = run_fit;
  return c;
}

} // namespace mpm
