// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm cut MESH --cuts CUTS -o PREFIX`: cuts a mesh along cutting lines
// (shortest paths between a few user vertices) and writes the mesh with
// one part label per face, ready for `mpm learn`. `mpm cut MESH --at V ...`
// finds the cut around the limb at each clicked vertex instead, and
// `mpm cut MESH --auto` proposes the joints itself.
#include "cli.h"

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Cutting/Joint_proposal.h>
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/IO/Mesh_io.h>

#include <climits>
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

struct Written_cut_mesh
{
  std::string mesh_file, seg_file;
  std::map<int, int> faces_of_label;
};

// Writes PREFIX.off and PREFIX.seg; returns their names and the parts' sizes.
Written_cut_mesh write_cut_mesh(const CGAL::MPM::Labeled_mesh& mesh, const std::string& prefix, Context& context)
{
  context.progress.update("writing files", 0.8);
  Written_cut_mesh w{prefix + ".off", prefix + ".seg", {}};
  ensure_parent_directory(w.mesh_file);
  CGAL::MPM::write_mesh_file(mesh.mesh, w.mesh_file, nullptr, context.meshes);
  CGAL::MPM::write_seg_file(mesh.face_labels, w.seg_file);
  context.progress.done();
  for(int label : mesh.face_labels) ++w.faces_of_label[label];
  return w;
}

Json joint_cuts_json(const std::vector<CGAL::MPM::Joint_cut>& cuts)
{
  Json r = Json::array();
  for(const CGAL::MPM::Joint_cut& c : cuts)
    r.push_back({{"vertex", c.vertex}, {"length", c.length}, {"edges", c.path.size() - 1},
                 {"limb_radius", c.limb_radius}, {"shift", c.shift},
                 {"centre", {c.centre.x(), c.centre.y(), c.centre.z()}}, {"path", c.path}});
  return r;
}

void print_joint_cuts(const std::vector<CGAL::MPM::Joint_cut>& cuts)
{
  Table table({"vertex", "length", "edges", "limb radius", "moved", "centre"}, {true, true, true, true, true, false});
  for(const CGAL::MPM::Joint_cut& c : cuts)
    table.add_row({std::to_string(c.vertex), format_number(c.length), std::to_string(c.path.size() - 1),
                   format_number(c.limb_radius), format_number(c.shift) + " along the limb",
                   format_number(c.centre.x()) + " " + format_number(c.centre.y()) + " " + format_number(c.centre.z())});
  table.print(std::cout);
}

CGAL::MPM::Joint_cutting_options joint_cutting_options(const Args& args)
{
  CGAL::MPM::Joint_cutting_options options;
  options.feature_weight = args.real("feature-weight", options.feature_weight);
  options.search_range = args.real("search-range", options.search_range);
  options.snap_band = args.real("snap-band", options.snap_band);
  return options;
}

// `--at V ...`: one cut per clicked vertex, found from the curve skeleton.
int run_cut_at(const Args& args, Context& context, const CGAL::MPM::Mesh_file& file, const std::string& mesh_path,
               const std::string& prefix)
{
  using namespace CGAL::MPM;
  std::vector<int> clicks;
  for(const Arg_item& item : args.items)
    if(item.option == "at") clicks.push_back(std::stoi(item.value));
  context.progress.update("skeleton and sections", 0.2);
  const Joint_cutting_result result = cut_at_vertices(file.mesh, clicks, joint_cutting_options(args), mesh_path);
  const auto [mesh_file, seg_file, faces_of_label] = write_cut_mesh(result.mesh, prefix, context);
  if(context.json) {
    print_json({{"mesh", mesh_path}, {"vertices", file.mesh.number_of_vertices()},
                {"faces", file.mesh.number_of_faces()}, {"parts", faces_of_label.size()},
                {"cuts", joint_cuts_json(result.cuts)}, {"files", {{"mesh", mesh_file}, {"labels", seg_file}}}});
    return exit_ok;
  }
  std::cout << "Cut " << mesh_path << " (" << file.mesh.number_of_vertices() << " vertices) at " << clicks.size()
            << " clicked vert" << (clicks.size() == 1 ? "ex" : "ices") << " into " << faces_of_label.size()
            << " parts\n\n";
  print_joint_cuts(result.cuts);
  std::cout << "\nWrote " << mesh_file << ", " << seg_file << "\n";
  return exit_ok;
}

