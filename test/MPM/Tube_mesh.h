// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An open tube, straight or bent, shared by the correspondence and editing suites.
#ifndef CGAL_MPM_TEST_TUBE_MESH_H
#define CGAL_MPM_TEST_TUBE_MESH_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

#include <cmath>
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

// Positions of a tube of `rings` x `sides` vertices (see tube_triangles())
// of the given length and radius, bent along a circular arc of total angle
// `angle` (0: straight, along z), lengths along the axis kept.
inline CGAL::MPM::Point_matrix bent_tube(int rings, int sides, double length, double radius, double angle)
{
  CGAL::MPM::Point_matrix p(rings * sides, 3);
  for(int r = 0; r < rings; ++r)
  {
    const double t = length * r / (rings - 1), phi = angle * t / length;
    const Eigen::RowVector3d centre =
      angle == 0. ? Eigen::RowVector3d(0., 0., t)
                  : Eigen::RowVector3d(0., length / angle * (1. - std::cos(phi)), length / angle * std::sin(phi));
    const Eigen::RowVector3d across(0., std::cos(phi), -std::sin(phi));
    for(int s = 0; s < sides; ++s)
    {
      const double alpha = 2. * M_PI * s / sides;
      p.row(r * sides + s) = centre + radius * (std::cos(alpha) * Eigen::RowVector3d::UnitX() + std::sin(alpha) * across);
    }
  }
  return p;
}

} // namespace mpm_test

#endif
