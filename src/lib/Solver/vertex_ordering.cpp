// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Vertex_ordering.h>

#include <Eigen/OrderingMethods>
#ifdef CGAL_MPM_HAS_CHOLMOD
#include <cholmod.h>
#endif

#include <algorithm>

namespace CGAL {
namespace MPM {
namespace internal {

void Vertex_ordering::operator()(const Eigen::SparseMatrix<double>& a, PermutationType& inverse) const
{
#ifdef CGAL_MPM_HAS_CHOLMOD
  if(a.isCompressed() && a.rows() > 0)
  {
    cholmod_common common;
    cholmod_start(&common);
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_AMD;
    common.postorder = 1;
    common.supernodal = CHOLMOD_SIMPLICIAL;
    common.print = 0;
    // The pattern of the lower triangle, read in place.
    cholmod_sparse pattern{};
    pattern.nrow = pattern.ncol = std::size_t(a.rows());
    pattern.nzmax = std::size_t(a.nonZeros());
    pattern.p = const_cast<int*>(a.outerIndexPtr());
    pattern.i = const_cast<int*>(a.innerIndexPtr());
    pattern.stype = -1;
    pattern.itype = CHOLMOD_INT;
    pattern.xtype = CHOLMOD_PATTERN;
    pattern.dtype = CHOLMOD_DOUBLE;
    pattern.sorted = 1;
    pattern.packed = 1;
    cholmod_factor* symbolic = cholmod_analyze(&pattern, &common);
    const bool ordered = symbolic != nullptr && common.status == CHOLMOD_OK;
    if(ordered)
    {
      inverse.resize(a.rows());
      const int* perm = static_cast<const int*>(symbolic->Perm);
      std::copy(perm, perm + a.rows(), inverse.indices().data());
    }
    cholmod_free_factor(&symbolic, &common);
    cholmod_finish(&common);
    if(ordered) return;
  }
#endif
  Eigen::AMDOrdering<int>()(a, inverse);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
