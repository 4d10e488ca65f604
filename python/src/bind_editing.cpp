// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Editing: the `Editor` (a prefactored embedding solver over one training
// example, for repeated drags), the one-call edits, handles, and the
// baseline deformation methods.
#include "arrays.h"
#include "bindings.h"

#include <CGAL/MPM/Baselines/Deformation_method.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Elapsed_time.h>

#include <pybind11/stl.h>

#include <mutex>

namespace mpm_python {

namespace {

using namespace CGAL::MPM;
using internal::Clock;
using internal::milliseconds_since;

template <class Enum>
Enum parse_choice(const py::handle& value, const std::string& key,
                  const std::vector<std::pair<std::string, Enum>>& choices)
{
  const std::string name = py::str(value);
  std::string allowed;
  for(const auto& [n, e] : choices)
  {
    if(n == name) return e;
    allowed += (allowed.empty() ? "" : ", ") + n;
  }
  throw py::value_error(key + ": unknown value \"" + name + "\" (allowed: " + allowed + ")");
}

// The solver options a Python call gives as keyword arguments.
Embedding_options to_solver_options(const py::kwargs& kwargs)
{
  Embedding_options o;
  for(const auto& [key_object, value] : kwargs)
  {
    const std::string key = py::str(key_object);
    if(key == "max_iterations") o.max_iterations = value.cast<int>();
    else if(key == "tolerance") o.tolerance = value.cast<double>();
    else if(key == "handle_weight") o.handle_weight = value.cast<double>();
    else if(key == "anchor_weight") o.anchor_weight = value.cast<double>();
    else if(key == "coupling_weight") o.coupling_weight = value.cast<double>();
    else if(key == "newton") o.newton = value.cast<bool>();
    else if(key == "quasi_newton") o.quasi_newton = value.cast<bool>();
    else if(key == "predict_rotations") o.predict_rotations = value.cast<bool>();
    else if(key == "anderson_history") o.anderson_history = value.cast<int>();
    else if(key == "global_step")
      o.global_step = parse_choice<Global_step>(
        value, key, {{"reduced", Global_step::reduced}, {"schur", Global_step::schur}, {"direct", Global_step::direct}});
    else if(key == "rotations")
      o.rotations = parse_choice<Rotations>(value, key, {{"per_cluster", Rotations::per_cluster},
                                                         {"per_vertex", Rotations::per_vertex}});
    else if(key == "sparse_solver")
      o.sparse_solver = parse_choice<Sparse_solver>(
        value, key, {{"simplicial_ldlt", Sparse_solver::simplicial_ldlt}, {"cholmod", Sparse_solver::cholmod}});
    else
      throw py::value_error("unknown solver option \"" + key +
                            "\" (allowed: max_iterations, tolerance, handle_weight, anchor_weight, coupling_weight, "
                            "newton, quasi_newton, predict_rotations, anderson_history, global_step, rotations, sparse_solver)");
  }
  if(!(o.max_iterations >= 1)) throw py::value_error("max_iterations: must be at least 1");
  if(!(o.tolerance >= 0.)) throw py::value_error("tolerance: must be a non-negative number");
  if(!(o.handle_weight > 0.) || !std::isfinite(o.handle_weight))
    throw py::value_error("handle_weight: must be a positive number");
  return o;
}

// The embedding problem of an edit of training example `example`.
Embedding_problem make_problem(const Morphable_part_model& model, int example, const std::string& edit,
                               const py::handle& factor, double relative_sigma)
{
  if(example < 0 || example >= int(model.examples.size()))
    throw py::value_error("example: " + std::to_string(example) + " does not exist (the model has " +
                          std::to_string(model.examples.size()) + ")");
  if(edit == "deform") return make_deformation_problem(model, example);
  if(edit == "symmetrize")
  {
    Symmetrization_options options;
    options.relative_sigma = relative_sigma;
    return make_symmetrization_problem(model, example, options);
  }
  if(edit == "caricature")
  {
    if(factor.is_none()) throw py::value_error("factor: the caricature edit needs a factor (e.g. 1.5, or -1)");
    const double f = factor.cast<double>();
    if(!std::isfinite(f)) throw py::value_error("factor: must be finite");
    return make_caricature_problem(model, f, example);
  }
  throw py::value_error("edit: unknown edit \"" + edit + "\" (allowed: deform, symmetrize, caricature)");
}

py::dict report_dict(const Solve_report& report, double solve_ms)
{
  return py::dict(py::arg("iterations") = report.iterations, py::arg("converged") = report.converged,
                  py::arg("energies") = double_array(report.energies), py::arg("energy") = report.energy(),
                  py::arg("solve_ms") = solve_ms);
}

// A prefactored solver over one training example. Calls on one editor from
// several threads take turns.
class Editor
{
public:
  Editor(const Morphable_part_model& model, int example, const std::string& edit, const py::handle& factor,
         double relative_sigma, const py::kwargs& kwargs)
    : options_(to_solver_options(kwargs))
  {
    Embedding_problem problem = make_problem(model, example, edit, factor, relative_sigma);
    Labeled_mesh rest = to_labeled_mesh(model.examples[example]);
    rest_ = std::move(rest.mesh);
    labels_ = std::move(rest.face_labels);
    options_.iteration_callback = [this](int iteration, double energy) {
      if(!per_iteration_) return;
      per_iteration_(iteration, energy);
      if(callback_flag_->load()) stop_.store(true);
    };
    options_.cancel = &stop_;
    py::gil_scoped_release release;
    const Clock::time_point start = Clock::now();
    solver_ = std::make_unique<Embedding_solver>(problem, options_);
    solver_->preprocess();
    setup_ms_ = milliseconds_since(start);
  }

