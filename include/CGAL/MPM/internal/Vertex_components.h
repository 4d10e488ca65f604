// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_VERTEX_COMPONENTS_H
#define CGAL_MPM_INTERNAL_VERTEX_COMPONENTS_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/IO/Mesh_io.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// Per vertex, the connected component (connected_component_labels()) of
// its triangles, -1 for a vertex in no triangle; a vertex where components
// touch at a corner only takes the component of its last triangle.
// `count`, when given, receives the number of components.
inline std::vector<int> vertex_component_labels(const Indexed_mesh& mesh, int* count = nullptr)
{
  const std::vector<int> face_component = connected_component_labels(mesh);
  std::vector<int> component(std::size_t(mesh.number_of_vertices()), -1);
  for(std::size_t f = 0; f < face_component.size(); ++f)
    for(int v : mesh.triangles[f]) component[std::size_t(v)] = face_component[f];
  if(count) *count = face_component.empty() ? 0 : *std::max_element(face_component.begin(), face_component.end()) + 1;
  return component;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
