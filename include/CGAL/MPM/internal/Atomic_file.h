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
// the previous file untouched. A symbolic link is written through (the link
// stays); a device, FIFO or socket is written directly, never replaced.
// Throws Input_error naming `path` on failure, and when `path` is a file
// this process read while inputs are guarded.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

// Throws Input_error naming `path` unless it is an existing, readable file
// (not a directory), so that readers which only report "failed" (CGAL's)
// are never the first to meet a missing file. Notes the file as an input.
void check_readable_file(const std::string& path);

// With `guard`, write_file_atomically() refuses from now on to replace a
// file this process reads (compared by identity, not by spelling): for a
// command-line tool, where an output named like an input is a typo; a
// program that saves what it loaded does not ask for it. Off by default.
void guard_inputs_against_overwriting(bool guard);

// SIGINT, SIGTERM, SIGHUP and SIGPIPE (a reader of standard output that
// stopped reading) remove the temporary files being written,
// then end the process as the signal would have.
void remove_temporary_files_on_signals();

// Another file for those signals to remove (a copy of standard input, say);
// returns its slot for forget_on_signals(), or -1 when all slots are taken.
int remove_on_signals(const std::string& path);
void forget_on_signals(int slot);

// Whole content of a file; throws Input_error naming `path` when it cannot be read.
std::string read_file(const std::string& path);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