  void set_handles(const py::handle& vertices, const py::handle& targets)
  {
    std::vector<int> v = to_indices(vertices, "vertices", -1, 0, rest_.number_of_vertices());
    const Point_matrix t = to_points(targets, "targets");
    if(t.rows() != Eigen::Index(v.size()))
      throw py::value_error("targets: has " + std::to_string(t.rows()) + " rows for " + std::to_string(v.size()) +
                            " handle vertices");
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    const Clock::time_point start = Clock::now();
    solver_->set_handles(v, t);
    solver_->preprocess();
    setup_ms_ = milliseconds_since(start);
    handles_ = std::move(v);
  }

  void move_handles(const py::handle& targets)
  {
    const Point_matrix t = to_points(targets, "targets");
    if(t.rows() != Eigen::Index(handles_.size()))
      throw py::value_error("targets: has " + std::to_string(t.rows()) + " rows for " +
                            std::to_string(handles_.size()) + " handles (set_handles() chooses the vertices)");
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    solver_->set_handles(handles_, t);
  }

  void clear_handles()
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    solver_->clear_handles();
    handles_.clear();
  }

  py::dict solve(const py::object& callback)
  {
    Python_callbacks callbacks;
    std::function<void(int, double)> per_iteration = callbacks.wrap<int, double>(callback);
    double solve_ms = 0.;
    const Solve_report report = callbacks.run([&] {
      std::lock_guard<std::mutex> lock(mutex_);
      const Iteration_callback_scope scope(*this, callbacks.flag(), std::move(per_iteration));
      const Clock::time_point start = Clock::now();
      Solve_report r = solver_->solve();
      solve_ms = milliseconds_since(start);
      return r; });
    return report_dict(report, solve_ms);
  }

  /// Runs `f(solver)` without the GIL and with the editor's lock, so that a
  /// thread waiting for the lock never holds the GIL a callback of a
  /// running solve needs.
  template <class F>
  auto with_solver(F&& f) -> decltype(f(std::declval<Embedding_solver&>()))
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    return f(*solver_);
  }

