// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_FACE_GRAPH_CONVERSION_H
#define CGAL_MPM_FACE_GRAPH_CONVERSION_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Input_error.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// The index of each vertex of `g` in the iteration order of `vertices(g)`:
/// the vertex numbering of `to_indexed_mesh()`, of handles and cut files
/// given for `g`, and of `write_positions()`. Descriptors may be sparse or
/// non-integral (`Polyhedron_3` iterators), so indices are assigned in
/// iteration order rather than taken from them.
template <class FaceGraph>
std::unordered_map<typename boost::graph_traits<FaceGraph>::vertex_descriptor, int> vertex_order(const FaceGraph& g)
{
  std::unordered_map<typename boost::graph_traits<FaceGraph>::vertex_descriptor, int> index;
  int n = 0;
  for(auto v : vertices(g)) index.emplace(v, n++);
  return index;
}

namespace internal {

// The inverse of `vertex_order()`: vertex `i` of `to_indexed_mesh(g)` is
// the `i`-th of the result.
template <class FaceGraph>
std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor> vertex_list(const FaceGraph& g)
{
  // Parentheses: OpenMesh's iterators convert to its handles, so braces
  // would make a list of the two ends.
  return std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>(vertices(g).begin(),
                                                                                 vertices(g).end());
}

} // namespace internal

/// \ingroup PkgMPMRef
/// Converts a triangle mesh given as a model of `FaceGraph` to the plain
/// `Indexed_mesh` the learning and solving code works on.
///
/// Vertex `i` of the result is the `i`-th vertex in the iteration order of
/// `vertices(g)`, triangle `t` the `t`-th face of `faces(g)`, with its corners
/// in the order of `vertices_around_face(halfedge(f, g), g)`. So labels read
/// with `face_labels_from_map()` line up with the triangles, and positions
/// computed on the result can be written back by iterating `vertices(g)`.
///
/// \tparam FaceGraph a model of `FaceListGraph` whose vertex points are convertible
///         to three coordinates through `x()`, `y()`, `z()` of the kernel point type
/// \param g the triangle mesh to convert
/// \param np optional named parameters: `vertex_point_map` (default:
///        `get(CGAL::vertex_point, g)`)
///
/// Throws `Input_error` naming the face when a face is not a triangle.
template <class FaceGraph, class NamedParameters = parameters::Default_named_parameters>
Indexed_mesh to_indexed_mesh(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, g));

  const std::unordered_map<vertex_descriptor, int> index = vertex_order(g);
  Indexed_mesh m;
  m.points.resize(static_cast<Eigen::Index>(index.size()), 3);
  for(vertex_descriptor v : vertices(g)) {
    const auto& p = get(vpm, v);
    m.points.row(index.at(v)) << CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z());
  }

  int f_index = 0;
  for(auto f : faces(g)) {
    Triangle t;
    int corners = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, g), g)) {
      if(corners < 3) t[corners] = index.at(v);
      ++corners;
    }
    if(corners != 3)
      throw Input_error("face graph", "face " + std::to_string(f_index),
                        "has " + std::to_string(corners) + " corners; triangulate the mesh first "
                        "(e.g. CGAL::Polygon_mesh_processing::triangulate_faces())");
    m.triangles.push_back(t);
    ++f_index;
  }
  return m;
}

/// \ingroup PkgMPMRef
/// The value of `labels` for each face of `g`, in the order of `faces(g)`
/// (the triangle order of `to_indexed_mesh()`).
///
/// \tparam FaceLabelMap a `ReadablePropertyMap` from the face descriptor of
///         `FaceGraph` to a type convertible to `int`
template <class FaceGraph, class FaceLabelMap>
std::vector<int> face_labels_from_map(const FaceGraph& g, FaceLabelMap labels)
{
  std::vector<int> r;
  r.reserve(static_cast<std::size_t>(num_faces(g)));
  for(auto f : faces(g)) r.push_back(static_cast<int>(get(labels, f)));
  return r;
}

/// \ingroup PkgMPMRef
/// `g` as a labelled mesh: `to_indexed_mesh(g, np)` with the labels of
/// `face_labels_from_map()`, named `source` in error messages.
template <class FaceGraph, class FaceLabelMap, class NamedParameters = parameters::Default_named_parameters>
Labeled_mesh to_labeled_mesh(const FaceGraph& g, FaceLabelMap face_labels, const std::string& source = "face graph",
                             const NamedParameters& np = parameters::default_values())
{
  Labeled_mesh mesh;
  mesh.mesh = to_indexed_mesh(g, np);
  mesh.face_labels = face_labels_from_map(g, face_labels);
  mesh.source = source;
  return mesh;
}

