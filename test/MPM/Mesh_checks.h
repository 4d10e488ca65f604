// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks on assembled meshes shared by the assembly suites: border edges and
// self-intersections (through CGAL's Polygon_mesh_processing).
#ifndef CGAL_MPM_TEST_MESH_CHECKS_H
#define CGAL_MPM_TEST_MESH_CHECKS_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace mpm_test {

// Edges with exactly one incident triangle.
inline int border_edges(const std::vector<CGAL::MPM::Triangle>& triangles)
{
  std::map<std::pair<int, int>, int> count;
  for(const CGAL::MPM::Triangle& t : triangles)
    for(int k = 0; k < 3; ++k) ++count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  int border = 0;
  for(const auto& [edge, c] : count) border += c == 1;
  return border;
}

inline bool self_intersects(const CGAL::MPM::Indexed_mesh& mesh)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  CGAL::Surface_mesh<K::Point_3> sm;
  std::vector<CGAL::Surface_mesh<K::Point_3>::Vertex_index> v;
  for(int i = 0; i < mesh.number_of_vertices(); ++i)
    v.push_back(sm.add_vertex(K::Point_3(mesh.points(i, 0), mesh.points(i, 1), mesh.points(i, 2))));
  for(const CGAL::MPM::Triangle& t : mesh.triangles) // a non-manifold or misoriented gluing fails here
    EXPECT_NE(sm.add_face(v[t[0]], v[t[1]], v[t[2]]), CGAL::Surface_mesh<K::Point_3>::null_face());
  return CGAL::Polygon_mesh_processing::does_self_intersect(sm);
}

} // namespace mpm_test

#endif
