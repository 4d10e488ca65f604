// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_MODEL_IO_H
#define CGAL_MPM_MODEL_IO_H

#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <cstdint>
#include <string>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Version of the model file format written by this library.
constexpr std::uint32_t model_file_version = 3;

/// \ingroup PkgMPMRef
/// The model as bytes of the versioned model format: a magic string, the
/// format version, the payload length, the payload and a CRC-32 of it.
std::string serialize_model(const Morphable_part_model& model);

/// \ingroup PkgMPMRef
/// Parses bytes written by `serialize_model()`. Throws `Input_error` naming
/// `source` for a foreign file, another format version, a truncated or
/// damaged payload (checksum), or inconsistent contents.
Morphable_part_model deserialize_model(const std::string& bytes, const std::string& source);

/// \ingroup PkgMPMRef
/// Saves a model (temporary file renamed into place).
void save_model(const Morphable_part_model& model, const std::string& path);

/// \ingroup PkgMPMRef
/// Loads a model saved by `save_model()`.
Morphable_part_model load_model(const std::string& path);

} // namespace MPM
} // namespace CGAL

#endif
