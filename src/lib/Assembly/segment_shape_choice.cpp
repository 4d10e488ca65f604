// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Part_graph_problem.h>

#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {

namespace {

// Intersecting face pairs of `graph` placed rigidly; a placement whose faces
// do not form a polygon mesh counts as crossing everything.
int crossings_of_placement(const Morphable_part_model& model, const Part_graph& graph)
{
  Assembly_options options;
  options.solve = false;
  const Assembly placed = assemble(model, graph, options);
  std::vector<std::pair<int, int>> pairs;
  if(!self_intersecting_faces(placed.mesh, pairs)) return static_cast<int>(placed.mesh.triangles.size());
  return static_cast<int>(pairs.size());
}

} // namespace

int choose_segment_shape(const Morphable_part_model& model, Part_graph& graph, int node)
{
  if(node < 0 || node >= static_cast<int>(graph.nodes.size()))
    throw Input_error(internal::part_graph_source, "node " + std::to_string(node),
                      "does not exist (the graph has " + std::to_string(graph.nodes.size()) + " nodes)");
  const Shape_space& space = model.types[graph.nodes[std::size_t(node)].type].space;
  std::vector<Eigen::VectorXd> candidates{graph.nodes[std::size_t(node)].coordinates,
                                          Eigen::VectorXd::Zero(space.number_of_modes())};
  for(Eigen::Index j = 0; j < space.instance_coordinates.cols(); ++j)
    candidates.push_back(space.instance_coordinates.col(j));
  int best = crossings_of_placement(model, graph);
  Eigen::VectorXd chosen = candidates.front();
  for(std::size_t k = 1; k < candidates.size() && best > 0; ++k)
  {
    if(candidates[k].size() != space.number_of_modes() ||
       (chosen.size() == candidates[k].size() && candidates[k] == chosen))
      continue; // Eigen compares vectors of one size only
    Part_graph trial = graph;
    trial.nodes[std::size_t(node)].coordinates = candidates[k];
    const int crossings = crossings_of_placement(model, trial);
    if(crossings < best)
    {
      best = crossings;
      chosen = candidates[k];
    }
  }
  graph.nodes[std::size_t(node)].coordinates = chosen;
  return best;
}

} // namespace MPM
} // namespace CGAL
