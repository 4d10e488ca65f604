// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_CANCELLATION_H
#define CGAL_MPM_CANCELLATION_H

#include <atomic>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Thrown by a long computation (a solve, learning, correspondence, ARAP,
/// spawning) when the cancellation flag given in its options was raised.
/// The computation's inputs are unchanged; its partial results are dropped.
class Operation_cancelled : public std::runtime_error
{
public:
  /// `what` names the computation that stopped (`"solve"`, `"learning"`).
  explicit Operation_cancelled(const std::string& what) : std::runtime_error(what + " cancelled") {}
};

/// \ingroup PkgMPMRef
/// A cancellation flag, as the options of long computations take it
/// (`Embedding_options::cancel`, `Learning_options::cancel`, ...): another
/// thread, or a signal handler, stores `true` and the computation throws
/// `Operation_cancelled` at its next check (each iteration, segment, part
/// type or spawned graph). Null: never cancelled.
using Cancellation_flag = const std::atomic<bool>*;

namespace internal {

// The check the loops make: throws when `flag` was raised.
inline void throw_if_cancelled(Cancellation_flag flag, const char* computation)
{
  if(flag != nullptr && flag->load(std::memory_order_relaxed)) throw Operation_cancelled(computation);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
