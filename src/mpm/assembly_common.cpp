// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "assembly_common.h"

#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Part_colors.h>
#include <CGAL/MPM/internal/Mesh_file_checks.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>

#include <algorithm>

namespace mpm {

using CGAL::MPM::internal::lower_extension;

CGAL::MPM::Morphable_part_model load_model_with_grammar(const std::string& path, bool observed_only, int* derived)
{
  CGAL::MPM::Morphable_part_model model = CGAL::MPM::load_model(path);
  int added = 0;
  if(!observed_only)
    added = static_cast<int>(CGAL::MPM::add_repetition_rules(model).size() + CGAL::MPM::add_bridging_rules(model).size());
  if(derived) *derived = added;
  return model;
}

void check_mesh_output(const std::string& option, const std::string& path)
{
  const std::string e = lower_extension(path);
  if(e != ".off" && e != ".obj" && e != ".ply" && e != ".stl")
    throw Usage_error("option --" + option + ": '" + path + "' must end in .off, .obj, .ply or .stl");
}

void write_assembly_mesh(const CGAL::MPM::Assembly& assembly, const std::string& path,
                         const CGAL::MPM::Mesh_write_options& options)
{
  ensure_parent_directory(path);
  if(lower_extension(path) != ".ply")
  {
    CGAL::MPM::write_mesh_file(assembly.mesh, path, nullptr, options);
    return;
  }
  Eigen::Matrix<unsigned char, Eigen::Dynamic, 3> colors(assembly.mesh.number_of_faces(), 3);
  for(int f = 0; f < colors.rows(); ++f)
  {
    const CGAL::MPM::Rgb_color c = CGAL::MPM::part_type_color(assembly.face_types[f]);
    colors.row(f) << c[0], c[1], c[2];
  }
  CGAL::MPM::write_mesh_file(assembly.mesh, path, &colors, options);
}

double training_energy_per_part(const CGAL::MPM::Morphable_part_model& model, int example,
                                CGAL::MPM::Assembly_options options)
{
  options.solver.iteration_callback = nullptr;
  return CGAL::MPM::assemble(model, CGAL::MPM::part_graph_of_example(model, example), options).energy_per_part();
}

std::vector<std::string> assembly_doubts(const CGAL::MPM::Assembly& a, double reference,
                                         const std::vector<std::string>& closed)
{
  // Below `negligible` an energy per part is rounding, whatever the
  // reference: a perfectly repeating model leaves 0. Measured: inserted
  // segments leave 0.5 to 2 times the reference, a row of three hexa-grid
  // tiles closed into a cycle 9,500 times.
  constexpr double negligible = 1e-6, factor = 1e3;
  std::string cause;
  for(const std::string& c : closed) cause += (cause.empty() ? " (closing " : ", ") + c;
  if(!cause.empty()) cause += ": the sites may be too far apart to meet)";
  std::vector<std::string> doubts;
  if(!a.report.converged)
    doubts.push_back("the embedding stopped at the iteration cap (" + std::to_string(a.report.iterations) +
                     ") before converging" + cause + "; --iterations raises the cap");
  const double per_part = a.energy_per_part();
  if(per_part > factor * std::max(reference, negligible))
    doubts.push_back("residual energy per part " + format_number(per_part, 3) + " is " +
                     format_number(per_part / std::max(reference, negligible), 2) +
                     " times that of the training example's graph (" + format_number(reference, 3) +
                     "): the graph asks for a shape the parts cannot take" + cause);
  return doubts;
}

Json assembly_summary(const CGAL::MPM::Morphable_part_model& model, const CGAL::MPM::Assembly& a)
{
  Json parts = Json::array();
  for(std::size_t i = 0; i < a.graph.nodes.size(); ++i)
    parts.push_back({{"node", i}, {"type", model.types[a.graph.nodes[i].type].name}, {"energy", a.part_energies.at(i)}});
  Json dockings = Json::array();
  for(std::size_t k = 0; k < a.graph.edges.size(); ++k)
    dockings.push_back({{"edge", k}, {"first", a.graph.edges[k].first}, {"second", a.graph.edges[k].second},
                        {"rule", a.graph.edges[k].rule}, {"energy", a.docking_energies.at(k)}});
  return {
    {"parts", a.graph.nodes.size()},
    {"dockings", a.graph.edges.size()},
    {"vertices", a.mesh.number_of_vertices()},
    {"faces", a.mesh.number_of_faces()},
    {"iterations", a.report.iterations},
    {"converged", a.report.converged},
    {"residual_energy", a.residual_energy},
    {"energy_per_part", a.energy_per_part()},
    {"setup_ms", a.setup_ms},
    {"solve_ms", a.solve_ms},
    {"part_energies", parts},
    {"docking_energies", dockings},
  };
}

} // namespace mpm
