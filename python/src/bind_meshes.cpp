// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes in and out: files, synthetic families, cutting, part type
// proposals and surface checks.
#include "arrays.h"
#include "bindings.h"
#include "synthetic.h"

#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <pybind11/stl.h>

namespace mpm_python {

namespace {

using namespace CGAL::MPM;

py::tuple mesh_tuple(Indexed_mesh&& mesh)
{
  return py::make_tuple(points_array(std::move(mesh.points)), triangles_array(std::move(mesh.triangles)));
}

py::tuple labeled_mesh_tuple(Labeled_mesh&& mesh)
{
  return py::make_tuple(points_array(std::move(mesh.mesh.points)), triangles_array(std::move(mesh.mesh.triangles)),
                        int_array(std::move(mesh.face_labels)));
}

using Color_matrix = Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>;

Color_matrix to_colors(const py::handle& object, int faces)
{
  py::array a = py::array::ensure(object);
  if(!a || a.ndim() != 2 || a.shape(0) != faces || a.shape(1) != 3 || a.dtype().kind() == 'f')
    throw py::value_error("face_colors: expected an integer array of shape (" + std::to_string(faces) +
                          ", 3) with entries in [0, 255]");
  const auto d = py::array_t<long long, py::array::forcecast>::ensure(a);
  const auto r = d.unchecked<2>();
  Color_matrix colors(faces, 3);
  for(int f = 0; f < faces; ++f)
    for(int k = 0; k < 3; ++k)
    {
      if(r(f, k) < 0 || r(f, k) > 255)
        throw py::value_error("face_colors: face " + std::to_string(f) + ": " + std::to_string(r(f, k)) +
                              " is not in [0, 255]");
      colors(f, k) = static_cast<unsigned char>(r(f, k));
    }
  return colors;
}

// A cut line from a list of vertices or a dict {"vertices", "closed", "name"}.
Cut_line to_cut_line(const py::handle& object, int index, int vertices)
{
  const std::string name = "cuts[" + std::to_string(index) + "]";
  Cut_line line;
  if(py::isinstance<py::dict>(object))
  {
    const py::dict d = py::reinterpret_borrow<py::dict>(object);
    for(const auto& item : d)
    {
      const std::string key = py::str(item.first);
      if(key != "vertices" && key != "closed" && key != "name")
        throw py::value_error(name + ": unknown key \"" + key + "\" (allowed: vertices, closed, name)");
    }
    if(!d.contains("vertices")) throw py::value_error(name + ": needs \"vertices\"");
    line.vertices = to_indices(d["vertices"], name + ".vertices", -1, 0, vertices);
    if(d.contains("closed")) line.closed = d["closed"].cast<bool>();
    if(d.contains("name")) line.name = d["name"].cast<std::string>();
  }
  else
    line.vertices = to_indices(object, name, -1, 0, vertices);
  return line;
}

py::dict segment_dict(const Segment_proposal& s)
{
  py::dict d;
  d["label"] = s.label;
  d["type"] = s.type;
  d["faces"] = s.faces;
  d["area"] = s.area;
  d["diameter"] = s.diameter;
  d["seam_loops"] = s.seam_loops;
  d["neighbours"] = s.neighbours;
  d["depth"] = s.depth;
  d["parent"] = s.parent;
  d["children"] = s.children;
  d["reason"] = s.reason;
  return d;
}

py::dict proposal_dict(const Part_type_proposal& p)
{
  py::dict d;
  d["annotation"] = annotation_object(p.annotation);
  py::list segments;
  for(const Segment_proposal& s : p.segments) segments.append(segment_dict(s));
  d["segments"] = segments;
  d["root"] = p.root;
  return d;
}

void bind_synthetic(py::module_& m)
{
  py::class_<Synthetic>(m, "Synthetic", "A synthetic family member with its ground truth (see `synthesize`).")
    .def_property_readonly("family", [](const Synthetic& s) { return family_name(s.model().family); },
                           "The family's name, as families() lists it.")
    .def_property_readonly("V", [](const Synthetic& s) { return points_array(Point_matrix(s.model().mesh.mesh.points)); },
                           "Vertex positions, n x 3 float64.")
    .def_property_readonly("F", [](const Synthetic& s) {
      return triangles_array(std::vector<Triangle>(s.model().mesh.mesh.triangles)); }, "Triangles, m x 3 int32.")
    .def_property_readonly("labels", [](const Synthetic& s) { return int_array(std::vector<int>(s.model().mesh.face_labels)); },
                           "Part label of each face, m int32.")
    .def_property_readonly("annotation", [](const Synthetic& s) { return annotation_object(s.model().annotation); },
                           "Part types per label and parameters, as the annotation file's dict.")
    .def_property_readonly("types", [](const Synthetic& s) {
      py::list types;
      for(const Synthetic_type& t : s.model().types)
        types.append(py::dict(py::arg("name") = t.name, py::arg("modes") = t.modes, py::arg("linear") = t.linear));
      return types; }, "Ground truth per part type: name, number of latent modes, linear or not.")
    .def_property_readonly("instances", [](const Synthetic& s) {
      py::list instances;
      for(const Synthetic_instance& i : s.model().instances)
        instances.append(py::dict(py::arg("label") = i.label, py::arg("type") = i.type,
                                  py::arg("vertices") = int_array(std::vector<int>(i.vertices)),
                                  py::arg("latent") = double_array(i.latent)));
      return instances; }, "Ground truth per part: label, type, the mesh vertex of each local vertex "
                           "(the true correspondence) and its latent parameters.")
    .def_property_readonly("connections", [](const Synthetic& s) {
      py::list connections;
      for(const Synthetic_connection& c : s.model().connections)
        connections.append(py::dict(py::arg("first") = c.first, py::arg("second") = c.second,
                                    py::arg("boundary") = c.boundary));
      return connections; }, "The generator's dockings: label pairs, shared seam (boundary) or not.")
    .def_property_readonly("expected_rules", [](const Synthetic& s) { return s.model().expected_rules; },
                           "Distinct docking rules a learned grammar must hold.")
    .def("draw_pose", [](const Synthetic& s, unsigned seed) {
      Point_matrix p;
      { py::gil_scoped_release release; p = s.model().draw_pose(seed); }
      return points_array(std::move(p)); }, py::arg("seed"),
         "Vertex positions (n x 3) of a held-out pose: the same parts and connectivity, new latent "
         "parameters drawn from `seed`.")
    .def("__repr__", [](const Synthetic& s) {
      return "<cgal_mpm.Synthetic " + family_name(s.model().family) + ": " +
             std::to_string(s.model().mesh.mesh.number_of_vertices()) + " vertices, " +
             std::to_string(s.model().instances.size()) + " parts>"; });

  m.def("families", [] {
    std::vector<std::string> names;
    for(Synthetic_family f : all_synthetic_families()) names.push_back(family_name(f));
    return names; }, "Names of the synthetic families: hexa-grid, facade, hand, spider, spine.");
  m.def("synthesize", [](const std::string& family, unsigned seed, int vertices) {
    const Synthetic_family f = parse_family(family);
    Synthetic_options options;
    options.seed = seed;
    options.vertices = vertices;
    py::gil_scoped_release release;
    return Synthetic(make_synthetic_model(f, options)); },
        py::arg("family") = "hand", py::arg("seed") = 1, py::arg("vertices") = 0,
        R"doc(A member of a synthetic family, labelled and annotated, with its ground truth.

family: "hexa-grid", "facade", "hand", "spider" or "spine" (see `families()`).
seed: seeds the latent parameters of the parts' shapes.
vertices: approximate vertex count; 0 is the family's default (the paper's scale).
Returns a `Synthetic` (V, F, labels, annotation, types, instances, draw_pose()).)doc");
}

} // namespace

