// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_TRAINING_EXAMPLE_H
#define CGAL_MPM_TRAINING_EXAMPLE_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Part_graph.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// The mesh a model keeps each training example in: a `CGAL::Surface_mesh`
/// whose vertex `Vertex_index(i)` is vertex `i` of the example's part graph
/// (`Part_node::vertices`) and whose face property `f:part` holds each
/// face's part label.
using Example_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

/// \ingroup PkgMPMRef
/// One training mesh and its part graph.
struct Training_example
{
  std::string name;  ///< where it came from (file name)
  Example_mesh mesh; ///< the rest geometry, with the part labels as `f:part`
  Part_graph graph;  ///< its instances and dockings

  /// The part label of each face of `mesh` (its property `f:part`).
  /// Throws `std::logic_error` when `mesh` has no such property.
  Example_mesh::Property_map<Example_mesh::Face_index, int> face_labels() const;
};

/// \ingroup PkgMPMRef
/// A training example holding `surface` (vertex `i` and triangle `t` become
/// `Vertex_index(i)` and `Face_index(t)`, the labels its `f:part`) with the
/// part graph `graph`. Throws `Input_error` naming `name` and the face when a
/// `Surface_mesh` cannot hold the triangle (a non-manifold edge or vertex,
/// an orientation inconsistent with its neighbours).
Training_example make_training_example(const std::string& name, const Labeled_mesh& surface, Part_graph graph);

/// \ingroup PkgMPMRef
/// `example` as the indexed, labelled mesh the numerical kernels work on,
/// named after the example in error messages.
Labeled_mesh to_labeled_mesh(const Training_example& example);

/// \ingroup PkgMPMRef
/// The rest position of each vertex of `example`, one row per vertex.
Point_matrix rest_positions(const Training_example& example);

/// \ingroup PkgMPMRef
/// Moves the vertices of `example` to `positions` (one row per vertex).
/// Throws `Input_error` naming the example when the row count differs.
void set_rest_positions(Training_example& example, const Point_matrix& positions);

} // namespace MPM
} // namespace CGAL

#endif
