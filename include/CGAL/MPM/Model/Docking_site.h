// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_DOCKING_SITE_H
#define CGAL_MPM_DOCKING_SITE_H

#include <tuple>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// How two parts attach.
enum class Docking_kind
{
  boundary,   ///< the parts share seam vertices (watertight)
  generalized ///< the parts are disconnected; virtual edges tie them
};

/// \ingroup PkgMPMRef
/// A region of a part type where another part attaches. For a boundary
/// docking it is the seam: the local vertices shared with the neighbour;
/// for a generalized docking, the local vertices within the docking radius
/// of the neighbour (united over all observations).
struct Docking_site
{
  Docking_kind kind = Docking_kind::boundary; ///< boundary or generalized
  std::vector<int> vertices;                  ///< sorted local vertex ids
};

/// \ingroup PkgMPMRef
/// Names one docking site of the model: part type and site index.
struct Site_ref
{
  int type = -1; ///< index of the part type in the model
  int site = -1; ///< index of the site in that type's `sites`

  /// Lexicographic order, so that site references can key maps.
  friend bool operator<(const Site_ref& a, const Site_ref& b)
  { return std::tie(a.type, a.site) < std::tie(b.type, b.site); }
  /// Equality of type and site.
  friend bool operator==(const Site_ref& a, const Site_ref& b)
  { return a.type == b.type && a.site == b.site; }
};

} // namespace MPM
} // namespace CGAL

#endif
