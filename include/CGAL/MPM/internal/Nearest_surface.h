// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_NEAREST_SURFACE_H
#define CGAL_MPM_INTERNAL_NEAREST_SURFACE_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

#include <memory>

namespace CGAL {
namespace MPM {
namespace internal {

// Queries against one surface with its search tree built once for many
// queries: the closest point, and whether a triangle lies turned over on
// the surface (the test of `folded_faces()`).
class Nearest_surface
{
public:
  explicit Nearest_surface(const Indexed_mesh& surface);
  ~Nearest_surface();
  Eigen::Vector3d closest_point(const Eigen::Vector3d& p) const;
  // Whether the triangle's normal points against the normal of the face
  // nearest to its centroid.
  bool folded(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