void bind_meshes(py::module_& m)
{
  m.def("read_mesh", [](const std::string& path) {
    Mesh_file file;
    { py::gil_scoped_release release; file = read_mesh_file(path); }
    return mesh_tuple(std::move(file.mesh)); }, py::arg("path"),
        "Reads an OFF, OBJ, PLY or STL mesh; returns (V, F): n x 3 float64 positions and m x 3 int32 "
        "triangles (polygons are fan-triangulated). Raises InputError naming the file and element.");
  m.def("write_mesh", [](const std::string& path, const py::handle& V, const py::handle& F,
                         const py::handle& face_colors, bool binary) {
    const Indexed_mesh mesh = to_mesh(V, F);
    const Color_matrix colors = face_colors.is_none() ? Color_matrix() : to_colors(face_colors, mesh.number_of_faces());
    Mesh_write_options options;
    options.binary = binary;
    py::gil_scoped_release release;
    write_mesh_file(mesh, path, face_colors.is_none() ? nullptr : &colors, options); },
        py::arg("path"), py::arg("V"), py::arg("F"), py::arg("face_colors") = py::none(), py::arg("binary") = false,
        "Writes a mesh (format from the extension: .off, .obj, .ply, .stl) through a temporary file renamed "
        "into place. face_colors: optional m x 3 integers in [0, 255] (PLY). binary: PLY and STL only.");
  m.def("read_labels", [](const std::string& path) { return int_array(read_seg_file(path)); }, py::arg("path"),
        "Reads a .seg file (one label per face); returns an int32 array.");
  m.def("write_labels", [](const std::string& path, const py::handle& labels) {
    write_seg_file(to_indices(labels, "labels"), path); }, py::arg("path"), py::arg("labels"),
        "Writes one label per face as a .seg file (temporary file renamed into place).");
  m.def("read_labeled_mesh", [](const std::string& mesh_path, const std::string& labels) {
    Labeled_mesh mesh;
    { py::gil_scoped_release release; mesh = read_labeled_mesh(mesh_path, labels); }
    return labeled_mesh_tuple(std::move(mesh)); }, py::arg("mesh_path"), py::arg("labels"),
        "Reads a mesh and its part labels; returns (V, F, labels). labels: a .seg file, \"components\" (one "
        "label per connected component) or \"property:NAME\" (an integer face property of a PLY file).");
  m.def("read_annotation", [](const std::string& path) { return annotation_object(read_annotation(path)); },
        py::arg("path"), "Reads an annotation file; returns its dict (part types, landmarks, parameters).");
  m.def("write_annotation", [](const std::string& path, const py::handle& annotation) {
    write_annotation(to_annotation(annotation), path); }, py::arg("path"), py::arg("annotation"),
        "Writes an annotation (a dict in the file format, or labels to type names).");
  m.def("connected_components", [](const py::handle& V, const py::handle& F) {
    return int_array(connected_component_labels(to_mesh(V, F))); }, py::arg("V"), py::arg("F"),
        "One label per face: its face-connected component, numbered from 0.");

  bind_synthetic(m);

  m.def("cut", [](const py::handle& V, const py::handle& F, const py::list& cuts, bool closed, double feature_weight,
                  const py::handle& parts) {
    const Indexed_mesh mesh = to_mesh(V, F);
    Cut_specification specification;
    specification.source = "cuts";
    for(std::size_t i = 0; i < cuts.size(); ++i)
      specification.cuts.push_back(to_cut_line(cuts[i], int(i), mesh.number_of_vertices()));
    if(!parts.is_none())
      for(const auto& [label, seed] : py::cast<py::dict>(parts))
        specification.parts.push_back(Part_seed{label.cast<int>(), seed.cast<int>()});
    Cutting_options options;
    options.closed = closed;
    options.feature_weight = feature_weight;
    Cutting_result result;
    { py::gil_scoped_release release; result = cut_mesh(mesh, specification, options, "V, F"); }
    py::list paths;
    for(std::vector<int>& p : result.paths) paths.append(int_array(std::move(p)));
    return py::dict(py::arg("labels") = int_array(std::move(result.mesh.face_labels)), py::arg("paths") = paths,
                    py::arg("lengths") = double_array(result.lengths), py::arg("regions") = result.regions); },
        py::arg("V"), py::arg("F"), py::arg("cuts"), py::arg("closed") = true, py::arg("feature_weight") = 1.,
        py::arg("parts") = py::none(),
        R"doc(Cuts a mesh along cutting lines and labels the regions they separate.

cuts: one entry per cut, a list of vertex indices in order along it (joined by
  feature-weighted shortest paths), or a dict {"vertices": [...],
  "closed": bool, "name": str}.
closed: whether cuts are loops (around a limb) unless they say otherwise.
feature_weight: how strongly paths snap to concave creases (0: geodesics).
parts: optional {label: seed vertex} naming regions; others are numbered.
Returns {"labels": m int32, "paths": [vertex arrays], "lengths": float64, "regions": int}.)doc");

  m.def("propose_part_types", [](const py::handle& V, const py::handle& F, const py::handle& labels,
                                 double max_area_ratio) {
    Part_type_proposal_options options;
    options.max_area_ratio = max_area_ratio;
    const Labeled_mesh mesh = to_labeled_mesh(V, F, labels);
    Part_type_proposal proposal;
    { py::gil_scoped_release release; proposal = propose_part_types(mesh, options); }
    return proposal_dict(proposal); },
        py::arg("V"), py::arg("F"), py::arg("labels"), py::arg("max_area_ratio") = 3.,
        R"doc(Proposes part types for a labelled mesh nobody has annotated.

From the segment graph (root: the segment with most neighbours; chains,
tips and branches by breadth-first search) and the segments' sizes (a class
whose largest area exceeds max_area_ratio times its smallest is split).
Returns {"annotation": dict for learn(), "segments": one dict per segment
(label, type, faces, area, diameter, seam_loops, neighbours, depth, parent,
children, reason), "root": label}.)doc");

  m.def("check_surface", [](const py::handle& V, const py::handle& F, const py::handle& reference_V,
                            const py::handle& groups) {
    const Indexed_mesh mesh = to_mesh(V, F);
    Indexed_mesh reference;
    if(!reference_V.is_none())
    {
      reference.points = to_points(reference_V, "reference_V");
      reference.triangles = mesh.triangles;
      if(reference.number_of_vertices() != mesh.number_of_vertices())
        throw py::value_error("reference_V: has " + std::to_string(reference.number_of_vertices()) +
                              " rows, V has " + std::to_string(mesh.number_of_vertices()));
    }
    const std::vector<int> face_groups =
      groups.is_none() ? std::vector<int>() : to_indices(groups, "groups", mesh.number_of_faces());
    Surface_soundness s;
    {
      py::gil_scoped_release release;
      s = check_surface(mesh, reference_V.is_none() ? nullptr : &reference, groups.is_none() ? nullptr : &face_groups);
    }
    return py::dict(py::arg("components") = s.components, py::arg("border_edges") = s.border_edges,
                    py::arg("non_manifold_edges") = s.non_manifold_edges,
                    py::arg("self_intersections") = s.self_intersections,
                    py::arg("degenerate_faces") = s.degenerate_faces, py::arg("flipped_faces") = s.flipped_faces,
                    py::arg("inverted_faces") = s.inverted_faces); },
        py::arg("V"), py::arg("F"), py::arg("reference_V") = py::none(), py::arg("groups") = py::none(),
        R"doc(Checks a surface with CGAL's Polygon_mesh_processing.

Returns a dict: components, border_edges, non_manifold_edges,
self_intersections, degenerate_faces and, against reference_V (the same
triangles before an edit), flipped_faces and inverted_faces (turned inside
out within their group, e.g. their part label; -1 without a reference).)doc");
}

} // namespace mpm_python
