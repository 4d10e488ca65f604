// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The connectivity of an open tube, shared by the correspondence suites.
#ifndef CGAL_MPM_TEST_TUBE_MESH_H
#define CGAL_MPM_TEST_TUBE_MESH_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <vector>

namespace mpm_test {

// Triangles of `rings` rings of `sides` vertices, vertex r * sides + s,
// open at both ends, oriented outwards for rings counter-clockwise about +z.
inline std::vector<CGAL::MPM::Triangle> tube_triangles(int rings, int sides)
{
  std::vector<CGAL::MPM::Triangle> triangles;
  for(int r = 0; r + 1 < rings; ++r)
    for(int s = 0; s < sides; ++s)
    {
      const int a = r * sides + s, b = r * sides + (s + 1) % sides, c = a + sides, d = b + sides;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  return triangles;
}

} // namespace mpm_test

#endif
