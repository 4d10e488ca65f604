// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Part graphs and their edits, assembly and spawning.
#include "arrays.h"
#include "bindings.h"
#include "model_data.h"

#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Assembly/Free_site_capping.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>

#include <pybind11/stl.h>

namespace mpm_python {

namespace {

using namespace CGAL::MPM;

void check_node(const Part_graph& graph, int node, const std::string& name)
{
  if(node < 0 || node >= int(graph.nodes.size()))
    throw py::value_error(name + ": node " + std::to_string(node) + " does not exist (the graph has " +
                          std::to_string(graph.nodes.size()) + " nodes)");
}

py::list node_list(const Morphable_part_model* model, const Part_graph& graph)
{
  py::list nodes;
  for(const Part_node& n : graph.nodes)
  {
    py::dict d(py::arg("type_index") = n.type, py::arg("label") = n.label,
               py::arg("coordinates") = vector_array(n.coordinates), py::arg("motion") = motion_dict(n.motion));
    if(model != nullptr && n.type >= 0 && n.type < int(model->types.size())) d["type"] = model->types[n.type].name;
    nodes.append(d);
  }
  return nodes;
}

py::list edge_list(const Part_graph& graph)
{
  py::list edges;
  for(const Part_edge& e : graph.edges)
    edges.append(py::dict(py::arg("first") = e.first, py::arg("second") = e.second, py::arg("rule") = e.rule,
                          py::arg("coordinates") = vector_array(e.coordinates)));
  return edges;
}

py::dict assembly_dict(Assembly&& a)
{
  return py::dict(py::arg("V") = points_array(std::move(a.mesh.points)),
                  py::arg("F") = triangles_array(std::move(a.mesh.triangles)),
                  py::arg("initial_V") = points_array(std::move(a.initial_positions)),
                  py::arg("face_nodes") = int_array(std::move(a.face_nodes)),
                  py::arg("face_types") = int_array(std::move(a.face_types)),
                  py::arg("residual_energy") = a.residual_energy, py::arg("energy_per_part") = a.energy_per_part(),
                  py::arg("part_energies") = double_array(a.part_energies),
                  py::arg("docking_energies") = double_array(a.docking_energies),
                  py::arg("iterations") = a.report.iterations, py::arg("converged") = a.report.converged,
                  py::arg("energies") = double_array(a.report.energies), py::arg("setup_ms") = a.setup_ms,
                  py::arg("solve_ms") = a.solve_ms);
}

Assembly_options assembly_options(bool solve, int max_iterations)
{
  Assembly_options options;
  options.solve = solve;
  options.solver.max_iterations = max_iterations;
  return options;
}

void bind_part_graph(py::module_& m)
{
  py::class_<Part_graph>(m, "PartGraph", R"doc(A part graph: part instances (nodes) docked by rules (edges).

Get one with part_graph(model, example) or PartGraph.from_json(); edit it
with insert_segment(), remove_segment(), remove_branch(), duplicate_branch(),
close_cycle(); embed it with assemble().)doc")
    .def_property_readonly("nodes", [](const Part_graph& g) { return node_list(nullptr, g); },
                           "Nodes, one dict each: type_index, label, coordinates, motion.")
    .def("node_types", [](const Part_graph& g, const Morphable_part_model& model) { return node_list(&model, g); },
         py::arg("model"), "Nodes as `nodes` gives them, with their type names in `model`.")
    .def_property_readonly("edges", &edge_list, "Edges, one dict each: first, second (nodes), rule, coordinates.")
    .def("to_json", [](const Part_graph& g, const Morphable_part_model& model) { return part_graph_to_json(model, g); },
         py::arg("model"), "The graph in the part graph file format (JSON text).")
    .def_static("from_json", [](const std::string& text, const Morphable_part_model& model) {
      return parse_part_graph(text, model, "json"); }, py::arg("text"), py::arg("model"),
                "Parses and validates a part graph in the JSON file format against `model`.")
    .def("copy", [](const Part_graph& g) { return Part_graph(g); }, "An independent copy.")
    .def("__repr__", [](const Part_graph& g) {
      return "<cgal_mpm.PartGraph: " + std::to_string(g.nodes.size()) + " nodes, " + std::to_string(g.edges.size()) +
             " edges>"; });

  m.def("part_graph", [](const Morphable_part_model& model, int example) { return part_graph_of_example(model, example); },
        py::arg("model"), py::arg("example") = 0, "The part graph of a training example, with its learned coordinates.");
  m.def("validate_part_graph", [](const Morphable_part_model& model, const Part_graph& graph) {
    validate_part_graph(model, graph); }, py::arg("model"), py::arg("graph"),
        "Raises InputError naming the node or edge when the graph breaks the model's grammar.");
  m.def("add_repetition_rules", &add_repetition_rules, py::arg("model"),
        "Adds to the model the repetition rule of every two-site part type (a finger segment docked to "
        "another of its type), so chains can grow. Returns the new rules' indices.");
  m.def("add_bridging_rules", &add_bridging_rules, py::arg("model"),
        "Adds to the model, for every segment of a training example (a part docked to exactly two others), a "
        "rule docking its two neighbours to each other (a proximal phalanx to a fingertip), so segments can be "
        "removed. Returns the new rules' indices.");
  m.def("root_node", &root_node, py::arg("graph"), "The node with the most dockings (the palm, the body).");
  m.def("insert_segment", [](const Morphable_part_model& model, Part_graph& graph, int edge, int type, bool choose_shape) {
    if(edge < 0 || edge >= int(graph.edges.size()))
      throw py::value_error("edge: " + std::to_string(edge) + " does not exist");
    const int node = insert_segment(model, graph, edge, type);
    if(choose_shape) choose_segment_shape(model, graph, node);
    return node; },
        py::arg("model"), py::arg("graph"), py::arg("edge"), py::arg("type") = -1, py::arg("choose_shape") = true,
        "Inserts a segment into docking `edge` (changes graph); returns the new node. With choose_shape, "
        "its shape is then the one that crosses the rest least (choose_segment_shape).");
  m.def("choose_segment_shape", [](const Morphable_part_model& model, Part_graph& graph, int node) {
    check_node(graph, node, "node");
    return choose_segment_shape(model, graph, node); }, py::arg("model"), py::arg("graph"), py::arg("node"),
        "Gives `node` the coordinates (its own, the mean or a training instance's) whose rigid placement "
        "crosses the rest least; returns the intersecting face pairs of that placement.");
  m.def("remove_segment", [](const Morphable_part_model& model, Part_graph& graph, int node) {
    check_node(graph, node, "node");
    return remove_segment(model, graph, node); }, py::arg("model"), py::arg("graph"), py::arg("node"),
        "Removes a node with two dockings and docks its neighbours; returns old -> new node indices.");
  m.def("remove_branch", [](const Morphable_part_model& model, Part_graph& graph, int node, int root) {
    check_node(graph, node, "node");
    check_node(graph, root, "root");
    return remove_branch(model, graph, node, root); }, py::arg("model"), py::arg("graph"), py::arg("node"),
        py::arg("root"), "Removes `node` and what hangs beyond it seen from `root`; returns old -> new indices.");
  m.def("duplicate_branch", [](const Morphable_part_model& model, Part_graph& graph, int node, int root, int target,
                               int target_site) {
    check_node(graph, node, "node");
    check_node(graph, root, "root");
    check_node(graph, target, "target");
    return duplicate_branch(model, graph, node, root, target, target_site); },
        py::arg("model"), py::arg("graph"), py::arg("node"), py::arg("root"), py::arg("target"),
        py::arg("target_site") = -1,
        "Copies the branch at `node` (seen from `root`) and docks it to `target`; returns the copy of `node`.");
  m.def("close_cycle", [](const Morphable_part_model& model, Part_graph& graph, int a, int b) {
    check_node(graph, a, "a");
    check_node(graph, b, "b");
    return close_cycle(model, graph, a, b); }, py::arg("model"), py::arg("graph"), py::arg("a"), py::arg("b"),
        "Docks nodes a and b at free sites a rule docks; returns the new edge.");
}

} // namespace

void bind_assembly(py::module_& m)
{
  bind_part_graph(m);

  m.def("assemble", [](const Morphable_part_model& model, const Part_graph& graph, bool solve, int max_iterations,
                       const py::object& callback, bool cap) {
    Python_callbacks callbacks;
    Assembly_options options = assembly_options(solve, max_iterations);
    options.solver.iteration_callback = callbacks.wrap<int, double>(callback);
    options.solver.cancel = callbacks.flag();
    return assembly_dict(callbacks.run([&] {
      Assembly a = assemble(model, graph, options);
      if(cap) cap_free_sites(model, a);
      return a;
    })); },
        py::arg("model"), py::arg("graph"), py::arg("solve") = true, py::arg("max_iterations") = 100,
        py::arg("callback") = py::none(), py::arg("cap_free_sites") = false,
        R"doc(Assembles a part graph and embeds it seamlessly.

Returns {"V", "F", "initial_V" (the rigid placement), "face_nodes",
"face_types", "residual_energy", "energy_per_part", "part_energies",
"docking_energies", "iterations", "converged", "energies", "setup_ms",
"solve_ms"}. solve=False stops after the rigid placement. callback(iteration,
energy) is called after each iteration of the solver; raising in it stops
the assembly and re-raises. cap_free_sites=True fills the hole a removed
branch leaves at a free site (cap_free_sites() in C++): "V", "F",
"face_nodes" and "face_types" then include the cap. Releases the GIL.)doc");

  m.def("spawn", [](const Morphable_part_model& model, const Part_graph& start, int count, unsigned seed,
                    const py::object& progress) {
    Python_callbacks callbacks;
    Spawn_options options;
    options.count = count;
    options.seed = seed;
    options.progress = callbacks.wrap<int, int>(progress);
    options.assembly.solver.cancel = callbacks.flag();
    std::vector<Spawned_graph> spawned = callbacks.run([&] { return spawn_part_graphs(model, start, options); });
    py::list result;
    for(Spawned_graph& s : spawned)
      result.append(py::dict(py::arg("index") = s.index, py::arg("graph") = s.graph, py::arg("edits") = s.edits,
                             py::arg("assembly") = assembly_dict(std::move(s.assembly))));
    return result; },
        py::arg("model"), py::arg("start"), py::arg("count") = 8, py::arg("seed") = 1, py::arg("progress") = py::none(),
        "Draws `count` random valid part graphs from `start` by random edits, embeds each, and returns them "
        "ranked by residual energy per part (dicts: index, graph, edits, assembly). Reproducible for a seed. "
        "progress: optional callable(done, count).");
}

} // namespace mpm_python
