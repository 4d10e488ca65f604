// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm correspond MESH [--labels SEG] [--annotation JSON] -o OUTDIR_OR_PREFIX`:
// puts the same-type parts of a labelled mesh in dense correspondence and
// writes every part with its type's template connectivity, for inspection.
#include "cli.h"
#include "standard_streams.h"

#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <chrono>
#include <climits>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace mpm {

namespace {

namespace fs = std::filesystem;

Json energies_json(const CGAL::MPM::Correspondence_energies& e)
{
  return {{"boundary", e.boundary}, {"sample", e.sample}, {"trace", e.trace}};
}

// Type names may hold characters that do not belong in a file name.
std::string file_safe(const std::string& name)
{
  std::string r;
  for(char c : name) r += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return r.empty() ? "type" : r;
}

int run_correspond(const Args& args, Context& context)
{
  using namespace CGAL::MPM;
  const auto start = std::chrono::steady_clock::now();
  if(!args.has("output")) throw Usage_error("'mpm correspond' needs -o OUTDIR_OR_PREFIX");
  const std::string output = args.text("output");
  const std::string mesh_path = args.positionals().front();
  std::error_code ec;
  std::string labels = args.text("labels");
  if(labels.empty())
  {
    const std::string seg = fs::path(mesh_path).replace_extension(".seg").string();
    labels = fs::is_regular_file(seg, ec) ? seg : "components";
  }
  std::string annotation_path = args.text("annotation");
  if(annotation_path.empty())
  {
    const std::string json = fs::path(mesh_path).replace_extension(".json").string();
    if(fs::is_regular_file(json, ec)) annotation_path = json;
  }
  if(annotation_path.empty())
    throw Usage_error("'mpm correspond' needs --annotation JSON naming the part types (no " +
                      fs::path(mesh_path).replace_extension(".json").string() + ")");

  // The annotation and labels found beside the mesh are inputs too.
  if(!fs::is_directory(output, ec)) refuse_overwriting(output + ".json", {annotation_path, labels});

  std::vector<std::string> warnings;
  Training_input input;
  context.progress.update("reading " + mesh_path, 0.);
  input.mesh = read_labeled_mesh(mesh_path, labels, &warnings);
  input.mesh.source = as_the_user_wrote(input.mesh.source); // `-`, not its temporary copy
  for(const std::string& w : warnings) context.progress.warning(w);
  validate_labeled_mesh(input.mesh);
  input.annotation = read_annotation(annotation_path);
  if(input.annotation.part_type_of_label.empty())
    throw Input_error(annotation_path, "parts", "no part types: nothing to put in correspondence");

  Learning_options options;
  options.progress = [&](const std::string& stage, double fraction) { context.progress.update(stage, fraction); };
  options.correspondence.refine = !args.flag("no-refine");
  options.correspondence.refinement_iterations =
    static_cast<int>(args.integer("refinement-iterations", options.correspondence.refinement_iterations));
  const Corresponded_training result = correspond_training_inputs({input}, options, true);

  // A directory (existing, or named with a trailing slash) gets TYPE_K.off
  // files and correspondence.json; anything else is a prefix.
  const bool directory = fs::is_directory(output, ec) || (!output.empty() && (output.back() == '/' || output.back() == '\\'));
  const auto path_of = [&](const std::string& stem, const std::string& extension) {
    return directory ? (fs::path(output) / (stem + extension)).string() : output + "_" + stem + extension;
  };
  const std::string summary_path = directory ? (fs::path(output) / "correspondence.json").string() : output + ".json";

  Json types = Json::array();
  std::size_t files = 0, written = 0;
  for(const auto& entry : result.types) files += entry.second.segments.size();
  for(const auto& [name, c] : result.types)
  {
    const std::vector<std::pair<int, int>>& refs = result.segments.at(name);
    Json segments = Json::array();
    for(std::size_t i = 0; i < c.segments.size(); ++i)
    {
      const Segment_correspondence& s = c.segments[i];
      Indexed_mesh mesh;
      mesh.points = s.positions;
      mesh.triangles = c.triangles;
      const std::string file = path_of(file_safe(name) + "_" + std::to_string(i), ".off");
      context.progress.update("writing " + file, double(written++) / files);
      ensure_parent_directory(file);
      write_mesh_file(mesh, file, nullptr, context.meshes);
      segments.push_back({{"label", refs[i].second},
                          {"file", file},
                          {"order", s.order},
                          {"iterations", s.iterations},
                          {"shape_space_regularizer", s.used_shape_space},
                          {"mirrored", s.mirrored},
                          {"automatic_landmarks", s.automatic_landmarks},
                          {"residual", s.residual}});
    }
    types.push_back({{"type", name},
                     {"template_vertices", c.segments.front().positions.rows()},
                     {"template_faces", c.triangles.size()},
                     {"segments", segments},
                     {"refinement_iterations", c.refinement_iterations},
                     {"before_refinement", energies_json(c.before)},
                     {"after_refinement", energies_json(c.after)}});
  }
  context.progress.done();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Json summary = {{"mesh", mesh_path},
                  {"labels", labels},
                  {"annotation", annotation_path},
                  {"types", types},
                  {"warnings", warnings},
                  {"time_seconds", seconds}};
  ensure_parent_directory(summary_path);
  internal::write_file_atomically(summary_path, [&](std::ostream& out) { out << summary.dump(2) << "\n"; });
  summary["summary"] = summary_path;
  if(context.json)
  {
    print_json(summary);
    return exit_ok;
  }
  std::cout << "Corresponded " << result.types.size() << " part type" << (result.types.size() == 1 ? "" : "s") << " of "
            << mesh_path << " in " << format_number(seconds, 3) << " s; summary: " << summary_path << "\n\n";
  Table table({"type", "segments", "template vertices", "residual (max)", "trace before", "trace after"},
              {false, true, true, true, true, true});
  for(const auto& [name, c] : result.types)
  {
    double worst = 0.;
    for(const Segment_correspondence& s : c.segments) worst = std::max(worst, s.residual);
    table.add_row({name, std::to_string(c.segments.size()), std::to_string(c.segments.front().positions.rows()),
                   format_number(worst), format_number(c.before.trace), format_number(c.after.trace)});
  }
  if(table.empty())
    std::cout << "  no part type has two or more segments\n";
  else
    table.print(std::cout);
  return exit_ok;
}

} // namespace

