// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm info MODEL`: part types, docking sites, rules, examples and parameters
// of a saved model.
#include "cli.h"

#include <CGAL/MPM/IO/Model_io.h>

#include <iostream>

namespace mpm {

namespace {

int run_info(const Args& args, Context& context)
{
  const std::string path = args.positionals().front();
  context.progress.update("loading " + path, 0.);
  const CGAL::MPM::Morphable_part_model model = CGAL::MPM::load_model(path);
  context.progress.done();
  const Json summary = model_summary(model, path);
  if(context.json) print_json(summary);
  else print_model_summary(std::cout, summary);
  return exit_ok;
}

} // namespace

Command make_info_command()
{
  Command c;
  c.name = "info";
  c.summary = "describe a saved model: part types, docking sites, rules, examples";
  c.synopsis = "MODEL [--json]";
  c.operand = "MODEL";
  c.description =
    "Per part type: instances, vertices, kept modes, the variance they explain, the\n"
    "first cumulative explained-variance fractions, the mode standard deviations and\n"
    "the largest relative residual of a training instance outside the kept modes.\n"
    "Then the docking sites of each type, the rules (site a <-> site b as TYPE:SITE),\n"
    "the training examples and the resolved parameters.";
  c.min_positionals = c.max_positionals = 1;
  c.run = run_info;
  return c;
}

} // namespace mpm
