// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared pieces of the `mpm` command-line tool: the command table entry, a
// small typed argument parser, progress/warning output and output helpers.
// A subcommand is one file `cmd_NAME.cpp` defining `make_NAME_command()`,
// listed in `all_commands()` (main.cpp).
#ifndef CGAL_MPM_TOOL_CLI_H
#define CGAL_MPM_TOOL_CLI_H

#include <CGAL/MPM/IO/Mesh_io.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <iosfwd>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL { namespace MPM { struct Morphable_part_model; } }

namespace mpm {

/// JSON objects keep their keys in insertion order, so summaries read well.
using Json = nlohmann::ordered_json;

/// A wrong command line: exit code 2.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Exit codes of the tool. `exit_warning`: the result was written, but a
/// check found it doubtful (the warning says why; doc/MPM/Command_line.md).
enum Exit_code { exit_ok = 0, exit_failure = 1, exit_usage = 2, exit_warning = 3 };

/// What an option takes. Files are text with a role: an input file or a
/// single output file may be `-` (standard input or output); an output
/// prefix or directory names several files and may not.
enum class Value_kind { flag, integer, real, text, input_file, output_file, output_prefix };

/// One option of a command: `--name VALUE`, `--name=VALUE` or `-s VALUE`.
struct Option_spec
{
  std::string name;         ///< long name without the dashes
  char short_name = 0;      ///< one-letter alias, or 0
  Value_kind kind = Value_kind::flag;
  std::string value_name;   ///< shown in the usage (`N`, `FILE`)
  std::string default_text; ///< shown in the usage as "(default: ...)"
  std::string help;         ///< one sentence
  double min = -std::numeric_limits<double>::infinity(); ///< numbers: lower bound
  double max = std::numeric_limits<double>::infinity();  ///< numbers: upper bound
  bool min_exclusive = false; ///< numbers: the lower bound itself is invalid
  bool repeatable = false;    ///< may be given more than once
};

/// One command-line item in order: an option with its value, or a positional
/// argument (`option` empty).
struct Arg_item
{
  std::string option; ///< long name, or empty for a positional argument
  std::string value;  ///< the value ("" for flags)
};

/// The parsed command line of one command. Values were checked against
/// their `Option_spec` (type and range) while parsing.
class Args
{
public:
  std::vector<Arg_item> items; ///< everything, in command-line order