  double iterate()
  {
    return with_solver([](Embedding_solver& s) { return s.iterate(); });
  }

  py::array positions()
  {
    return points_array(with_solver([](Embedding_solver& s) { return Point_matrix(s.positions()); }));
  }

  py::array unfolded_positions()
  {
    return points_array(with_solver([this](Embedding_solver& s) { return unfold_faces(rest_, s.positions(), handles_); }));
  }

  void cancel() { stop_.store(true); }
  const Indexed_mesh& rest() const { return rest_; }
  const std::vector<int>& labels() const { return labels_; }
  const std::vector<int>& handles() const { return handles_; }
  double setup_ms() const { return setup_ms_; }

private:
  // Makes the solver's iteration callback (installed by the constructor)
  // call `per_iteration` during one solve, and stop the solve once `raised`.
  struct Iteration_callback_scope
  {
    Iteration_callback_scope(Editor& editor, CGAL::MPM::Cancellation_flag raised,
                             std::function<void(int, double)> per_iteration)
      : editor_(editor)
    {
      editor_.stop_.store(false);
      editor_.callback_flag_ = raised;
      editor_.per_iteration_ = std::move(per_iteration);
    }
    ~Iteration_callback_scope() { editor_.per_iteration_ = nullptr; }
    Editor& editor_;
  };

  Embedding_options options_;
  std::unique_ptr<Embedding_solver> solver_;
  Indexed_mesh rest_;
  std::vector<int> labels_;
  std::vector<int> handles_;
  double setup_ms_ = 0.;
  std::function<void(int, double)> per_iteration_;
  CGAL::MPM::Cancellation_flag callback_flag_ = nullptr;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
};

// One edit from start to end, as the `mpm` editing commands do it.
py::tuple edit_once(const Morphable_part_model& model, int example, const std::string& edit, const py::handle& factor,
                    double relative_sigma, const py::handle& vertices, const py::handle& targets, bool unfold,
                    const py::object& callback, const py::kwargs& kwargs)
{
  Editor editor(model, example, edit, factor, relative_sigma, kwargs);
  if(!vertices.is_none()) editor.set_handles(vertices, targets);
  py::dict report = editor.solve(callback);
  report["setup_ms"] = editor.setup_ms();
  return py::make_tuple(unfold ? editor.unfolded_positions() : editor.positions(), report);
}

