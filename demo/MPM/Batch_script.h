// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The demo's batch mode (`mpm_demo --batch SCRIPT`): the edits of the window
// run from a script, one command a line, with screenshots and checks of
// them, for the tests and the manual's figures. The commands are listed in
// doc/MPM/Demo.md.
#ifndef MPM_DEMO_BATCH_SCRIPT_H
#define MPM_DEMO_BATCH_SCRIPT_H

#include <string>

namespace mpm_demo {

class Main_window;
class Session;

/// Runs the commands of the script file `script` on `session` shown in
/// `window`, echoing each command and its result to standard output.
/// Returns 0 when every command succeeded, 1 when the script cannot be read
/// or at the first failing command, whose error goes to standard error as
/// `SCRIPT:LINE: COMMAND: message`.
int run_batch_script(Session& session, Main_window& window, const std::string& script);

} // namespace mpm_demo

#endif
