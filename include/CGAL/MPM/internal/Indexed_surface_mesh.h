// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_INDEXED_SURFACE_MESH_H
#define CGAL_MPM_INTERNAL_INDEXED_SURFACE_MESH_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace CGAL {
namespace MPM {
namespace internal {

using Indexed_surface_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

// `mesh` as a halfedge structure for CGAL's algorithms that need one
// (cutting, ARAP, remeshing, AABB location): vertex i and face f of the
// result are vertex i and triangle f of `mesh`, so indices carry over both
// ways. Throws Input_error(source, "face f", ...) for a corner out of range
// or a face the halfedge structure cannot hold (non-manifold edge or vertex,
// orientation inconsistent with its neighbours, repeated corner); `user`
// names what needed the manifold mesh ("cutting").
Indexed_surface_mesh to_surface_mesh(const Indexed_mesh& mesh, const std::string& source, const std::string& user);

// The same with another point type: exact predicates (self-intersection
// tests) need `Exact_predicates_inexact_constructions_kernel` points.
template <typename Point>
CGAL::Surface_mesh<Point> to_surface_mesh_of(const Indexed_mesh& mesh, const std::string& source,
                                             const std::string& user)
{
  const Indexed_surface_mesh plain = to_surface_mesh(mesh, source, user);
  CGAL::Surface_mesh<Point> result;
  for(auto v : plain.vertices())
    result.add_vertex(Point(plain.point(v).x(), plain.point(v).y(), plain.point(v).z()));
  for(auto f : plain.faces())
  {
    std::vector<typename CGAL::Surface_mesh<Point>::Vertex_index> corners;
    for(auto v : CGAL::vertices_around_face(plain.halfedge(f), plain)) corners.emplace_back(std::size_t(v));
    result.add_face(corners);
  }
  return result;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
