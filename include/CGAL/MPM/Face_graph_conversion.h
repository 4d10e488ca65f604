// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_FACE_GRAPH_CONVERSION_H
#define CGAL_MPM_FACE_GRAPH_CONVERSION_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Input_error.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace MPM {

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

  Indexed_mesh m;
  // Descriptors may be sparse or non-integral (Polyhedron iterators), so
  // indices are assigned in iteration order rather than taken from them.
  std::unordered_map<vertex_descriptor, int> index;
  m.points.resize(static_cast<Eigen::Index>(num_vertices(g)), 3);
  int n = 0;
  for(vertex_descriptor v : vertices(g)) {
    const auto& p = get(vpm, v);
    m.points.row(n) << CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z());
    index.emplace(v, n++);
  }
  m.points.conservativeResize(n, 3);

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

} // namespace MPM
} // namespace CGAL

#endif
