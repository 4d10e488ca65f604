// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_PARALLEL_FOR_H
#define CGAL_MPM_INTERNAL_PARALLEL_FOR_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace MPM {
namespace internal {

/// `body(i)` for every `i` in `[0, count)`: in parallel with TBB, in order
/// without it. Each `i` must write only its own results, so that nothing
/// depends on the scheduling.
template <class Index, class Body>
void parallel_for_each_index(Index count, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(Index(0), count, body);
#else
  for(Index i = 0; i < count; ++i) body(i);
#endif
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
