// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Edit_solving.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Elapsed_time.h>

#include <cmath>
#include <sstream>
#include <string>

namespace CGAL {
namespace MPM {

namespace {

using internal::Clock;
using internal::milliseconds_since;

// Displacements beyond this many bounding-box diagonals are no shape anyone
// asked for: a handle target of 1e150 wrote displacements of 1e148, one of
// 1e308 overflowed the solve, and neither error named the handle.
constexpr double farthest_sensible_move = 100.;

std::string number_text(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

// Refused before the solve, naming the handle.
void check_handles(const Handle_set& handles, const Indexed_mesh& mesh, const std::string& mesh_name,
                   const std::string& source)
{
  const double diagonal = internal::bounding_box_diagonal(mesh.points);
  for(int k = 0; k < handles.size(); ++k) {
    const int v = handles.vertices[k];
    const std::string element = "handle " + std::to_string(k) + " (vertex " + std::to_string(v) + ")";
    if(v < 0 || v >= mesh.number_of_vertices())
      throw Input_error(source, element,
                        "is not a vertex of " + mesh_name + " (it has " + std::to_string(mesh.number_of_vertices()) +
                          ")");
    const double asked = (handles.targets.row(k) - mesh.points.row(v)).stableNorm() / diagonal;
    if(diagonal > 0. && !(asked <= farthest_sensible_move))
      throw Input_error(source, element,
                        "its target is " + number_text(asked) + " bounding-box diagonals away (more than " +
                          number_text(farthest_sensible_move) + "); nothing written");
  }
}

Indexed_mesh at_positions(const Indexed_mesh& mesh, const Point_matrix& positions)
{
  Indexed_mesh m;
  m.points = positions;
  m.triangles = mesh.triangles;
  return m;
}

} // namespace

namespace internal {

Solved_edit solve_edit(const Morphable_part_model& model, const Embedding_problem& problem,
                       const Handle_set& handles, const Edit_options& options)
{
  const int example = options.example;
  if(example < 0 || example >= static_cast<int>(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  const Training_example& input = model.examples[example];
  const std::string name = "example " + std::to_string(example) + " (" + input.name + ")";
  const Labeled_mesh rest = to_labeled_mesh(input);
  check_handles(handles, rest.mesh, name, options.handles_source);

  Solved_edit edit;
  Edit_result& r = edit.result;
  const Clock::time_point setup_start = Clock::now();
  Embedding_solver solver(problem, options.solver);
  if(handles.size() > 0) solver.set_handles(handles.vertices, handles.targets);
  solver.preprocess();
  r.setup_ms = milliseconds_since(setup_start);

  const Clock::time_point solve_start = Clock::now();
  r.report = solver.solve();
  r.solve_ms = milliseconds_since(solve_start);
  const Point_matrix& solved = solver.positions();
  if(!solved.allFinite() || !std::isfinite(r.report.energy()))
    throw Computation_error("the solver produced non-finite positions or energy for " + name +
                            " (try a smaller handle weight or handle offsets)");
  r.inverted_faces_solved =
    static_cast<int>(inverted_faces(at_positions(rest.mesh, solved), rest.mesh, &rest.face_labels).size());

  const Clock::time_point unfold_start = Clock::now();
  edit.mesh = at_positions(rest.mesh, options.unfold ? unfold_faces(rest.mesh, solved, handles.vertices) : solved);
  r.unfold_ms = milliseconds_since(unfold_start);
  r.inverted_faces_written = static_cast<int>(inverted_faces(edit.mesh, rest.mesh, &rest.face_labels).size());

  const double diagonal = bounding_box_diagonal(rest.mesh.points);
  const double moved = (edit.mesh.points - rest.mesh.points).rowwise().norm().maxCoeff() / diagonal;
  if(diagonal > 0. && moved > farthest_sensible_move)
    throw Computation_error("the edit of " + name + " moves vertices by up to " + number_text(moved) +
                            " bounding-box diagonals (more than " + number_text(farthest_sensible_move) +
                            "); nothing written");
  return edit;
}

} // namespace internal

} // namespace MPM
} // namespace CGAL
