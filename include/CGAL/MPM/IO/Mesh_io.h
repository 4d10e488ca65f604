// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_MESH_IO_H
#define CGAL_MPM_MESH_IO_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// A mesh as read from a file, with what the reader had to do to it.
struct Mesh_file
{
  Indexed_mesh mesh;              ///< triangles (polygons are fan-triangulated)
  std::vector<int> file_face;     ///< for each triangle, the index of the face in the file
  int number_of_file_faces = 0;   ///< faces as counted in the file
  std::vector<std::string> warnings; ///< one line each, naming file and element
};

/// \ingroup PkgMPMRef
/// Reads an OFF, OBJ, PLY or STL file through CGAL's IO. Polygons with more
/// than three corners are fan-triangulated (with a warning). Throws
/// `Input_error` naming the file and the element for a missing, unreadable,
/// empty or malformed file, an index out of range, a non-finite coordinate
/// or a degenerate face. The file is only read.
Mesh_file read_mesh_file(const std::string& path);

/// \ingroup PkgMPMRef
/// Reads a Princeton Segmentation Benchmark `.seg` file: one integer label per
/// face, in face order, separated by white space. Throws `Input_error` for
/// a non-numeric or negative entry (naming its line).
std::vector<int> read_seg_file(const std::string& path);

/// \ingroup PkgMPMRef
/// Reads a mesh and its part labels. `labels` is a `.seg` file, the word
/// `components` (one label per connected component) or `property:NAME` (an
/// integer face property of a PLY file). Labels given per file face are
/// expanded to the triangles made from it. Throws `Input_error` when the
/// label count differs from the face count.
Labeled_mesh read_labeled_mesh(const std::string& mesh_path, const std::string& labels,
                               std::vector<std::string>* warnings = nullptr);

/// \ingroup PkgMPMRef
/// Labels of the connected components of a triangle soup (faces sharing an
/// edge are connected), numbered in order of their first face.
std::vector<int> connected_component_labels(const Indexed_mesh& mesh);

/// \ingroup PkgMPMRef
/// How `write_mesh_file()` encodes a mesh.
struct Mesh_write_options
{
  /// PLY and STL: binary (little-endian) instead of ASCII. OFF and OBJ are
  /// always ASCII.
  bool binary = false;
};

/// \ingroup PkgMPMRef
/// Writes a mesh as OFF, OBJ, PLY or STL (chosen by extension). With
/// `face_colors` (one RGB row per face, 0..255), PLY files get per-face
/// colours. STL has no shared vertices: each triangle is written with its
/// own three corners (single precision when binary). The file is written to
/// a temporary name and renamed into place.
void write_mesh_file(const Indexed_mesh& mesh, const std::string& path,
                     const Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>* face_colors = nullptr,
                     const Mesh_write_options& options = Mesh_write_options());

/// \ingroup PkgMPMRef
/// Writes labels in `.seg` format (temporary file renamed into place).
void write_seg_file(const std::vector<int>& labels, const std::string& path);

/// \ingroup PkgMPMRef
/// Checks a labelled mesh before learning: finite coordinates, triangles
/// with distinct in-range vertices and non-zero area, one non-negative label
/// per face. Throws `Input_error` naming `mesh.source` and the element.
void validate_labeled_mesh(const Labeled_mesh& mesh);

} // namespace MPM
} // namespace CGAL

#endif
