// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_ANNOTATION_IO_H
#define CGAL_MPM_ANNOTATION_IO_H

#include <CGAL/MPM/Model/Model_parameters.h>

#include <string>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Parses the JSON annotation format (see the manual's file formats page).
/// `source` names the text's origin in error messages. Throws `Input_error`
/// for malformed JSON, unknown keys, wrong types and out-of-range values
/// (for example a docking radius of zero or less).
Annotation parse_annotation(const std::string& text, const std::string& source);

/// \ingroup PkgMPMRef
/// Reads and parses an annotation file.
Annotation read_annotation(const std::string& path);

/// \ingroup PkgMPMRef
/// The annotation as JSON text (parsed back by `parse_annotation()`).
std::string annotation_to_json(const Annotation& annotation);

/// \ingroup PkgMPMRef
/// Writes an annotation file (temporary file renamed into place).
void write_annotation(const Annotation& annotation, const std::string& path);

} // namespace MPM
} // namespace CGAL

#endif
