// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_FOLD_TEST_H
#define CGAL_MPM_INTERNAL_FOLD_TEST_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

#include <memory>

namespace CGAL {
namespace MPM {
namespace internal {

// Whether a triangle lies turned over on `surface`: its normal points
// against the normal of the face of `surface` nearest to its centroid (the
// test of `folded_faces()`), with the surface's search tree built once for
// many triangles.
class Fold_test
{
public:
  explicit Fold_test(const Indexed_mesh& surface);
  ~Fold_test();
  bool folded(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