/// \ingroup PkgMPMRef
/// Writes `labels` (one per face, in the order of `faces(g)`) into the
/// property map `face_labels`: the inverse of `face_labels_from_map()`, how
/// the cutting functions over a face graph hand their labels back.
///
/// \tparam FaceLabelMap a `WritablePropertyMap` from the face descriptor of
///         `FaceGraph` to `int`
///
/// Throws `Input_error` when `g` has not one face per label.
template <class FaceGraph, class FaceLabelMap>
void write_face_labels(const std::vector<int>& labels, const FaceGraph& g, FaceLabelMap face_labels)
{
  if(static_cast<std::size_t>(num_faces(g)) != labels.size())
    throw Input_error("face graph", "", "has " + std::to_string(num_faces(g)) + " faces; the labels are for " +
                                          std::to_string(labels.size()));
  std::size_t t = 0;
  for(auto f : faces(g)) put(face_labels, f, labels[t++]);
}

/// \ingroup PkgMPMRef
/// Fills the empty `g` with `mesh`: vertex `i` of `mesh` becomes the
/// `i`-th vertex of `vertices(g)` and triangle `t` the `t`-th face of
/// `faces(g)`, so that `to_indexed_mesh(g)` gives `mesh` back. Returns the
/// faces in triangle order, for the caller to fill face properties.
///
/// \tparam MutableFaceGraph a model of `MutableFaceGraph`
/// Named parameters: `vertex_point_map` (default: `get(CGAL::vertex_point, g)`).
///
/// Throws `Input_error` when `g` is not empty, and naming the triangle when
/// `g` cannot hold it (a non-manifold edge or vertex, an orientation
/// inconsistent with its neighbours).
template <class MutableFaceGraph, class NamedParameters = parameters::Default_named_parameters>
std::vector<typename boost::graph_traits<MutableFaceGraph>::face_descriptor>
copy_to_face_graph(const Indexed_mesh& mesh, MutableFaceGraph& g,
                   const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<MutableFaceGraph>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<MutableFaceGraph>::face_descriptor;

  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, g));
  using Point = typename boost::property_traits<std::remove_const_t<decltype(vpm)>>::value_type;

  // Clearing is no option: Surface_mesh::clear() also drops the property
  // maps the caller made for the faces to come.
  if(!CGAL::is_empty(g))
    throw Input_error("face graph", "", "is not empty; copy into an empty mesh");
  std::vector<vertex_descriptor> vertex;
  vertex.reserve(static_cast<std::size_t>(mesh.number_of_vertices()));
  for(Eigen::Index i = 0; i < mesh.points.rows(); ++i) {
    vertex.push_back(add_vertex(g));
    put(vpm, vertex.back(), Point(mesh.points(i, 0), mesh.points(i, 1), mesh.points(i, 2)));
  }
  std::vector<face_descriptor> faces;
  faces.reserve(mesh.triangles.size());
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& c = mesh.triangles[t];
    const std::array<vertex_descriptor, 3> corners = {vertex[std::size_t(c[0])], vertex[std::size_t(c[1])],
                                                       vertex[std::size_t(c[2])]};
    faces.push_back(CGAL::Euler::add_face(corners, g));
    if(faces.back() == boost::graph_traits<MutableFaceGraph>::null_face())
      throw Input_error("face graph", "triangle " + std::to_string(t),
                        "cannot be added: a non-manifold edge or vertex, or an orientation inconsistent with its "
                        "neighbours");
  }
  return faces;
}

/// \ingroup PkgMPMRef
/// Writes `positions` (one row per vertex, in the order of `vertices(g)`)
/// into `g` through its vertex point map, as CGAL's
/// `Surface_mesh_deformation` writes its result into the mesh it deforms.
///
/// Named parameters: `vertex_point_map` (default: `get(CGAL::vertex_point, g)`).
///
/// Throws `Input_error` when `g` has not one vertex per row.
template <class FaceGraph, class NamedParameters = parameters::Default_named_parameters>
void write_positions(const Point_matrix& positions, FaceGraph& g,
                     const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_property_map(CGAL::vertex_point, g));
  using Point = typename boost::property_traits<std::remove_const_t<decltype(vpm)>>::value_type;
  if(static_cast<Eigen::Index>(num_vertices(g)) != positions.rows())
    throw Input_error("face graph", "", "has " + std::to_string(num_vertices(g)) + " vertices; the result has " +
                                          std::to_string(positions.rows()) + " (copy the edited example into it "
                                          "first with copy_training_example())");
  Eigen::Index i = 0;
  for(auto v : vertices(g)) {
    put(vpm, v, Point(positions(i, 0), positions(i, 1), positions(i, 2)));
    ++i;
  }
}

} // namespace MPM
} // namespace CGAL

#endif
