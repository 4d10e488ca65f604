// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The MESH arguments of `mpm learn` and `mpm fit`, each with the
// --labels/--annotation (and, for learn, --write-annotation) that follow it.
#ifndef MPM_TOOL_MESH_FILES_H
#define MPM_TOOL_MESH_FILES_H

#include "cli.h"

#include <string>
#include <vector>

namespace mpm {

struct Mesh_files
{
  std::string mesh, labels, annotation;
  std::string write_annotation; // --write-annotation FILE: where proposed part types go
  bool labels_given = false, annotation_given = false;
  bool proposed = false; // part types proposed by propose_part_types()
};

// Positional arguments are meshes (after the first, the model, when
// `first_is_model`). Labels default to MESH.seg when it exists, else
// "components"; the annotation to MESH.json when it exists.
// `--write-annotation` is accepted when `write_annotation` is true.
std::vector<Mesh_files> collect_mesh_files(const Args& args, bool first_is_model, bool write_annotation);

// The --labels and --annotation options that collect_mesh_files() reads,
// repeatable, each for the MESH before it.
std::vector<Option_spec> mesh_file_options();

} // namespace mpm

#endif