  bool has(const std::string& option) const;
  bool flag(const std::string& option) const { return has(option); }
  /// Last value of `option`, or `fallback`.
  std::string text(const std::string& option, const std::string& fallback = "") const;
  long long integer(const std::string& option, long long fallback) const;
  double real(const std::string& option, double fallback) const;
  std::vector<std::string> positionals() const;
};

class Progress;

/// What a command's `run` gets besides its arguments.
struct Context
{
  const std::string& command; ///< the subcommand's name
  bool json;                  ///< --json: one JSON object on stdout
  Progress& progress;         ///< progress and warnings on stderr
  /// --binary: PLY and STL meshes written in binary.
  CGAL::MPM::Mesh_write_options meshes;
};

/// An entry of the command table.
struct Command
{
  std::string name;        ///< `synth`
  std::string summary;     ///< one line for `mpm --help`
  std::string synopsis;    ///< after `mpm NAME `, e.g. `FAMILY [options] -o PREFIX`
  std::string description; ///< paragraphs printed after the synopsis (may be empty)
  std::vector<Option_spec> options; ///< command-specific options (common ones are added)
  std::string operand;     ///< name of the positional argument(s), e.g. `FAMILY`
  int min_positionals = 0;
  int max_positionals = 0; ///< -1: unlimited
  std::function<int(const Args&, Context&)> run; ///< returns the exit code
  /// Extensions of the files written next to an output prefix (`-o PREFIX`).
  std::vector<std::string> prefix_extensions;
  /// The positional arguments are files (`MODEL`, `MESH`), so `-` reads
  /// standard input; false where they are names (`FAMILY`).
  bool positionals_are_files = true;
};

/// Options every command takes (--json, --progress, --help).
const std::vector<Option_spec>& common_options();

/// Parses `arguments` (after the command name). Throws `Usage_error` for an
/// unknown option, a missing or malformed value, a repeated option or a
/// wrong number of positional arguments.
Args parse_arguments(const Command& command, const std::vector<std::string>& arguments);

/// The kind of `option` (a long name) of `command`; for "" (a positional
/// argument) `input_file` when the command's positionals are files.
Value_kind option_kind(const Command& command, const std::string& option);

/// True when `arguments` ask for help (`--help` or `-h` before any `--`).
bool wants_help(const std::vector<std::string>& arguments);

/// The full usage text of a command: synopsis, description, every option
/// with its default.
std::string usage_text(const Command& command);

/// Progress (stage and percentage) and warnings on stderr. Enabled when
/// stderr is a terminal or `--progress` was given; on a terminal it keeps
/// one line updated with `\r`, otherwise it prints plain lines (at each new
/// stage and every 10%).
class Progress
{
public:
  Progress(const std::string& command, bool requested);
  ~Progress();
  void update(const std::string& stage, double fraction);
  /// Clears the progress line (terminal) so that normal output follows.
  void done();
  /// `mpm: warning: MESSAGE` on stderr (clears the progress line first).
  void warning(const std::string& message);
  bool enabled() const { return enabled_; }

private:
  std::string command_;
  bool enabled_ = false, tty_ = false, line_open_ = false;
  std::string stage_;
  int percent_ = -1;
};

/// A solver's `Embedding_options::iteration_callback` that advances
/// `progress` in `stage` from `from` to `to` as the iterations approach
/// `max_iterations` (a solve of many parts sat at one percentage).
std::function<void(int, double)> iteration_progress(Progress& progress, const std::string& stage, double from,
                                                    double to, int max_iterations);

// ---- output helpers --------------------------------------------------------

/// Prints one JSON object on stdout (indented, one trailing newline).
void print_json(const Json& object);

/// `%.*g` formatting of a number (NaN/inf spelled out).
std::string format_number(double value, int digits = 4);

/// A text table with aligned columns; columns marked numeric are right-aligned.
class Table
{
public:
  explicit Table(std::vector<std::string> headers, std::vector<bool> numeric = {});
  void add_row(std::vector<std::string> cells);
  void print(std::ostream& out, const std::string& indent = "  ") const;
  bool empty() const { return rows_.empty(); }

private:
  std::vector<std::string> headers_;
  std::vector<bool> numeric_;
  std::vector<std::vector<std::string>> rows_;
};

// ---- file helpers ----------------------------------------------------------

/// Throws `CGAL::MPM::Input_error` naming both files when `output` is one of
/// `inputs`, compared by identity (not by spelling).
void refuse_overwriting(const std::string& output, const std::vector<std::string>& inputs);

/// `refuse_overwriting()` for every output of the command (`-o`,
/// `--write-annotation`; for a prefix, the prefix with each of
/// `Command::prefix_extensions`) against the files named on its command
/// line, before any work.
void refuse_outputs_over_inputs(const Command& command, const Args& args);

/// Throws `Usage_error` with the estimate when `bytes`, what `--option
/// value` would need, exceed the machine's physical memory: refused up front
/// rather than allocated until the machine gives out.
void check_memory(const std::string& option, const std::string& value, double bytes);

/// Throws `Usage_error` when the `-o PREFIX` of a command that writes files
/// next to a prefix names a directory (`dir/`), which would write `dir/.off`.
void check_output_prefix(const Command& command, const Args& args);

/// Creates the parent directory of `path` when it is missing; throws
/// `CGAL::MPM::Input_error` naming the directory when that fails.
void ensure_parent_directory(const std::string& path);

// ---- the commands ----------------------------------------------------------

Command make_synth_command();
Command make_learn_command();
Command make_info_command();
Command make_deform_command();
Command make_symmetrize_command();
Command make_caricature_command();

// ---- shared by learn and info ----------------------------------------------

/// Everything `mpm info` reports about a model, as JSON.
Json model_summary(const CGAL::MPM::Morphable_part_model& model, const std::string& path);

/// Renders `model_summary()` as aligned tables.
void print_model_summary(std::ostream& out, const Json& summary);

} // namespace mpm

#endif
