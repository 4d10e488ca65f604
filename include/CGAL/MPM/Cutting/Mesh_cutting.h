// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_MESH_CUTTING_H
#define CGAL_MPM_MESH_CUTTING_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// One cutting line as the user draws it: a few mesh vertices in order.
/// Consecutive vertices are joined by shortest paths along mesh edges.
struct Cut_line
{
  std::vector<int> vertices;   ///< at least two distinct vertex indices, in order along the cut
  std::optional<bool> closed;  ///< join the last vertex back to the first; empty: `Cutting_options::closed`
  std::string name;            ///< shown in messages and summaries (may be empty)
};

/// \ingroup PkgMPMRef
/// Names the region that contains `seed` (a vertex strictly inside it) with `label`.
struct Part_seed
{
  int label = 0; ///< non-negative face label of the region
  int seed = 0;  ///< a vertex of the region not on any cut
};

/// \ingroup PkgMPMRef
/// What to cut and how to label the pieces (the cut file's content, see
/// `doc/MPM/File_formats.md`).
struct Cut_specification
{
  std::vector<Cut_line> cuts;   ///< the cutting lines
  std::vector<Part_seed> parts; ///< labels of chosen regions; the others are numbered automatically
  std::string source;           ///< file name or description, for error messages
};

/// \ingroup PkgMPMRef
/// Options of `cut_mesh()`.
struct Cutting_options
{
  /// Strength of the feature term: an edge costs its length divided by
  /// `1 + feature_weight * c`, where `c` is the edge's concave bending angle
  /// (0 on convex and flat edges) relative to the mean absolute bending angle
  /// of the mesh. So paths snap to valleys such as the crease where a limb
  /// meets a body; 0 gives pure edge-graph geodesics. Must be finite and >= 0.
  double feature_weight = 1.;
  /// Whether cuts without their own `closed` flag are loops (around a limb)
  /// rather than open lines (from border to border).
  bool closed = true;
};

/// \ingroup PkgMPMRef
/// The cuts' paths; what `cut_mesh()` over the user's face graph returns,
/// the labels being in its face label map. `Vertex` names a vertex: its
/// index in the indexed mesh, its descriptor in the face graph.
template <class Vertex>
struct Cut_paths
{
  /// Vertex path of each cut, in the order of `Cut_specification::cuts`;
  /// a closed cut ends with its first vertex again.
  std::vector<std::vector<Vertex>> paths;
  /// Euclidean length of each path.
  std::vector<double> lengths;
  /// Number of face-connected regions (equal to the number of labels).
  int regions = 0;
};

/// \ingroup PkgMPMRef
/// The cut indexed mesh and the cuts' paths.
struct Cutting_result : Cut_paths<int>
{
  /// The input geometry, unchanged, with one label per face: a region named
  /// by a `Part_seed` gets its label; the others, in order of their lowest
  /// face index, get the smallest non-negative labels not used by a seed.
  Labeled_mesh mesh;
};

/// \ingroup PkgMPMRef
/// Cuts `mesh` along the cutting lines of `cuts` and labels the
/// face-connected regions the cuts separate (the paper's section 4, "part
/// correspondences"). Each pair of consecutive cut vertices is joined by a
/// Dijkstra shortest path on the edge graph (feature-weighted, see
/// `Cutting_options::feature_weight`) that avoids the cut's earlier
/// vertices, so a loop of two or more points goes around a limb without
/// doubling back. `mesh_source` names the mesh in error messages.
///
/// Throws `Input_error` for: bad geometry (as `validate_labeled_mesh()`), a
/// non-manifold edge or inconsistently oriented faces; a cut with fewer than
/// two vertices, a vertex out of range or listed twice; consecutive cut
/// vertices on different connected components (no path); a cut whose removal
/// does not lower the region count (it separates nothing); a negative or
/// repeated label; a seed out of range, on a cut or on no face; two seeds in
/// one region. Messages name the cut (`cuts[2] "front left leg"`) or the part.
Cutting_result cut_mesh(const Indexed_mesh& mesh, const Cut_specification& cuts,
                        const Cutting_options& options = Cutting_options(),
                        const std::string& mesh_source = "mesh");

/// \ingroup PkgMPMRef
/// Parses the JSON cut file format (`"format": "cgal-mpm-cuts"`, see the
/// manual's file formats page). Throws `Input_error` for malformed JSON,
/// unknown keys and wrong types; vertex indices are checked against the
/// mesh by `cut_mesh()`.
Cut_specification parse_cut_specification(const std::string& text, const std::string& source);

/// \ingroup PkgMPMRef
/// Reads and parses a cut file.
Cut_specification read_cut_specification(const std::string& path);

} // namespace MPM
} // namespace CGAL

#endif
