// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Learning a model, saving and loading it, inspecting it, and fitting a
// new shape into it.
#include "arrays.h"
#include "bindings.h"
#include "model_data.h"
#include "synthetic.h"

#include <CGAL/MPM/Learning/Model_fit.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <pybind11/stl.h>

namespace mpm_python {

namespace {

using namespace CGAL::MPM;

// One training mesh: a (V, F, labels) tuple or a `Synthetic`.
Training_input to_training_input(const py::handle& object, const py::handle& annotation, int index)
{
  const std::string source = "meshes[" + std::to_string(index) + "]";
  Training_input input;
  if(py::isinstance<Synthetic>(object))
  {
    const Synthetic_model& s = object.cast<const Synthetic&>().model();
    input.mesh = s.mesh;
    input.annotation = s.annotation;
  }
  else
  {
    if(!py::isinstance<py::sequence>(object) || py::len(object) != 3)
      throw py::value_error(source + ": expected a (V, F, labels) tuple or a Synthetic, got " +
                            py::repr(object).cast<std::string>());
    const py::sequence t = py::reinterpret_borrow<py::sequence>(object);
    input.mesh = to_labeled_mesh(t[0], t[1], t[2], source);
  }
  if(!annotation.is_none()) input.annotation = to_annotation(annotation, source + " annotation");
  return input;
}

bool is_single_mesh(const py::handle& meshes)
{
  if(py::isinstance<Synthetic>(meshes)) return true;
  return py::isinstance<py::tuple>(meshes) && py::len(meshes) == 3 &&
         !py::isinstance<py::tuple>(py::reinterpret_borrow<py::tuple>(meshes)[0]) &&
         !py::isinstance<Synthetic>(py::reinterpret_borrow<py::tuple>(meshes)[0]);
}

std::vector<Training_input> to_training_inputs(const py::handle& meshes, const py::handle& annotations)
{
  std::vector<Training_input> inputs;
  if(is_single_mesh(meshes))
  {
    inputs.push_back(to_training_input(meshes, annotations, 0));
    return inputs;
  }
  if(!py::isinstance<py::sequence>(meshes))
    throw py::value_error("meshes: expected a (V, F, labels) tuple, a Synthetic or a list of them, got " +
                          py::repr(meshes).cast<std::string>());
  const py::sequence list = py::reinterpret_borrow<py::sequence>(meshes);
  if(list.size() == 0) throw py::value_error("meshes: no mesh to learn from");
  const bool each = !annotations.is_none() && py::isinstance<py::list>(annotations);
  const py::list annotation_list = each ? py::reinterpret_borrow<py::list>(annotations) : py::list();
  if(each && py::len(annotations) != list.size())
    throw py::value_error("annotations: " + std::to_string(py::len(annotations)) + " annotations for " +
                          std::to_string(list.size()) + " meshes");
  if(!annotations.is_none() && !each)
    throw py::value_error("annotations: with several meshes, give a list (one annotation or None per mesh)");
  for(std::size_t i = 0; i < list.size(); ++i)
    inputs.push_back(to_training_input(list[i], each ? py::handle(annotation_list[i]) : py::handle(py::none()), int(i)));
  return inputs;
}

// As `mpm learn` does: meshes without part types whose segments are not in
// known correspondence (a real segmentation) get proposed types.
void propose_missing_types(std::vector<Training_input>& inputs)
{
  std::vector<int> bare;
  std::vector<Labeled_mesh> meshes;
  for(std::size_t i = 0; i < inputs.size(); ++i)
  {
    meshes.push_back(inputs[i].mesh);
    if(inputs[i].annotation.part_type_of_label.empty()) bare.push_back(int(i));
  }
  if(bare.empty() || !part_types_need_proposing(meshes)) return;
  const std::vector<Part_type_proposal> proposals = propose_part_types(meshes);
  for(int i : bare) inputs[i].annotation.part_type_of_label = proposals[i].annotation.part_type_of_label;
}

void warn_all(const std::vector<std::string>& warnings)
{
  const py::object warn = py::module_::import("warnings").attr("warn");
  for(const std::string& w : warnings) warn(w, py::module_::import("builtins").attr("RuntimeWarning"), 2);
}

py::dict segment_fit_dict(const Morphable_part_model& model, const Segment_fit& s)
{
  py::dict d;
  d["label"] = s.label;
  d["type"] = model.types.at(s.type).name;
  d["type_index"] = s.type;
  d["type_source"] = s.type_source == Fit_type_source::annotation ? "annotation" : "seams_and_size";
  d["seam_loops"] = s.seam_loops;
  d["known_correspondence"] = s.known_correspondence;
  d["corresponded"] = points_array(Point_matrix(s.corresponded));
  d["fitted"] = points_array(Point_matrix(s.fitted));
  d["coordinates"] = vector_array(s.coordinates);
  d["coordinates_in_sigmas"] = vector_array(s.coordinates_in_sigmas);
  d["motion"] = motion_dict(s.motion);
  d["rms"] = s.rms;
  d["rms_over_segment_diagonal"] = s.rms_over_segment_diagonal;
  d["rms_over_mesh_diagonal"] = s.rms_over_mesh_diagonal;
  d["segment_to_fit_over_mesh_diagonal"] = s.segment_to_fit_over_mesh_diagonal;
  d["coverage_residual"] = s.coverage_residual;
  d["mirrored"] = s.mirrored;
  d["flipped_faces"] = s.flipped_faces;
  return d;
}

py::dict model_fit_dict(const Morphable_part_model& model, const Model_fit& fit)
{
  py::list segments, skipped, errors;
  for(const Segment_fit& s : fit.segments) segments.append(segment_fit_dict(model, s));
  for(const Skipped_segment& s : fit.skipped)
    skipped.append(py::dict(py::arg("label") = s.label, py::arg("reason") = s.reason));
  for(const Type_fit_error& e : fit.errors_by_type(model))
    errors.append(py::dict(py::arg("type") = e.name, py::arg("segments") = e.segments,
                           py::arg("rms_over_mesh_diagonal") = e.rms_over_mesh_diagonal,
                           py::arg("rms_over_segment_diagonal") = e.rms_over_segment_diagonal,
                           py::arg("worst_over_mesh_diagonal") = e.worst_over_mesh_diagonal,
                           py::arg("worst_coverage_residual") = e.worst_coverage_residual,
                           py::arg("segment_to_fit_over_mesh_diagonal") = e.segment_to_fit_over_mesh_diagonal));
  Labeled_mesh surface = fit.fitted_surface(model);
  return py::dict(py::arg("segments") = segments, py::arg("skipped") = skipped, py::arg("errors_by_type") = errors,
                  py::arg("mesh_diagonal") = fit.mesh_diagonal,
                  py::arg("rms_over_mesh_diagonal") = fit.rms_over_mesh_diagonal,
                  py::arg("warnings") = fit.warnings,
                  py::arg("fitted_surface") = py::make_tuple(points_array(std::move(surface.mesh.points)),
                                                             triangles_array(std::move(surface.mesh.triangles)),
                                                             int_array(std::move(surface.face_labels))));
}

void bind_model_class(py::module_& m)
{
  py::class_<Morphable_part_model>(m, "Model", R"doc(A learned morphable part model.

Part types with their shape spaces, docking rules with the shape spaces of
their pair geometry (the grammar), and the training examples. Made by
`learn()` or `load_model()`; pickles as the binary model file.)doc")
    .def_property_readonly("types", [](const Morphable_part_model& model) {
      py::list types;
      for(const Part_type& t : model.types) types.append(part_type_dict(t));
      return types; }, "Part types, one dict each: name, vertices, triangles, sites, mean, modes (3n x d), "
                       "sigmas, variances, instance_coordinates (d x m), instance_motions, instance_residuals.")
    .def_property_readonly("rules", [](const Morphable_part_model& model) {
      py::list rules;
      for(const Docking_rule& r : model.rules) rules.append(docking_rule_dict(model, r));
      return rules; }, "Docking rules, one dict each: first and second site ({type, type_index, site}), kind, "
                       "seam (k x 2 local vertex pairs), and the pair geometry's shape space.")
    .def_property_readonly("examples", [](const Morphable_part_model& model) {
      py::list examples;
      for(const Training_example& e : model.examples) {
        Labeled_mesh rest = to_labeled_mesh(e);
        examples.append(py::dict(py::arg("name") = e.name, py::arg("V") = points_array(std::move(rest.mesh.points)),
                                 py::arg("F") = triangles_array(std::move(rest.mesh.triangles)),
                                 py::arg("labels") = int_array(std::move(rest.face_labels))));
      }
      return examples; }, "Training examples, one dict each: name, V, F, labels (the mesh the edits start from).")
    .def_property_readonly("parameters", [](const Morphable_part_model& model) { return parameters_dict(model.parameters); },
                           "Model parameters (sigma_sub, sigma_bound, docking_radius, modes, explained_variance).")
    .def("find_type", &Morphable_part_model::find_type, py::arg("name"), "Index of the part type called name, or -1.")
    .def("save", [](const Morphable_part_model& model, const std::string& path) { save_model(model, path); },
         py::arg("path"), "Writes the model file (binary, temporary file renamed into place).")
    .def("to_bytes", [](const Morphable_part_model& model) { return py::bytes(serialize_model(model)); },
         "The model file's bytes.")
    .def_static("from_bytes", [](const py::bytes& bytes) { return deserialize_model(bytes, "bytes"); },
                py::arg("data"), "A model from a model file's bytes (raises InputError for malformed ones).")
    .def(py::pickle([](const Morphable_part_model& model) { return py::bytes(serialize_model(model)); },
                    [](const py::bytes& bytes) { return deserialize_model(bytes, "pickle"); }))
    .def("__repr__", [](const Morphable_part_model& model) {
      return "<cgal_mpm.Model: " + std::to_string(model.types.size()) + " part types, " +
             std::to_string(model.rules.size()) + " docking rules, " + std::to_string(model.examples.size()) +
             " example" + (model.examples.size() == 1 ? "" : "s") + ">"; });
  m.def("load_model", [](const std::string& path) { return load_model(path); }, py::arg("path"),
        "Reads a model file written by Model.save() or `mpm learn`.");
}

} // namespace

void bind_model(py::module_& m)
{
  bind_model_class(m);

  m.def("learn", [](const py::handle& meshes, const py::handle& annotations, const py::object& progress,
                    const py::object& warning) {
    std::vector<Training_input> inputs = to_training_inputs(meshes, annotations);
    Python_callbacks callbacks;
    std::vector<std::string> warnings;
    Learning_options options;
    options.progress = callbacks.wrap<const std::string&, double>(progress);
    options.cancel = callbacks.flag();
    if(!warning.is_none()) options.warning = callbacks.wrap<const std::string&>(warning);
    else options.warning = [&warnings](const std::string& w) { warnings.push_back(w); };
    Morphable_part_model model = callbacks.run([&] {
      propose_missing_types(inputs);
      return learn_morphable_part_model(inputs, options); });
    warn_all(warnings);
    return model; },
        py::arg("meshes"), py::arg("annotations") = py::none(), py::arg("progress") = py::none(),
        py::arg("warning") = py::none(),
        R"doc(Learns a morphable part model from one or several labelled meshes.

meshes: a (V, F, labels) tuple, a Synthetic, or a list of them.
annotations: the annotation of the mesh (a dict in the annotation file
  format, or {label: type name}); a list with several meshes; None
  proposes part types for real segmentations (see propose_part_types()) and
  groups parts by identical connectivity otherwise.
progress: optional callable(stage: str, fraction: float); raising in it
  stops learning and re-raises.
warning: optional callable(message: str); by default warnings are issued as
  RuntimeWarning after learning.
Releases the GIL while learning. Returns a Model.)doc");

  m.def("fit", [](const Morphable_part_model& model, const py::handle& V, const py::handle& F,
                  const py::handle& labels, const py::handle& annotation, const py::handle& segments,
                  bool skip_unfittable, const py::object& progress) {
    const Labeled_mesh mesh = to_labeled_mesh(V, F, labels);
    const Annotation a = to_annotation(annotation);
    Python_callbacks callbacks;
    Model_fit_options options;
    if(!segments.is_none()) options.labels = to_indices(segments, "segments");
    options.skip_unfittable = skip_unfittable;
    options.progress = callbacks.wrap<const std::string&, double>(progress);
    options.correspondence.cancel = callbacks.flag();
    const Model_fit fit = callbacks.run([&] { return fit_morphable_part_model(model, mesh, a, options); });
    return model_fit_dict(model, fit); },
        py::arg("model"), py::arg("V"), py::arg("F"), py::arg("labels"), py::arg("annotation") = py::none(),
        py::arg("segments") = py::none(), py::arg("skip_unfittable") = false, py::arg("progress") = py::none(),
        R"doc(Fits a new labelled mesh of the model's kind into the model.

Each segment gets a part type (the annotation's, or the type with as many
seam loops and the closest size), its type's template put on it by dense
correspondence and slid over the segment's surface toward the shape its
space fits, and its shape-space coordinates. segments: labels to fit
(default: all). skip_unfittable: list segments that cannot be fitted in
"skipped" instead of raising InputError.
Returns {"segments": per segment dicts (label, type, coordinates,
coordinates_in_sigmas, motion, corresponded, fitted, rms,
segment_to_fit_over_mesh_diagonal, ...), "skipped",
"errors_by_type", "mesh_diagonal", "rms_over_mesh_diagonal", "warnings",
"fitted_surface": (V, F, labels)}.)doc");
}

} // namespace mpm_python
