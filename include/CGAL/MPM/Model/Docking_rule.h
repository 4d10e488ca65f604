// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_DOCKING_RULE_H
#define CGAL_MPM_DOCKING_RULE_H

#include <CGAL/MPM/Model/Docking_site.h>
#include <CGAL/MPM/Model/Part_type.h>
#include <CGAL/MPM/Model/Shape_space.h>

#include <array>
#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// A point of a pair geometry: a local vertex of the first (side 0) or of
/// the second (side 1) part of the docking.
struct Pair_point
{
  int side = 0;  ///< 0: the part at `Docking_rule::first`, 1: at `second`
  int local = 0; ///< local vertex id in that part's type
};

/// \ingroup PkgMPMRef
/// A vertex of the merged seam of a boundary docking between two loops
/// sampled differently (see `Docking_rule::merged_seam`): a local vertex of
/// one side or of both. On a side where it is not a local vertex it is
/// *inserted*: it splits that side's border edge `from[side] -> to[side]`
/// (directed as that side's boundary half-edge) at `weight[side]` of its
/// length, and its statistics (mean position, modes) are interpolated
/// linearly between those two loop neighbours.
struct Seam_vertex
{
  double parameter = 0.; ///< arc-length parameter along the first site's loop, in [0, 1)
  std::array<int, 2> local = {{-1, -1}};  ///< local vertex on side 0 / side 1; -1: inserted there
  std::array<int, 2> from = {{-1, -1}};   ///< on a side where it is inserted: start of the split border edge
  std::array<int, 2> to = {{-1, -1}};     ///< ... and its end
  std::array<double, 2> weight = {{0., 0.}}; ///< ... and where on it: (1 - w) from + w to
};

/// \ingroup PkgMPMRef
/// A rule of the grammar: one observed way two docking sites meet, with the
/// shape space of its pair geometry. Seam vertices of a boundary docking
/// appear once in `points`, on side 0; `seam` says which local vertex of the
/// second part each of them is. When the two seams are sampled differently
/// (a derived rule between loops of different vertex counts, see
/// `derive_docking_rule()`), `merged_seam` is their union ordered along the
/// first site's loop, and `seam` keeps only the pairs of local vertices that
/// coincide in it.
struct Docking_rule
{
  Site_ref first;                        ///< docking site of the side-0 part
  Site_ref second;                       ///< docking site of the side-1 part
  Docking_kind kind = Docking_kind::boundary; ///< boundary or generalized
  std::vector<std::pair<int, int>> seam; ///< (local of first, local of second) identified vertices
  /// The merged loop of two differently sampled seams; empty when the seams
  /// are sampled alike (then `seam` is the whole correspondence).
  std::vector<Seam_vertex> merged_seam;
  std::vector<Pair_point> points;        ///< the pair geometry's points
  std::vector<Cluster_edge> edges;       ///< its edges (indices into `points`)
  Shape_space space;                     ///< shape space of the pair geometry
};

} // namespace MPM
} // namespace CGAL

#endif
