// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm graph MODEL -o G.json`: the part graph of a training example, to edit.
// `mpm assemble MODEL [--graph G.json] [edits] -o OUT`: assemble and embed a
// part graph, optionally edited on the command line.
#include "assembly_common.h"

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Assembly/Free_site_capping.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>

#include <climits>
#include <cmath>
#include <iostream>

namespace mpm {

namespace {

using namespace CGAL::MPM;

const char* const grammar_text =
  "The grammar is the model's learned rules plus, unless --observed-only, the\n"
  "derived repetition rules (a two-site segment docked to a copy of itself: what\n"
  "lengthens a finger) and bridging rules (the two neighbours of a two-site\n"
  "segment docked to each other: what shortens it), appended after the learned\n"
  "ones (doc/MPM/Part_graphs.md).";

int example_of(const Args& args, const Morphable_part_model& model, const std::string& path)
{
  const int example = static_cast<int>(args.integer("example", 0));
  if(example >= static_cast<int>(model.examples.size()))
    throw Input_error(path, "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  return example;
}

int run_graph(const Args& args, Context& context)
{
  const std::string path = args.positionals().front();
  if(!args.has("output")) throw Usage_error("'mpm graph' needs -o G.json");
  context.progress.update("loading " + path, 0.);
  int derived = 0;
  const Morphable_part_model model = load_model_with_grammar(path, args.flag("observed-only"), &derived);
  const int example = example_of(args, model, path);
  const Part_graph graph = part_graph_of_example(model, example);
  const std::string output = args.text("output");
  ensure_parent_directory(output);
  write_part_graph(model, graph, output);
  context.progress.done();
  const Json summary = {{"command", "graph"}, {"model", path}, {"example", example},
                        {"parts", graph.nodes.size()}, {"dockings", graph.edges.size()},
                        {"rules", model.rules.size()}, {"derived_rules", derived}, {"output", output}};
  if(context.json) print_json(summary);
  else
    std::cout << "Part graph of example " << example << " of " << path << ": " << graph.nodes.size() << " parts, "
              << graph.edges.size() << " dockings (" << model.rules.size() << " rules, " << derived
              << " derived)\nWrote " << output << "\n";
  return exit_ok;
}

std::pair<int, int> node_pair(const std::string& option, const std::string& value)
{
  const std::size_t colon = value.find(':');
  try {
    if(colon == std::string::npos) throw std::invalid_argument("");
    std::size_t end_a = 0, end_b = 0;
    const int a = std::stoi(value.substr(0, colon), &end_a);
    const int b = std::stoi(value.substr(colon + 1), &end_b);
    if(end_a != colon || end_b != value.size() - colon - 1 || a < 0 || b < 0) throw std::invalid_argument("");
    return {a, b};
  } catch(const std::exception&) {
    throw Usage_error("option --" + option + ": '" + value + "' is not two node indices A:B");
  }
}

int index_of(const std::string& option, const std::string& value)
{
  try {
    std::size_t end = 0;
    const int v = std::stoi(value, &end);
    if(end != value.size() || v < 0) throw std::invalid_argument("");
    return v;
  } catch(const std::exception&) {
    throw Usage_error("option --" + option + ": '" + value + "' is not a non-negative index");
  }
}

// Applies the edit options in command-line order; returns their descriptions.
std::vector<std::string> apply_edits(const Args& args, const Morphable_part_model& model, Part_graph& graph)
{
  std::vector<std::string> done;
  for(const Arg_item& item : args.items)
  {
    const std::string& o = item.option;
    if(o == "insert")
    {
      const int n = insert_segment(model, graph, index_of(o, item.value));
      const int crossings = choose_segment_shape(model, graph, n);
      done.push_back("inserted node " + std::to_string(n) + " (" + model.types[graph.nodes[n].type].name +
                     ") into edge " + item.value + ", shaped to cross the rest least (" + std::to_string(crossings) +
                     " face pairs intersect when placed)");
    }
    else if(o == "remove-segment")
    {
      remove_segment(model, graph, index_of(o, item.value));
      done.push_back("removed segment " + item.value);
    }
    else if(o == "remove-branch")
    {
      const int root = root_node(graph);
      const std::size_t before = graph.nodes.size();
      remove_branch(model, graph, index_of(o, item.value), root);
      done.push_back("removed the branch at " + item.value + " (" + std::to_string(before - graph.nodes.size()) +
                     " parts)");
    }
    else if(o == "duplicate-branch")
    {
      const auto [node, target] = node_pair(o, item.value);
      const int copy = duplicate_branch(model, graph, node, root_node(graph), target);
      done.push_back("duplicated the branch at " + std::to_string(node) + " onto node " + std::to_string(target) +
                     " (copy at node " + std::to_string(copy) + ")");
    }
    else if(o == "close")
    {
      const auto [a, b] = node_pair(o, item.value);
      const int e = close_cycle(model, graph, a, b);
      done.push_back("docked nodes " + std::to_string(a) + " and " + std::to_string(b) + " (edge " +
                     std::to_string(e) + ", rule " + std::to_string(graph.edges[e].rule) + ")");
    }
  }
  return done;
}

int run_assemble(const Args& args, Context& context)
{
  const std::string path = args.positionals().front();
  if(!args.has("output")) throw Usage_error("'mpm assemble' needs -o OUT");
  const std::string output = args.text("output");
  check_mesh_output("output", output);
  context.progress.update("loading " + path, 0.);
  const Morphable_part_model model = load_model_with_grammar(path, args.flag("observed-only"));
  const std::string graph_file = args.text("graph");
  Part_graph graph = graph_file.empty() ? part_graph_of_example(model, example_of(args, model, path))
                                        : read_part_graph(graph_file, model);
  const std::vector<std::string> edits = apply_edits(args, model, graph);
  if(args.has("save-graph"))
  {
    ensure_parent_directory(args.text("save-graph"));
    write_part_graph(model, graph, args.text("save-graph"));
  }
  // Measured: about 2.7 kB per vertex of the assembly (the factorization
  // dominates); a graph of a million parts is refused, not attempted.
  double vertices = 0.;
  for(const Part_node& node : graph.nodes) vertices += model.types[node.type].number_of_vertices;
  check_memory("graph", std::to_string(graph.nodes.size()) + " parts (" + format_number(vertices) + " vertices)",
               4000. * vertices);
  Assembly_options options;
  options.solver.max_iterations = static_cast<int>(args.integer("iterations", options.solver.max_iterations));
  options.solver.tolerance = args.real("tolerance", options.solver.tolerance);
  context.progress.update("assembling " + std::to_string(graph.nodes.size()) + " parts", 0.2);
  options.solver.iteration_callback =
    iteration_progress(context.progress, "embedding " + std::to_string(graph.nodes.size()) + " parts", 0.3, 0.9,
                       options.solver.max_iterations);
  Assembly assembly = assemble(model, graph, options);
  // The training graph itself, unedited, is its own reference.
  const bool is_training_graph = graph_file.empty() && edits.empty();
  context.progress.update("comparing with the training example's graph", 0.9);
  const double reference = is_training_graph ? assembly.energy_per_part()
                                             : training_energy_per_part(model, example_of(args, model, path), options);
  std::vector<std::string> closed;
  for(const Arg_item& item : args.items)
    if(item.option == "close") closed.push_back("--close " + item.value);
  const std::vector<std::string> warnings = assembly_doubts(assembly, reference, closed);
  const std::size_t solved_faces = assembly.mesh.triangles.size();
  const int capped = args.flag("keep-holes") ? 0 : cap_free_sites(model, assembly);
  const std::size_t cap_faces = assembly.mesh.triangles.size() - solved_faces;
  context.progress.update("writing " + output, 0.95);
  write_assembly_mesh(assembly, output, context.meshes);
  context.progress.done();
  for(const std::string& w : warnings) context.progress.warning(w);
  const int status = warnings.empty() ? exit_ok : exit_warning;

  Json summary = {{"command", "assemble"}, {"model", path},
                  {"graph", graph_file.empty() ? Json("example " + std::to_string(args.integer("example", 0)))
                                               : Json(graph_file)},
                  {"edits", edits}};
  const Json details = assembly_summary(model, assembly);
  for(const auto& [key, value] : details.items()) summary[key] = value;
  summary["training_energy_per_part"] = reference;
  summary["capped_free_sites"] = capped;
  summary["cap_faces"] = cap_faces;
  summary["warnings"] = warnings;
  summary["output"] = output;
  if(args.has("save-graph")) summary["saved_graph"] = args.text("save-graph");
  if(context.json)
  {
    print_json(summary);
    return status;
  }
  std::cout << "Assembled " << assembly.graph.nodes.size() << " parts, " << assembly.graph.edges.size()
            << " dockings of " << path << ": " << assembly.mesh.number_of_vertices() << " vertices, "
            << assembly.mesh.number_of_faces() << " faces\n";
  for(const std::string& e : edits) std::cout << "  edit              " << e << "\n";
  if(capped > 0)
    std::cout << "  capped            " << capped << " free site" << (capped > 1 ? "s" : "") << " (a removed branch's hole; "
              << cap_faces << " faces)\n";
  std::cout << "  iterations        " << assembly.report.iterations
            << (assembly.report.converged ? " (converged)" : " (not converged: iteration cap)") << "\n"
            << "  residual energy   " << format_number(assembly.residual_energy, 6) << " ("
            << format_number(assembly.energy_per_part(), 6) << " per part; the training example's graph: "
            << format_number(reference, 3) << ")\n"
            << "  time              set-up " << format_number(assembly.setup_ms) << " ms, solve "
            << format_number(assembly.solve_ms) << " ms\n";
  Table table({"node", "type", "energy"}, {true, false, true});
  for(std::size_t i = 0; i < assembly.graph.nodes.size(); ++i)
    table.add_row({std::to_string(i), model.types[assembly.graph.nodes[i].type].name,
                   format_number(assembly.part_energies[i], 4)});
  std::cout << "Energy per part:\n";
  table.print(std::cout);
  std::cout << "Wrote " << output << "\n";
  if(args.has("save-graph")) std::cout << "Wrote " << args.text("save-graph") << "\n";
  return status;
}

} // namespace

Command make_graph_command()
{
  Command c;
  c.name = "graph";
  c.summary = "write the part graph of a training example (to edit and assemble)";
  c.synopsis = "MODEL [--example N] [--observed-only] -o G.json";
  c.operand = "MODEL";
  c.description =
    std::string("Writes the instances (type, shape coordinates) and dockings (rule, sites) of a\n"
                "training example in the part-graph format (doc/MPM/Part_graphs.md).\n") + grammar_text;
  c.min_positionals = c.max_positionals = 1;
  c.options = {
    {"output", 'o', Value_kind::output_file, "G.json", "", "part graph file to write (required)"},
    {"example", 0, Value_kind::integer, "N", "0", "training example", 0, INT_MAX},
    {"observed-only", 0, Value_kind::flag, "", "", "the learned rules only (no derived repetition or bridging rules)"},
  };
  c.run = run_graph;
  return c;
}

Command make_assemble_command()
{
  const Embedding_options defaults;
  Command c;
  c.name = "assemble";
  c.summary = "assemble and embed a part graph (new arrangements of the learned parts)";
  c.synopsis = "MODEL [--graph G.json | --example N] [edits] -o OUT [--save-graph G2.json]";
  c.operand = "MODEL";
  c.description =
    std::string(
      "Assembles the part graph G.json (default: the graph of training example N),\n"
      "after the edit options in command-line order (indices refer to the graph as it\n"
      "is when the edit applies): seam vertices are shared, each part starts at its\n"
      "type's mean plus its coordinates placed rigidly on its neighbours, and the\n"
      "embedding solver minimizes the distortion. Prints the residual energy (total,\n"
      "per part, per node). OUT is .off, .obj, .ply or .stl (PLY: per-face colours by type).\n"
      "An embedding that stops at the iteration cap, or whose energy per part is over\n"
      "1000 times that of the training example's graph (a cycle that cannot close),\n"
      "is written with a warning and exit status 3. The hole a removed branch leaves\n"
      "at a free site is filled with a smooth cap (unless --keep-holes).\n") +
    grammar_text;
  c.min_positionals = c.max_positionals = 1;
  c.options = {
    {"output", 'o', Value_kind::output_file, "OUT", "", "mesh to write: .off, .obj, .ply or .stl (required)"},
    {"graph", 0, Value_kind::input_file, "G.json", "", "part graph file (default: the training example's)"},
    {"example", 0, Value_kind::integer, "N", "0", "training example whose graph is used without --graph", 0, INT_MAX},
    {"insert", 0, Value_kind::text, "EDGE", "", "insert a segment into docking EDGE", -HUGE_VAL, HUGE_VAL, false, true},
    {"remove-segment", 0, Value_kind::text, "NODE", "", "remove a two-docking segment, reconnecting its neighbours",
     -HUGE_VAL, HUGE_VAL, false, true},
    {"remove-branch", 0, Value_kind::text, "NODE", "", "remove NODE and everything beyond it from the root",
     -HUGE_VAL, HUGE_VAL, false, true},
    {"duplicate-branch", 0, Value_kind::text, "NODE:TARGET", "",
     "copy the branch at NODE and dock it at a free site of TARGET", -HUGE_VAL, HUGE_VAL, false, true},
    {"close", 0, Value_kind::text, "A:B", "", "dock nodes A and B at free sites (close a cycle)", -HUGE_VAL,
     HUGE_VAL, false, true},
    {"save-graph", 0, Value_kind::output_file, "G2.json", "", "also write the edited part graph"},
    {"observed-only", 0, Value_kind::flag, "", "", "the learned rules only (no derived repetition or bridging rules)"},
    {"keep-holes", 0, Value_kind::flag, "", "", "leave the holes at free sites open (no cap)"},
    {"iterations", 0, Value_kind::integer, "N", std::to_string(defaults.max_iterations),
     "maximum number of solver iterations", 1, INT_MAX},
    {"tolerance", 0, Value_kind::real, "T", format_number(defaults.tolerance),
     "stop when the energy decreases by less than this fraction", 0, HUGE_VAL},
  };
  c.run = run_assemble;
  return c;
}

} // namespace mpm