void bind_editor(py::module_& m)
{
  py::class_<Editor>(m, "Editor", R"doc(A prefactored embedding solver over one training example.

Editor(model, example=0, edit="deform", factor=None, relative_sigma=0.01, **options)
edit: "deform" (free-form, handles pull within the learned space),
  "symmetrize" (instances of a type pulled to one shape; relative_sigma),
  "caricature" (coordinates scaled by factor; < 0: anti-shape).
options: solver options max_iterations (100), tolerance (1e-6),
  handle_weight (100), anchor_weight, coupling_weight, newton (True),
  quasi_newton, predict_rotations (True: a drag's solve starts at the
  rotations its last turn predicts), anderson_history, global_step ("reduced", "schur",
  "direct"), rotations ("per_cluster", "per_vertex"), sparse_solver.

Set handles once (set_handles factors), then move their targets and solve
as often as needed (move_handles costs no factorization): a drag loop in
Python costs what it costs in C++. Long calls release the GIL.)doc")
    .def(py::init<const Morphable_part_model&, int, const std::string&, const py::handle&, double, const py::kwargs&>(),
         py::arg("model"), py::arg("example") = 0, py::arg("edit") = "deform", py::arg("factor") = py::none(),
         py::arg("relative_sigma") = 0.01)
    .def("set_handles", &Editor::set_handles, py::arg("vertices"), py::arg("targets"),
         "Chooses handle vertices (k integers) and their targets (k x 3); a new vertex set refactors.")
    .def("move_handles", &Editor::move_handles, py::arg("targets"),
         "New targets (k x 3) for the current handle vertices; no factorization.")
    .def("clear_handles", &Editor::clear_handles, "Removes all handles.")
    .def("solve", &Editor::solve, py::arg("callback") = py::none(),
         "Iterates from the current state to convergence. callback(iteration, energy) is called after each "
         "iteration; raising in it stops the solve and re-raises. Returns {iterations, converged, energies, "
         "energy, solve_ms}. The GIL is released while solving.")
    .def("iterate", &Editor::iterate, "Runs one iteration; returns the energy after it.")
    .def("cancel", &Editor::cancel, "Stops a solve running in another thread (it raises Cancelled).")
    .def_property_readonly("positions", &Editor::positions, "Current vertex positions (n x 3 float64, a new array).")
    .def("unfolded_positions", &Editor::unfolded_positions,
         "Current positions with folds taken out (as the mpm editing commands write them).")
    .def_property_readonly("energy", [](Editor& e) {
      return e.with_solver([](Embedding_solver& s) { return s.energy(); }); }, "Energy of the current state.")
    .def("reset", [](Editor& e) {
      e.with_solver([](Embedding_solver& s) { s.reset(); return 0; }); },
         "Restarts from the rest positions with zero coordinates.")
    .def_property_readonly("number_of_clusters", [](Editor& e) {
      return e.with_solver([](Embedding_solver& s) { return s.number_of_clusters(); }); },
                           "Clusters of the problem (part instances, then pair geometries).")
    .def("coordinates", [](Editor& e, int c) {
      return vector_array(e.with_solver([&](Embedding_solver& s) {
        if(c < 0 || c >= s.number_of_clusters()) throw py::index_error("cluster " + std::to_string(c) + " out of range");
        return Eigen::VectorXd(s.coordinates(c)); })); }, py::arg("cluster"), "Shape coordinates of a cluster.")
    .def("rotation", [](Editor& e, int c) {
      return matrix_array(e.with_solver([&](Embedding_solver& s) {
        if(c < 0 || c >= s.number_of_clusters()) throw py::index_error("cluster " + std::to_string(c) + " out of range");
        return Eigen::MatrixXd(s.rotation(c)); })); }, py::arg("cluster"), "Rotation (3 x 3) of a cluster.")
    .def_property_readonly("rest_V", [](const Editor& e) { return points_array(Point_matrix(e.rest().points)); },
                           "Rest positions of the example (n x 3).")
    .def_property_readonly("F", [](const Editor& e) { return triangles_array(std::vector<Triangle>(e.rest().triangles)); },
                           "Triangles (m x 3 int32).")
    .def_property_readonly("labels", [](const Editor& e) { return int_array(std::vector<int>(e.labels())); },
                           "Part label of each face.")
    .def_property_readonly("handles", [](const Editor& e) { return int_array(std::vector<int>(e.handles())); },
                           "Current handle vertices.")
    .def_property_readonly("setup_ms", &Editor::setup_ms,
                           "Milliseconds of the last set-up (construction or set_handles).");
}

} // namespace

