// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `-` as a file name: standard input for one input file, standard output
// for one single-file output. The library reads and writes named files, so
// an input `-` is copied to a temporary file first, and an output `-` is
// written to one and copied to standard output once the command succeeded
// (a failed command writes nothing there). Messages name `-`, never the
// temporary files.
#ifndef MPM_TOOL_STANDARD_STREAMS_H
#define MPM_TOOL_STANDARD_STREAMS_H

#include "cli.h"

#include <memory>
#include <streambuf>
#include <string>
#include <vector>

namespace mpm {

class Standard_streams
{
public:
  /// Replaces every `-` of `args` that names a file by a temporary file;
  /// throws Usage_error for a `-` that cannot be one (an output prefix, a
  /// second input or output, an output beside `--json`, a terminal as input).
  /// While an output goes to standard output, what the command prints for
  /// the user goes to standard error.
  Standard_streams(const Command& command, Args& args, bool json);
  ~Standard_streams();
  Standard_streams(const Standard_streams&) = delete;
  Standard_streams& operator=(const Standard_streams&) = delete;

  /// Copies the output written for `-` to standard output.
  void send_output();

private:
  // A temporary file standing for `-`, removed with its owner (also when
  // the constructor throws after making it) or by a signal.
  struct Temporary
  {
    std::string path;
    int slot = -1;
    ~Temporary();
  };
  Temporary input_, output_;
  std::streambuf* cout_buffer_ = nullptr;
  std::unique_ptr<std::streambuf> spelling_;
};

/// `text` with the temporary files standing for `-` named `-` again.
std::string as_the_user_wrote(std::string text);

} // namespace mpm

#endif
