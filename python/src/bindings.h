// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the binding files share: the functions that add each stage's
// bindings to the module, Python callbacks called from computations that
// run without the GIL, and JSON-shaped plain data (the file formats'
// annotations and part graphs as Python dicts).
#ifndef CGAL_MPM_PYTHON_BINDINGS_H
#define CGAL_MPM_PYTHON_BINDINGS_H

#include <CGAL/MPM/Solver/Cancellation.h>
#include <CGAL/MPM/Model/Model_parameters.h>

#include <pybind11/pybind11.h>

#include <atomic>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mpm_python {

namespace py = pybind11;

void bind_meshes(py::module_& m);
void bind_cutting(py::module_& m);
void bind_model(py::module_& m);
void bind_editing(py::module_& m);
void bind_assembly(py::module_& m);

/// Python callables given to a long computation, which runs without the
/// GIL: each call takes the GIL back. When a callable raises, the
/// computation's cancellation flag stops it at its next check and `run()`
/// raises the callable's exception instead of `Operation_cancelled`.
class Python_callbacks
{
public:
  /// The callable `f` as a C++ function (empty for None). The object must
  /// outlive the returned function; the callable is not copied, so copies
  /// of the function made without the GIL touch no reference count.
  template <class... Args>
  std::function<void(Args...)> wrap(const py::object& f)
  {
    if(f.is_none()) return {};
    callables_.push_back(f);
    const py::object* callable = &callables_.back();
    return [this, callable](Args... args) {
      if(raised_.load()) return;
      py::gil_scoped_acquire gil;
      try
      {
        (*callable)(args...);
      }
      catch(py::error_already_set& e)
      {
        error_.emplace(std::move(e));
        raised_.store(true);
      }
    };
  }
  /// The flag that a raising callable sets.
  CGAL::MPM::Cancellation_flag flag() const { return &raised_; }
  /// Runs `work` without the GIL and raises what a callable raised.
  template <class Work>
  auto run(Work&& work) -> decltype(work())
  {
    std::optional<decltype(work())> result;
    try
    {
      py::gil_scoped_release release;
      result.emplace(work());
    }
    catch(const CGAL::MPM::Operation_cancelled&)
    {
      if(!error_) throw;
    }
    if(error_) throw *error_;
    return std::move(*result);
  }

private:
  std::deque<py::object> callables_;
  std::atomic<bool> raised_{false};
  std::optional<py::error_already_set> error_;
};

/// A Python object (dict, list, number, string) as JSON text, and back.
std::string to_json_text(const py::handle& object);
py::object from_json_text(const std::string& text);

/// An annotation given as a dict in the annotation file format
/// (`{"parts": [{"label": 0, "type": "palm"}, ...], ...}`), as a mapping of
/// labels to type names, or None (empty).
CGAL::MPM::Annotation to_annotation(const py::handle& object, const std::string& source = "annotation");
/// The annotation as a dict in the file format.
py::object annotation_object(const CGAL::MPM::Annotation& annotation);

} // namespace mpm_python

#endif