void bind_editing(py::module_& m)
{
  bind_editor(m);

  m.def("deform", [](const Morphable_part_model& model, const py::handle& vertices, const py::handle& targets,
                     int example, bool unfold, const py::object& callback, const py::kwargs& kwargs) {
    return edit_once(model, example, "deform", py::none(), 0.01, vertices, targets, unfold, callback, kwargs); },
        py::arg("model"), py::arg("vertices"), py::arg("targets"), py::arg("example") = 0, py::arg("unfold") = true,
        py::arg("callback") = py::none(),
        "Deforms training example `example` so that handle vertices reach their targets (k x 3). Returns "
        "(V, report). unfold: take out folds as `mpm deform` does. callback(iteration, energy): as for "
        "Editor.solve(). **options: solver options (see Editor).");
  m.def("symmetrize", [](const Morphable_part_model& model, int example, double relative_sigma,
                         const py::handle& vertices, const py::handle& targets, bool unfold, const py::object& callback,
                         const py::kwargs& kwargs) {
    return edit_once(model, example, "symmetrize", py::none(), relative_sigma, vertices, targets, unfold, callback,
                     kwargs); },
        py::arg("model"), py::arg("example") = 0, py::arg("relative_sigma") = 0.01, py::arg("vertices") = py::none(),
        py::arg("targets") = py::none(), py::arg("unfold") = true, py::arg("callback") = py::none(),
        "Symmetrizes training example `example`: instances of each type pulled to one shape. Optional handles. "
        "Returns (V, report).");
  m.def("caricature", [](const Morphable_part_model& model, double factor, int example, const py::handle& vertices,
                         const py::handle& targets, bool unfold, const py::object& callback, const py::kwargs& kwargs) {
    return edit_once(model, example, "caricature", py::float_(factor), 0.01, vertices, targets, unfold, callback,
                     kwargs); },
        py::arg("model"), py::arg("factor"), py::arg("example") = 0, py::arg("vertices") = py::none(),
        py::arg("targets") = py::none(), py::arg("unfold") = true, py::arg("callback") = py::none(),
        "Caricature (factor > 1) or anti-shape (factor < 0) of training example `example`. Returns (V, report).");

  m.def("handles_per_part", [](const Morphable_part_model& model, int per_part, int example, const py::handle& targets) {
    if(example < 0 || example >= int(model.examples.size()))
      throw py::value_error("example: " + std::to_string(example) + " does not exist");
    const Labeled_mesh mesh = to_labeled_mesh(model.examples[example]);
    const Point_matrix source = targets.is_none() ? mesh.mesh.points : to_points(targets, "targets");
    Handle_set h = handles_per_part(mesh, per_part, source);
    return py::make_tuple(int_array(std::move(h.vertices)), points_array(std::move(h.targets))); },
        py::arg("model"), py::arg("per_part") = 1, py::arg("example") = 0, py::arg("targets") = py::none(),
        "One or two handles per part of a training example (nearest to and farthest from the part's "
        "centroid). targets: n x 3 positions the handles' targets are read from (e.g. a held-out pose); "
        "default the rest positions. Returns (vertices, targets).");
  m.def("farthest_point_handles", [](const py::handle& V, const py::handle& F, int count, const py::handle& targets) {
    const Indexed_mesh mesh = to_mesh(V, F);
    const Point_matrix source = targets.is_none() ? mesh.points : to_points(targets, "targets");
    Handle_set h = farthest_point_handles(mesh, count, source);
    return py::make_tuple(int_array(std::move(h.vertices)), points_array(std::move(h.targets))); },
        py::arg("V"), py::arg("F"), py::arg("count"), py::arg("targets") = py::none(),
        "`count` handles spread by farthest-point sampling; targets from `targets` (default V). "
        "Returns (vertices, targets).");

  m.def("deformation_methods", &deformation_method_names,
        "Names of the deformation methods deform_with() knows: mpm and the baselines.");
  m.def("deform_with", [](const std::string& method, const Morphable_part_model& model, const py::handle& vertices,
                          const py::handle& targets, int example) {
    Handle_set handles;
    handles.vertices = to_indices(vertices, "vertices");
    handles.targets = to_points(targets, "targets");
    std::unique_ptr<Deformation_method> d = make_deformation_method(method, model, example);
    Point_matrix p;
    {
      py::gil_scoped_release release;
      d->set_handles(handles);
      p = d->deform();
    }
    return py::make_tuple(points_array(std::move(p)), d->iterations()); },
        py::arg("method"), py::arg("model"), py::arg("vertices"), py::arg("targets"), py::arg("example") = 0,
        "Deforms training example `example` with `method` (mpm, arap, arap-sre, laplacian, tps, pca: the "
        "baselines of `mpm compare`) for the same handles. Returns (V, iterations; -1 for direct methods).");
}

} // namespace mpm_python
