// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editing commands (`deform`, `symmetrize`, `caricature`) share
// everything but the embedding problem they solve: loading the model and the
// handles, the solver options, solving, writing the mesh and the summary.
// Each cmd_*.cpp describes its differences in an `Editing_command` and turns
// it into a table entry with `make_editing_command()`.
#ifndef CGAL_MPM_TOOL_EDITING_COMMON_H
#define CGAL_MPM_TOOL_EDITING_COMMON_H

#include "cli.h"

#include <CGAL/MPM/Solver/Embedding_problem.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <functional>
#include <string>
#include <vector>

namespace mpm {

/// What distinguishes one editing command from the others.
struct Editing_command
{
  std::string name;        ///< `deform`
  std::string summary;     ///< one line for `mpm --help`
  std::string synopsis;    ///< arguments specific to this command, before the shared options
  std::string description; ///< paragraphs for the usage text
  std::string done;        ///< past participle for the text summary (`Deformed`)
  std::vector<Option_spec> options; ///< options specific to this command
  /// Options that must be given besides `-o`, checked before any work
  /// (`handles` for `deform`, `factor` for `caricature`).
  std::vector<std::string> required;
  /// Builds the problem for training example `example` of `model`, and
  /// stores the command's own settings (as given or defaulted) in
  /// `settings`, which the summary reports under "options".
  std::function<CGAL::MPM::Embedding_problem(const Args& args, const CGAL::MPM::Morphable_part_model& model,
                                             int example, Json& settings)>
    make_problem;
};

/// The command-table entry: `editing`'s options followed by the shared ones
/// (`-o`, `--example`, `--handles`, solver options), run by the shared
/// implementation.
Command make_editing_command(const Editing_command& editing);

} // namespace mpm

#endif
