// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared by `mpm graph`, `mpm assemble` and `mpm spawn`: loading the model
// with its grammar (learned rules plus derived repetition rules), writing an
// assembled mesh with per-face colours by part type, and its summary.
#ifndef CGAL_MPM_TOOL_ASSEMBLY_COMMON_H
#define CGAL_MPM_TOOL_ASSEMBLY_COMMON_H

#include "cli.h"

#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <string>

namespace mpm {

/// The model at `path` with the repetition and bridging rules appended
/// unless `observed_only` (doc/MPM/Part_graphs.md); `derived` receives
/// their count.
CGAL::MPM::Morphable_part_model load_model_with_grammar(const std::string& path, bool observed_only,
                                                         int* derived = nullptr);

/// Refuses (usage error) an output mesh name that is not .off, .obj or .ply.
void check_mesh_output(const std::string& option, const std::string& path);

/// Writes the assembled mesh; PLY files get a colour per face by part type
/// (the palette of the editing commands).
void write_assembly_mesh(const CGAL::MPM::Assembly& assembly, const std::string& path,
                         const CGAL::MPM::Mesh_write_options& options);

/// Energy per part of the training example's own graph assembled with
/// `options`: what an assembly from this model normally leaves.
double training_energy_per_part(const CGAL::MPM::Morphable_part_model& model, int example,
                                CGAL::MPM::Assembly_options options);

/// What makes an assembly doubtful, one sentence each (empty: nothing): the
/// solve stopped at the iteration cap, or the residual energy per part is
/// over 10^3 times `reference` (`training_energy_per_part()`), as a cycle
/// that cannot close or parts forced far apart leave. `closed` lists the
/// cycles closed on the command line, named in the sentences.
std::vector<std::string> assembly_doubts(const CGAL::MPM::Assembly& assembly, double reference,
                                         const std::vector<std::string>& closed);

/// Residual energy, per part, per node and per docking, timings.
Json assembly_summary(const CGAL::MPM::Morphable_part_model& model, const CGAL::MPM::Assembly& assembly);

} // namespace mpm

#endif
