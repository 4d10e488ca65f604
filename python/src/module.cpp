// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `cgal_mpm` module: its exceptions and the plain-data conversions the
// binding files share; each stage's functions are in a bind_*.cpp file.
#include "bindings.h"

#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Solver/Cancellation.h>
#include <CGAL/MPM/Input_error.h>

#include <algorithm>

namespace mpm_python {

std::string to_json_text(const py::handle& object)
{
  return py::module_::import("json").attr("dumps")(object).cast<std::string>();
}

py::object from_json_text(const std::string& text)
{
  return py::module_::import("json").attr("loads")(text);
}

CGAL::MPM::Annotation to_annotation(const py::handle& object, const std::string& source)
{
  if(object.is_none()) return CGAL::MPM::Annotation();
  if(!py::isinstance<py::dict>(object))
    throw py::value_error(source + ": expected a dict (the annotation file's JSON, or labels to type names), got " +
                          py::repr(object).cast<std::string>());
  const py::dict d = py::reinterpret_borrow<py::dict>(object);
  const bool label_map = !d.empty() && std::all_of(d.begin(), d.end(), [](const auto& item) {
    return py::isinstance<py::int_>(item.first) && py::isinstance<py::str>(item.second);
  });
  if(!label_map) return CGAL::MPM::parse_annotation(to_json_text(d), source);
  CGAL::MPM::Annotation annotation;
  annotation.source = source;
  for(const auto& [label, type] : d)
  {
    const int l = label.cast<int>();
    if(l < 0) throw py::value_error(source + ": label " + std::to_string(l) + ": must not be negative");
    annotation.part_type_of_label[l] = type.cast<std::string>();
  }
  return annotation;
}

py::object annotation_object(const CGAL::MPM::Annotation& annotation)
{
  return from_json_text(CGAL::MPM::annotation_to_json(annotation));
}

} // namespace mpm_python

PYBIND11_MODULE(cgal_mpm, m)
{
  namespace py = pybind11;
  m.doc() = R"doc(Morphable part models (CGAL-MPM) from Python.

Learn how the parts of segmented meshes vary and connect, then edit within
what was learned: drag handles, symmetrize, exaggerate, assemble new
arrangements of parts. Meshes are numpy arrays: V (n x 3 float64), F (m x 3
integer vertex indices), labels (m integers, one part label per face).

Errors: InputError (a ValueError) for bad input, naming the element at
fault; ComputationError (a RuntimeError) when a computation cannot give a
meaningful result; Cancelled when a callback stopped a computation.
See doc/MPM/Python.md.)doc";

  static py::exception<CGAL::MPM::Input_error> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<CGAL::MPM::Computation_error> computation_error(m, "ComputationError", PyExc_RuntimeError);
  static py::exception<CGAL::MPM::Operation_cancelled> cancelled(m, "Cancelled", PyExc_RuntimeError);
  input_error.attr("__doc__") = "Bad input: a malformed mesh, label array, annotation, model, handle or part graph. "
                      "The message names the source, the element and what is wrong.";
  computation_error.attr("__doc__") = "A computation could not produce a meaningful result; the message names the part at fault.";
  cancelled.attr("__doc__") = "A long computation was stopped (its cancellation flag was raised).";
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p) std::rethrow_exception(p);
    }
    catch(const CGAL::MPM::Input_error& e)
    {
      input_error(e.what());
    }
    catch(const CGAL::MPM::Computation_error& e)
    {
      computation_error(e.what());
    }
    catch(const CGAL::MPM::Operation_cancelled& e)
    {
      cancelled(e.what());
    }
  });

  mpm_python::bind_meshes(m);
  mpm_python::bind_cutting(m);
  mpm_python::bind_model(m);
  mpm_python::bind_editing(m);
  mpm_python::bind_assembly(m);
}
