// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_EDGE_FACES_H
#define CGAL_MPM_INTERNAL_EDGE_FACES_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// An undirected edge of an indexed mesh, the smaller vertex first.
using Mesh_edge = std::pair<int, int>;

// Faces around each edge, in face order: one face on a border, two inside,
// more on a non-manifold edge. Works on any triangle soup, where a halfedge
// structure could not even be built (the checks of segmentations need that).
inline std::map<Mesh_edge, std::vector<int>> faces_of_edges(const Indexed_mesh& mesh)
{
  std::map<Mesh_edge, std::vector<int>> r;
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      r[{std::min(a, b), std::max(a, b)}].push_back(int(f));
    }
  return r;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
