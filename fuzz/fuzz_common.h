// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared by the libFuzzer targets: the expected failures (Input_error,
// Computation_error) are swallowed, anything else escapes and is a finding.
#ifndef CGAL_MPM_FUZZ_COMMON_H
#define CGAL_MPM_FUZZ_COMMON_H

#include <CGAL/MPM/Input_error.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace mpm_fuzz {

template <class F>
void expect_input_errors_only(F&& f)
{
  try
  {
    f();
  }
  catch(const CGAL::MPM::Input_error&)
  {
  }
  catch(const CGAL::MPM::Computation_error&)
  {
  }
}

inline std::string as_string(const std::uint8_t* data, std::size_t size)
{
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Writes `bytes` to `path`, aborting when the file system fails (that is not
// a finding about the readers, but it must not pass silently).
inline void write_bytes(const std::string& path, const std::string& bytes)
{
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if(f == nullptr) { std::perror(path.c_str()); std::abort(); }
  if(!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size())
  { std::perror(path.c_str()); std::abort(); }
  std::fclose(f);
}

// With MPM_FUZZ_WRITE_SEED=path set, a target writes a valid input it built
// itself (for the corpus) to `path` during initialization.
inline void maybe_write_seed(const std::string& bytes)
{
  if(const char* path = std::getenv("MPM_FUZZ_WRITE_SEED"))
    write_bytes(path, bytes);
}

} // namespace mpm_fuzz

#endif
