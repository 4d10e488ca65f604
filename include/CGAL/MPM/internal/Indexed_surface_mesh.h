// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_INDEXED_SURFACE_MESH_H
#define CGAL_MPM_INTERNAL_INDEXED_SURFACE_MESH_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Input_error.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace CGAL {
namespace MPM {
namespace internal {

using Indexed_surface_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

// For algorithms whose predicates must be exact: self-intersection tests,
// and hole filling, whose 3D Delaunay search can run for minutes on a
// nearly cocircular loop with inexact ones.
using Exact_predicates_surface_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

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
  using Result = CGAL::Surface_mesh<Point>;
  Result result;
  const int n = mesh.number_of_vertices();
  for(int v = 0; v < n; ++v) result.add_vertex(Point(mesh.points(v, 0), mesh.points(v, 1), mesh.points(v, 2)));
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    const Triangle& t = mesh.triangles[std::size_t(f)];
    const std::string element = "face " + std::to_string(f);
    for(int corner : t)
      if(corner < 0 || corner >= n)
        throw Input_error(source, element, "vertex " + std::to_string(corner) + " is out of range (the mesh has " +
                                             std::to_string(n) + " vertices)");
    using Vertex = typename Result::Vertex_index;
    if(result.add_face(Vertex(t[0]), Vertex(t[1]), Vertex(t[2])) == Result::null_face())
      throw Input_error(source, element,
                        "non-manifold edge or vertex, orientation inconsistent with its neighbours, or a repeated "
                        "corner (" + user + " needs a manifold, consistently oriented triangle mesh)");
  }
  return result;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