// `--auto`: joints proposed from the curve skeleton, then cut as clicks.
int run_cut_auto(const Args& args, Context& context, const CGAL::MPM::Mesh_file& file, const std::string& mesh_path,
                 const std::string& prefix)
{
  using namespace CGAL::MPM;
  Joint_proposal_options options;
  options.cutting = joint_cutting_options(args);
  options.sensitivity = args.real("sensitivity", options.sensitivity);
  context.progress.update("skeleton, limbs and joints", 0.2);
  const Joint_proposal proposal = cut_at_proposed_joints(file.mesh, options, mesh_path);
  const auto [mesh_file, seg_file, faces_of_label] = write_cut_mesh(proposal.cutting.mesh, prefix, context);
  if(context.json) {
    print_json({{"mesh", mesh_path}, {"vertices", file.mesh.number_of_vertices()},
                {"faces", file.mesh.number_of_faces()}, {"sensitivity", options.sensitivity},
                {"limbs", proposal.limbs}, {"proposed", proposal.joints.size()}, {"parts", faces_of_label.size()},
                {"cuts", joint_cuts_json(proposal.cutting.cuts)},
                {"files", {{"mesh", mesh_file}, {"labels", seg_file}}}});
    return exit_ok;
  }
  std::cout << "Cut " << mesh_path << " (" << file.mesh.number_of_vertices() << " vertices) at "
            << proposal.cutting.cuts.size() << " proposed joints on " << proposal.limbs << " limbs into "
            << faces_of_label.size() << " parts (sensitivity " << format_number(options.sensitivity) << ")\n\n";
  print_joint_cuts(proposal.cutting.cuts);
  if(!proposal.cutting.skipped.empty())
    std::cout << "\n" << proposal.cutting.skipped.size() << " proposed joints could not be cut and were left out\n";
  std::cout << "\nWrote " << mesh_file << ", " << seg_file << "\n";
  return exit_ok;
}

int run_cut(const Args& args, Context& context)
{
  using namespace CGAL::MPM;
  if(int(args.has("cuts")) + int(args.has("at")) + int(args.flag("auto")) != 1)
    throw Usage_error("'mpm cut' needs one of --cuts CUTS, --at V or --auto");
  if(!args.has("output")) throw Usage_error("'mpm cut' needs -o PREFIX");
  const std::string mesh_path = args.positionals().front();
  std::string prefix = args.text("output");
  for(const char* extension : {".off", ".seg"})
    if(prefix.size() > 4 && prefix.compare(prefix.size() - 4, 4, extension) == 0) prefix.resize(prefix.size() - 4);

  context.progress.update("reading " + mesh_path, 0.);
  const Mesh_file file = read_mesh_file(mesh_path);
  require_triangles(file, mesh_path);
  if(args.has("at")) return run_cut_at(args, context, file, mesh_path, prefix);
  if(args.flag("auto")) return run_cut_auto(args, context, file, mesh_path, prefix);
  const std::string cuts_path = args.text("cuts");
  const Cut_specification spec = read_cut_specification(cuts_path);
  Cutting_options options;
  options.feature_weight = args.real("feature-weight", options.feature_weight);
  options.closed = !args.flag("open");

  context.progress.update("cutting", 0.3);
  const Cutting_result result = cut_mesh(file.mesh, spec, options, mesh_path);

  const auto [mesh_file, seg_file, faces_of_label] = write_cut_mesh(result.mesh, prefix, context);
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
  c.summary = "cut a mesh into labelled parts along cutting lines or at clicked joints";
  c.synopsis = "MESH (--cuts CUTS | --at V [--at V ...] | --auto [--sensitivity S]) [--feature-weight W] [--open]\n"
               "       [--search-range R] [--snap-band B] -o PREFIX";
  c.operand = "MESH";
  c.description =
    "MESH is a triangle mesh (OFF, OBJ, PLY or STL). CUTS is a cut file (JSON, see\n"
    "doc/MPM/File_formats.md): per cut a few vertices in order, joined by shortest\n"
    "paths along mesh edges that prefer concave creases; optional seeds name the\n"
    "labels of the regions. With --at instead, each given vertex is one click per\n"
    "joint: the cut is the closed loop around the limb there (the limb's axis from\n"
    "the curve skeleton, the section across it through V, then the loop through V\n"
    "along the crease within --snap-band limb radii of that section, traced like a\n"
    "cut line); the mesh must be closed and connected. With --auto, the joints are\n"
    "proposed: the skeleton's long branches are limbs, cut where they leave the\n"
    "body and where they narrow or crease. Writes\n"
    "PREFIX.off (the geometry, unchanged) and PREFIX.seg (one part label per face),\n"
    "the input 'mpm learn' reads.";
  c.min_positionals = c.max_positionals = 1;
  c.options = {
    {"output", 'o', Value_kind::output_prefix, "PREFIX", "", "output prefix (required; a trailing .off or .seg is dropped)"},
    {"cuts", 0, Value_kind::input_file, "CUTS", "", "cut file (this, --at or --auto is required)"},
    {"at", 0, Value_kind::integer, "V", "", "a vertex next to a joint: cut around the limb there (repeat per joint)", 0,
     INT_MAX, false, true},
    {"auto", 0, Value_kind::flag, "", "", "propose the joints: limbs from the curve skeleton, joints at their creases"},
    {"sensitivity", 0, Value_kind::real, "S", "0.5",
     "with --auto: 0 cuts limbs off the body only, higher proposes more joints along them", 0, 1},
    {"search-range", 0, Value_kind::real, "R", "0.5",
     "with --at: how far, in limb radii, to look for a small section when the one at V runs into the body", 0, HUGE_VAL},
    {"snap-band", 0, Value_kind::real, "B", "0.5",
     "with --at or --auto: how far, in limb radii, a cut may leave the section through V to follow the crease; "
     "0 keeps the section", 0, HUGE_VAL},
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
