// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `mpm spawn MODEL --count N --seed S [-o DIR]`: random valid part graphs from
// the grammar, embedded and ranked by residual energy per part.
#include "assembly_common.h"

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Part_graph_io.h>

#include <climits>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace mpm {

namespace {

using namespace CGAL::MPM;

int run_spawn(const Args& args, Context& context)
{
  const std::string path = args.positionals().front();
  context.progress.update("loading " + path, 0.);
  const Morphable_part_model model = load_model_with_grammar(path, args.flag("observed-only"));
  const int example = static_cast<int>(args.integer("example", 0));
  if(example >= static_cast<int>(model.examples.size()))
    throw Input_error(path, "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  Spawn_options options;
  options.count = static_cast<int>(args.integer("count", options.count));
  // Every spawned assembly is kept for the ranking: measured about 315 bytes
  // per vertex of the example per graph.
  check_memory("count", std::to_string(options.count),
               400. * options.count * model.examples[example].mesh.number_of_vertices());
  options.seed = static_cast<unsigned>(args.integer("seed", options.seed));
  options.edits.max_edits = static_cast<int>(args.integer("edits", options.edits.max_edits));
  options.edits.min_edits = std::min(options.edits.min_edits, options.edits.max_edits);
  options.assembly.solver.max_iterations =
    static_cast<int>(args.integer("iterations", options.assembly.solver.max_iterations));
  const std::string directory = args.text("output");
  context.progress.update("spawning " + std::to_string(options.count) + " graphs", 0.1);
  options.progress = [&context](int done, int count) {
    context.progress.update("spawning " + std::to_string(count) + " graphs", 0.1 + 0.8 * done / std::max(1, count));
  };
  const std::vector<Spawned_graph> spawned = spawn_part_graphs(model, part_graph_of_example(model, example), options);

  Json ranking = Json::array();
  for(std::size_t rank = 0; rank < spawned.size(); ++rank)
  {
    const Spawned_graph& s = spawned[rank];
    Json entry = {{"rank", rank + 1}, {"index", s.index}, {"parts", s.graph.nodes.size()},
                  {"dockings", s.graph.edges.size()}, {"residual_energy", s.assembly.residual_energy},
                  {"energy_per_part", s.assembly.energy_per_part()}, {"edits", s.edits}};
    if(!directory.empty())
    {
      const std::string stem = (std::filesystem::path(directory) / ("spawn_" + std::to_string(s.index))).string();
      write_assembly_mesh(s.assembly, stem + ".ply", context.meshes);
      write_part_graph(model, s.graph, stem + ".json");
      entry["mesh"] = stem + ".ply";
      entry["graph"] = stem + ".json";
    }
    ranking.push_back(entry);
  }
  context.progress.done();
  const Json summary = {{"command", "spawn"}, {"model", path}, {"example", example}, {"count", options.count},
                        {"seed", options.seed}, {"max_edits", options.edits.max_edits}, {"ranking", ranking}};
  if(context.json)
  {
    print_json(summary);
    return exit_ok;
  }
  std::cout << "Spawned " << spawned.size() << " part graphs from example " << example << " of " << path
            << " (seed " << options.seed << "), ranked by residual energy per part:\n";
  Table table({"rank", "graph", "parts", "energy/part", "edits"}, {true, true, true, true, false});
  for(const Json& e : ranking)
  {
    std::string edits;
    for(const auto& x : e["edits"]) edits += (edits.empty() ? "" : "; ") + x.get<std::string>();
    table.add_row({std::to_string(e["rank"].get<int>()), "spawn_" + std::to_string(e["index"].get<int>()),
                   std::to_string(e["parts"].get<int>()), format_number(e["energy_per_part"].get<double>(), 4), edits});
  }
  table.print(std::cout);
  if(!directory.empty()) std::cout << "Wrote spawn_*.ply and spawn_*.json in " << directory << "\n";
  return exit_ok;
}

} // namespace

Command make_spawn_command()
{
  const Embedding_options defaults;
  Command c;
  c.name = "spawn";
  c.summary = "draw random valid part graphs from the grammar, embed and rank them";
  c.synopsis = "MODEL [--count N] [--seed S] [--edits K] [-o DIR]";
  c.operand = "MODEL";
  c.description =
    "Starts from the graph of training example --example and applies 1 to K random\n"
    "valid edits (insert or remove a segment, remove a branch, duplicate a branch\n"
    "onto a free docking site; a site never carries more dockings than observed),\n"
    "embeds each graph and ranks them by residual energy per part, lowest first.\n"
    "The same seed gives the same graphs and ranking. With -o, writes DIR/spawn_I.ply\n"
    "(colours by part type) and DIR/spawn_I.json (its part graph) for each draw I.\n"
    "Repetition and bridging rules are derived as for 'mpm assemble' unless --observed-only.";
  c.min_positionals = c.max_positionals = 1;
  c.options = {
    {"count", 0, Value_kind::integer, "N", "8", "how many graphs", 1, 100000},
    {"seed", 0, Value_kind::integer, "S", "1", "seed of the random draws", 0, double(UINT_MAX)},
    {"edits", 0, Value_kind::integer, "K", "3", "most random edits per graph", 1, 1000},
    {"example", 0, Value_kind::integer, "N", "0", "training example to start from", 0, INT_MAX},
    {"output", 'o', Value_kind::output_prefix, "DIR", "", "directory for the meshes and graphs"},
    {"observed-only", 0, Value_kind::flag, "", "", "the learned rules only (no derived repetition or bridging rules)"},
    {"iterations", 0, Value_kind::integer, "N", std::to_string(defaults.max_iterations),
     "maximum number of solver iterations", 1, INT_MAX},
  };
  c.run = run_spawn;
  return c;
}

} // namespace mpm
