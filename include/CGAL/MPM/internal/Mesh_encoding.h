// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_MESH_ENCODING_H
#define CGAL_MPM_INTERNAL_MESH_ENCODING_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

#include <iosfwd>

namespace CGAL {
namespace MPM {
namespace internal {

// STL: one facet per triangle with its unit normal (zero for a degenerate
// one). Binary: an 80-byte header, the facet count and 50 bytes per facet,
// little-endian floats, as every reader expects; ASCII otherwise.
void write_stl(std::ostream& out, const Indexed_mesh& mesh, bool binary);

// Binary little-endian PLY: double coordinates, int corner indices, and
// per-face RGB colours when `face_colors` is given.
void write_binary_ply(std::ostream& out, const Indexed_mesh& mesh,
                      const Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>* face_colors);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
