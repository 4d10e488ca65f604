// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <CGAL/MPM/Input_error.h>

namespace CGAL {
namespace MPM {
namespace internal {

Indexed_surface_mesh to_surface_mesh(const Indexed_mesh& mesh, const std::string& source, const std::string& user)
{
  using vertex_descriptor = Indexed_surface_mesh::Vertex_index;
  Indexed_surface_mesh result;
  const int n = mesh.number_of_vertices();
  for(int v = 0; v < n; ++v)
    result.add_vertex(Indexed_surface_mesh::Point(mesh.points(v, 0), mesh.points(v, 1), mesh.points(v, 2)));
  for(int f = 0; f < mesh.number_of_faces(); ++f) {
    const Triangle& t = mesh.triangles[std::size_t(f)];
    const std::string element = "face " + std::to_string(f);
    for(int corner : t)
      if(corner < 0 || corner >= n)
        throw Input_error(source, element, "vertex " + std::to_string(corner) + " is out of range (the mesh has " +
                                             std::to_string(n) + " vertices)");
    if(result.add_face(vertex_descriptor(t[0]), vertex_descriptor(t[1]), vertex_descriptor(t[2])) ==
       Indexed_surface_mesh::null_face())
      throw Input_error(source, element,
                        "non-manifold edge or vertex, orientation inconsistent with its neighbours, or a repeated "
                        "corner (" + user + " needs a manifold, consistently oriented triangle mesh)");
  }
  return result;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
