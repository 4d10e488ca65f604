// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm cut MESH --cuts CUTS -o PREFIX`: cuts a mesh along cutting lines
// (shortest paths between a few user vertices) and writes the mesh with
// one part label per face, ready for `mpm learn`.
#include "cli.h"

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Mesh_cutting.h>
#include <CGAL/MPM/Mesh_io.h>

#include <cmath>
#include <iostream>
#include <map>

namespace mpm {

namespace {

// Labels are written per face and the geometry is copied unchanged, so a
// polygon the reader fan-triangulated would change both: refuse it.
void require_triangles(const CGAL::MPM::Mesh_file& file, const std::string& path)
{
  if(file.number_of_file_faces == file.mesh.number_of_faces()) return;
  std::map<int, int> triangles_of_face;
  for(int f : file.file_face) ++triangles_of_face[f];
  for(const auto& [face, triangles] : triangles_of_face)
    if(triangles > 1)
      throw CGAL::MPM::Input_error(path, "face " + std::to_string(face),
                                   "has " + std::to_string(triangles + 2) +
                                     " corners; 'mpm cut' needs a triangle mesh (triangulate it first)");
}

int run_cut(const Args& args, Context& context)
{
  using namespace CGAL::MPM;
  if(!args.has("cuts")) throw Usage_error("'mpm cut' needs --cuts CUTS");
  if(!args.has("output")) throw Usage_error("'mpm cut' needs -o PREFIX");
  const std::string mesh_path = args.positionals().front(), cuts_path = args.text("cuts");
  std::string prefix = args.text("output");
  for(const char* extension : {".off", ".seg"})
    if(prefix.size() > 4 && prefix.compare(prefix.size() - 4, 4, extension) == 0) prefix.resize(prefix.size() - 4);

  context.progress.update("reading " + mesh_path, 0.);
  const Mesh_file file = read_mesh_file(mesh_path);
  require_triangles(file, mesh_path);
  const Cut_specification spec = read_cut_specification(cuts_path);
  Cutting_options options;
  options.feature_weight = args.real("feature-weight", options.feature_weight);
  options.closed = !args.flag("open");

  context.progress.update("cutting", 0.3);
  const Cutting_result result = cut_mesh(file.mesh, spec, options, mesh_path);

  context.progress.update("writing files", 0.8);
  const std::string mesh_file = prefix + ".off", seg_file = prefix + ".seg";
  ensure_parent_directory(mesh_file);
  write_mesh_file(result.mesh.mesh, mesh_file, nullptr, context.meshes);
  write_seg_file(result.mesh.face_labels, seg_file);
  context.progress.done();

  std::map<int, int> faces_of_label;
  for(int label : result.mesh.face_labels) ++faces_of_label[label];
  Json parts = Json::array();
  for(const auto& [label, faces] : faces_of_label) {
    Json seed = nullptr;
    for(const Part_seed& p : spec.parts)
      if(p.label == label) seed = p.seed;
    parts.push_back({{"label", label}, {"faces", faces}, {"seed", seed}});
  }
  Json cuts = Json::array();
  for(std::size_t i = 0; i < spec.cuts.size(); ++i)
    cuts.push_back({{"name", spec.cuts[i].name},
                    {"closed", spec.cuts[i].closed.value_or(options.closed)},
                    {"points", spec.cuts[i].vertices.size()},
                    {"edges", result.paths[i].size() - 1},
                    {"length", result.lengths[i]},
                    {"path", result.paths[i]}});
  const Json summary = {
    {"mesh", mesh_path},
    {"cuts_file", cuts_path},
    {"feature_weight", options.feature_weight},
    {"vertices", file.mesh.number_of_vertices()},
    {"faces", file.mesh.number_of_faces()},
    {"parts", parts},
    {"cuts", cuts},
    {"files", {{"mesh", mesh_file}, {"labels", seg_file}}},
  };
  if(context.json) {
    print_json(summary);
    return exit_ok;
  }
  std::cout << "Cut " << mesh_path << " (" << file.mesh.number_of_vertices() << " vertices, "
            << file.mesh.number_of_faces() << " faces) along " << spec.cuts.size() << " cut"
            << (spec.cuts.size() == 1 ? "" : "s") << " into " << faces_of_label.size() << " part"
            << (faces_of_label.size() == 1 ? "" : "s") << "\n\n";
  Table cut_table({"#", "name", "closed", "points", "edges", "length"}, {true, false, false, true, true, true});
  for(std::size_t i = 0; i < cuts.size(); ++i)
    cut_table.add_row({std::to_string(i), spec.cuts[i].name, cuts[i]["closed"].get<bool>() ? "yes" : "no",
                       std::to_string(spec.cuts[i].vertices.size()), std::to_string(result.paths[i].size() - 1),
                       format_number(result.lengths[i])});
  cut_table.print(std::cout);
  std::cout << "\n";
  Table part_table({"label", "faces", "seed"}, {true, true, true});
  for(const Json& p : parts)
    part_table.add_row({std::to_string(p["label"].get<int>()), std::to_string(p["faces"].get<int>()),
                        p["seed"].is_null() ? "-" : std::to_string(p["seed"].get<int>())});
  part_table.print(std::cout);
  std::cout << "\nWrote " << mesh_file << ", " << seg_file << "\n";
  return exit_ok;
}

} // namespace

Command make_cut_command()
{
  Command c;
  c.name = "cut";
  c.summary = "cut a mesh into labelled parts along cutting lines";
  c.synopsis = "MESH --cuts CUTS [--feature-weight W] [--open] -o PREFIX";
  c.operand = "MESH";
  c.description =
    "MESH is a triangle mesh (OFF, OBJ, PLY or STL). CUTS is a cut file (JSON, see\n"
    "doc/MPM/File_formats.md): per cut a few vertices in order, joined by shortest\n"
    "paths along mesh edges that prefer concave creases; optional seeds name the\n"
    "labels of the regions. Writes PREFIX.off (the geometry, unchanged) and\n"
    "PREFIX.seg (one part label per face), the input 'mpm learn' reads.";
  c.min_positionals = c.max_positionals = 1;
  c.options = {
    {"output", 'o', Value_kind::output_prefix, "PREFIX", "", "output prefix (required; a trailing .off or .seg is dropped)"},
    {"cuts", 0, Value_kind::input_file, "CUTS", "", "cut file (required)"},
    {"feature-weight", 0, Value_kind::real, "W", "1",
     "how strongly cuts snap to concave creases; 0 = shortest edge paths", 0, HUGE_VAL},
    {"open", 0, Value_kind::flag, "", "closed loops",
     "cuts without a \"closed\" key run open, from border to border"},
  };
  c.prefix_extensions = {".off", ".seg"};
  c.run = run_cut;
  return c;
}

} // namespace mpm
