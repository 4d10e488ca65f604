// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_ELAPSED_TIME_H
#define CGAL_MPM_INTERNAL_ELAPSED_TIME_H

#include <chrono>

namespace CGAL {
namespace MPM {
namespace internal {

using Clock = std::chrono::steady_clock;

// Wall-clock milliseconds from `start` to now, as the reports give them.
inline double milliseconds_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