Command make_correspond_command()
{
  Command c;
  c.name = "correspond";
  c.summary = "put same-type parts with different triangulations in dense correspondence";
  c.synopsis = "MESH [--labels SEG] [--annotation JSON] -o OUTDIR_OR_PREFIX [options]";
  c.operand = "MESH";
  c.description =
    "Every part type of the annotation with two or more segments gets its first\n"
    "segment's connectivity on all of them (automatic landmarks from the seams and\n"
    "tips, the annotation's landmarks first; deformable ICP; refinement of\n"
    "trace(Sigma); see doc/MPM/Correspondence.md). Writes one OFF per segment\n"
    "(OUTDIR/TYPE_K.off or PREFIX_TYPE_K.off, K in label order) and a JSON summary\n"
    "(OUTDIR/correspondence.json or PREFIX.json): per type the ICP iterations,\n"
    "residuals and the refinement energies before and after. Labels and annotation\n"
    "default to MESH's .seg and .json siblings.";
  c.min_positionals = 1;
  c.max_positionals = 1;
  c.options = {
    {"output", 'o', Value_kind::output_prefix, "OUTDIR_OR_PREFIX", "", "output directory (existing or ending in /) or prefix (required)"},
    {"labels", 0, Value_kind::input_file, "SEG", "MESH.seg if present, else components", "part labels of MESH"},
    {"annotation", 0, Value_kind::input_file, "JSON", "MESH.json if present", "annotation naming the part types"},
    {"no-refine", 0, Value_kind::flag, "", "", "skip the refinement (trace(Sigma) minimization)"},
    {"refinement-iterations", 0, Value_kind::integer, "N", "40", "gradient steps of the refinement", 0, INT_MAX},
  };
  c.prefix_extensions = {".json"};
  c.run = run_correspond;
  return c;
}

} // namespace mpm
