// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_HANDLE_SET_H
#define CGAL_MPM_HANDLE_SET_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Handles of an edit: vertex `vertices[i]` is pulled to row `i` of `targets`.
/// Vertices are distinct.
struct Handle_set
{
  std::vector<int> vertices; ///< handle vertices, indices into the mesh
  Point_matrix targets;      ///< k x 3 target positions, one row per handle

  /// Number of handles.
  int size() const { return static_cast<int>(vertices.size()); }
};

/// \ingroup PkgMPMRef
/// Parses the JSON handle format (`doc/MPM/Handles.md`): each handle gives a
/// vertex and either an absolute `target` or an `offset` from its position in
/// `rest` (the mesh the handles belong to, n x 3). Handles repeated with the
/// same target are merged. `source` names the text's origin in error
/// messages. Throws `Input_error` naming the handle (`handles[3]`) for
/// malformed JSON, unknown keys, a vertex outside `rest`, a non-finite
/// target, both or neither of `target` and `offset`, one vertex with two
/// different targets, and an empty handle list.
Handle_set parse_handles(const std::string& text, const std::string& source, const Point_matrix& rest);

/// \ingroup PkgMPMRef
/// Checks a handle set against a mesh of `number_of_vertices` vertices: one
/// target per vertex, distinct in-range vertices, finite targets. Throws
/// `Input_error` naming `source` and the handle (`handles[3]`).
void validate_handles(const Handle_set& handles, int number_of_vertices, const std::string& source);

/// \ingroup PkgMPMRef
/// Reads and parses a handle file (see `parse_handles()`).
Handle_set read_handles(const std::string& path, const Point_matrix& rest);

/// \ingroup PkgMPMRef
/// The handles as JSON text with absolute targets (parsed back by
/// `parse_handles()` to the same set). Throws `Input_error` when the sizes
/// disagree or a target is not finite, which the format cannot hold.
std::string handles_to_json(const Handle_set& handles);

/// \ingroup PkgMPMRef
/// Writes a handle file (temporary file renamed into place).
void write_handles(const Handle_set& handles, const std::string& path);

/// \ingroup PkgMPMRef
/// `count` handles spread over the mesh by farthest-point sampling on the
/// rest positions (Euclidean distance): the first is the vertex farthest
/// from the centroid, each next one the vertex farthest from those chosen;
/// ties go to the smallest index, so the choice is deterministic. Targets
/// are the handle vertices' rows of `targets_source` (n x 3, e.g. a held-out
/// pose). Throws `Input_error` when `count` is not in [1, n] or
/// `targets_source` has the wrong number of rows.
Handle_set farthest_point_handles(const Indexed_mesh& mesh, int count, const Point_matrix& targets_source);

/// \ingroup PkgMPMRef
/// One or two handles per part (face label), parts in increasing label
/// order: the part vertex nearest to the part's centroid and, when
/// `per_part` is 2, also the part vertex farthest from it (ties to the
/// smallest index). A seam vertex picked by two parts counts once. Targets
/// come from `targets_source` as in `farthest_point_handles()`. Throws
/// `Input_error` when `per_part` is not 1 or 2, or the sizes disagree.
Handle_set handles_per_part(const Labeled_mesh& mesh, int per_part, const Point_matrix& targets_source);

} // namespace MPM
} // namespace CGAL

#endif
