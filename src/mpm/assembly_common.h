// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared by `mpm graph`, `mpm assemble` and `mpm spawn`: loading the model
// with its grammar (learned rules plus derived repetition rules), writing an
// assembled mesh with per-face colours by part type, and its summary.
#ifndef CGAL_MPM_TOOL_ASSEMBLY_COMMON_H
#define CGAL_MPM_TOOL_ASSEMBLY_COMMON_H

#include "cli.h"

#include <CGAL/MPM/Assembly.h>
#include <CGAL/MPM/Morphable_part_model.h>

#include <string>

namespace mpm {

/// The model at `path` with the repetition rules appended unless
/// `observed_only` (doc/MPM/Part_graphs.md); `derived` receives their count.
CGAL::MPM::Morphable_part_model load_model_with_grammar(const std::string& path, bool observed_only,
                                                         int* derived = nullptr);

/// Refuses (usage error) an output mesh name that is not .off, .obj or .ply.
void check_mesh_output(const std::string& option, const std::string& path);

/// Writes the assembled mesh; PLY files get a colour per face by part type
/// (the palette of the editing commands).
void write_assembly_mesh(const CGAL::MPM::Assembly& assembly, const std::string& path,
                         const CGAL::MPM::Mesh_write_options& options);

/// Residual energy, per part, per node and per docking, timings.
Json assembly_summary(const CGAL::MPM::Morphable_part_model& model, const CGAL::MPM::Assembly& assembly);

} // namespace mpm

#endif
