// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm`: the command-line tool of CGAL-MPM. Dispatches to the subcommands in
// the table below; each lives in its own cmd_NAME.cpp.
#include "cli.h"
#include "standard_streams.h"

#include <CGAL/MPM/internal/Atomic_file.h>

#include <CGAL/MPM/Input_error.h>

#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <sstream>

namespace mpm { Command make_compare_command(); } // cmd_compare.cpp
namespace mpm { Command make_assemble_command(); Command make_graph_command(); } // cmd_assemble.cpp
namespace mpm { Command make_spawn_command(); } // cmd_spawn.cpp
namespace mpm { Command make_handles_command(); } // cmd_handles.cpp
namespace mpm { Command make_cut_command(); } // cmd_cut.cpp
namespace mpm { Command make_correspond_command(); } // cmd_correspond.cpp
namespace mpm { Command make_fit_command(); } // cmd_fit.cpp

namespace {

// The command table: add a subcommand by writing cmd_NAME.cpp with a
// `make_NAME_command()` (declared in cli.h) and listing it here.
const std::vector<mpm::Command>& all_commands()
{
  static const std::vector<mpm::Command> commands = {
    mpm::make_synth_command(),
    mpm::make_learn_command(),
    mpm::make_info_command(),
    mpm::make_deform_command(),
    mpm::make_symmetrize_command(),
    mpm::make_caricature_command(),
    mpm::make_handles_command(),
    mpm::make_compare_command(),
    mpm::make_graph_command(),
    mpm::make_assemble_command(),
    mpm::make_spawn_command(),
    mpm::make_cut_command(),
    mpm::make_correspond_command(),
    mpm::make_fit_command(),
  };
  return commands;
}

const mpm::Command* find_command(const std::string& name)
{
  for(const mpm::Command& c : all_commands())
    if(c.name == name) return &c;
  return nullptr;
}

std::string general_usage()
{
  std::ostringstream s;
  s << "Usage: mpm COMMAND [options]\n"
       "       mpm help COMMAND | mpm COMMAND --help\n\n"
       "Morphable part models (CGAL-MPM): learn a shape space per part type and a\n"
       "docking grammar from part-labelled meshes, then inspect and edit them.\n\n"
       "Commands:\n";
  std::size_t width = 0;
  for(const mpm::Command& c : all_commands()) width = std::max(width, c.name.size());
  for(const mpm::Command& c : all_commands())
    s << "  " << c.name << std::string(width - c.name.size() + 2, ' ') << c.summary << "\n";
  s << "\nEvery command takes --json (one JSON object on stdout), --progress, --binary (PLY and STL\n"
       "meshes written in binary) and --help. A single input or output file may be '-'\n"
       "(standard input or output; meshes written there are OFF).\n"
       "Exit status: 0 success, 1 input or computation error, 2 usage error,\n"
       "3 result written with a warning.\n"
       "Manual: doc/MPM/Command_line.md\n";
  return s.str();
}

int fail(int code, const std::string& message)
{
  std::cout.flush();
  std::string line = mpm::as_the_user_wrote(message); // always one line
  for(char& ch : line)
    if(ch == '\n' || ch == '\r') ch = ' ';
  std::fprintf(stderr, "mpm: error: %s\n", line.c_str());
  return code;
}

const mpm::Command& command_or_throw(const std::string& name)
{
  const mpm::Command* c = find_command(name);
  if(c == nullptr) throw mpm::Usage_error("unknown command '" + name + "' (run 'mpm --help' for the list)");
  return *c;
}

int dispatch(const std::vector<std::string>& argv)
{
  if(argv.empty())
  {
    std::cerr << general_usage();
    return mpm::exit_usage;
  }
  const std::string& first = argv[0];
  if(first == "--help" || first == "-h" || (first == "help" && argv.size() == 1))
  {
    std::cout << general_usage();
    return mpm::exit_ok;
  }
  if(first == "help")
  {
    if(argv.size() > 2) throw mpm::Usage_error("'mpm help' takes one command name");
    std::cout << mpm::usage_text(command_or_throw(argv[1]));
    return mpm::exit_ok;
  }
  if(first.size() > 1 && first[0] == '-') throw mpm::Usage_error("unknown option '" + first + "' (run 'mpm --help')");

  const mpm::Command& command = command_or_throw(first);
  const std::vector<std::string> rest(argv.begin() + 1, argv.end());
  if(mpm::wants_help(rest))
  {
    std::cout << mpm::usage_text(command);
    return mpm::exit_ok;
  }
  mpm::Args args = mpm::parse_arguments(command, rest);
  CGAL::MPM::internal::remove_temporary_files_on_signals();
  mpm::Standard_streams standard_streams(command, args, args.flag("json"));
  mpm::check_output_prefix(command, args);
  mpm::refuse_outputs_over_inputs(command, args);
  CGAL::MPM::internal::guard_inputs_against_overwriting(true);
  mpm::Progress progress(command.name, args.flag("progress"));
  mpm::Context context{command.name, args.flag("json"), progress, CGAL::MPM::Mesh_write_options{args.flag("binary")}};
  const int status = command.run(args, context);
  if(status == mpm::exit_ok || status == mpm::exit_warning) standard_streams.send_output();
  return status;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return dispatch(std::vector<std::string>(argv + 1, argv + argc));
  }
  catch(const mpm::Usage_error& e)
  {
    return fail(mpm::exit_usage, e.what());
  }
  catch(const CGAL::MPM::Input_error& e)
  {
    return fail(mpm::exit_failure, e.what());
  }
  catch(const CGAL::MPM::Computation_error& e)
  {
    return fail(mpm::exit_failure, std::string("computation failed: ") + e.what());
  }
  catch(const std::bad_alloc&)
  {
    return fail(mpm::exit_failure, "out of memory");
  }
  catch(const std::exception& e)
  {
    return fail(mpm::exit_failure, e.what());
  }
}
