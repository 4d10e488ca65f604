// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_DOCKING_RULE_H
#define CGAL_MPM_DOCKING_RULE_H

#include <CGAL/MPM/Docking_site.h>
#include <CGAL/MPM/Part_type.h>
#include <CGAL/MPM/Shape_space.h>

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
/// A rule of the grammar: one observed way two docking sites meet, with the
/// shape space of its pair geometry. Seam vertices of a boundary docking
/// appear once in `points`, on side 0; `seam` says which local vertex of the
/// second part each of them is.
struct Docking_rule
{
  Site_ref first;                        ///< docking site of the side-0 part
  Site_ref second;                       ///< docking site of the side-1 part
  Docking_kind kind = Docking_kind::boundary; ///< boundary or generalized
  std::vector<std::pair<int, int>> seam; ///< (local of first, local of second) identified vertices
  std::vector<Pair_point> points;        ///< the pair geometry's points
  std::vector<Cluster_edge> edges;       ///< its edges (indices into `points`)
  Shape_space space;                     ///< shape space of the pair geometry
};

} // namespace MPM
} // namespace CGAL

#endif
