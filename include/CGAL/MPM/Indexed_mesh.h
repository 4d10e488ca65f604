// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INDEXED_MESH_H
#define CGAL_MPM_INDEXED_MESH_H

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Positions of n points, one row per point (n x 3).
using Point_matrix = Eigen::Matrix<double, Eigen::Dynamic, 3>;

/// \ingroup PkgMPMRef
/// A triangle as three vertex indices.
using Triangle = std::array<int, 3>;

/// \ingroup PkgMPMRef
/// The plain triangle mesh the learning and solving code works on. Generic
/// FaceGraph inputs are converted to it once (see `Face_graph_conversion.h`);
/// vertex `i` is row `i` of `points`, in the input's vertex order.
struct Indexed_mesh
{
  Point_matrix points;            ///< n x 3 vertex positions
  std::vector<Triangle> triangles; ///< faces, in the input's face order

  /// Number of vertices.
  int number_of_vertices() const { return static_cast<int>(points.rows()); }
  /// Number of triangles.
  int number_of_faces() const { return static_cast<int>(triangles.size()); }
};

/// \ingroup PkgMPMRef
/// A mesh with one part label per face. `source` names where it came from
/// (a file name), so that errors found later can name the file.
struct Labeled_mesh
{
  Indexed_mesh mesh;            ///< the geometry
  std::vector<int> face_labels; ///< one non-negative label per triangle
  std::string source;           ///< file name or description, for error messages
};

} // namespace MPM
} // namespace CGAL

#endif
