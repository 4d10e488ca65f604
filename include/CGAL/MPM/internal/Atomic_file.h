// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_ATOMIC_FILE_H
#define CGAL_MPM_INTERNAL_ATOMIC_FILE_H

#include <functional>
#include <iosfwd>
#include <string>

namespace CGAL {
namespace MPM {
namespace internal {

// Writes through `write` into a temporary file next to `path` and renames it
// into place, so a reader never sees a half-written file and a failure leaves
// the previous file untouched. Throws Input_error naming `path` on failure.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

// Throws Input_error naming `path` unless it is an existing, readable file
// (not a directory), so that readers which only report "failed" (CGAL's)
// are never the first to meet a missing file.
void check_readable_file(const std::string& path);

// Whole content of a file; throws Input_error naming `path` when it cannot be read.
std::string read_file(const std::string& path);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
