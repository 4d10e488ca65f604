// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Input_error.h>

namespace CGAL {
namespace MPM {

void set_example_pose(Morphable_part_model& model, int example, const Indexed_mesh& mesh, const std::string& mesh_name)
{
  if(example < 0 || example >= static_cast<int>(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  Training_example& ex = model.examples[example];
  const Indexed_mesh rest = to_labeled_mesh(ex).mesh;
  if(mesh.number_of_vertices() != rest.number_of_vertices())
    throw Input_error(mesh_name, "", "has " + std::to_string(mesh.number_of_vertices()) +
                                       " vertices; the model's example " + std::to_string(example) + " (" + ex.name +
                                       ") has " + std::to_string(rest.number_of_vertices()));
  if(mesh.number_of_faces() != rest.number_of_faces())
    throw Input_error(mesh_name, "", "has " + std::to_string(mesh.number_of_faces()) +
                                       " faces; the model's example " + std::to_string(example) + " (" + ex.name +
                                       ") has " + std::to_string(rest.number_of_faces()));
  for(int f = 0; f < mesh.number_of_faces(); ++f)
    if(mesh.triangles[f] != rest.triangles[f])
      throw Input_error(mesh_name, "face " + std::to_string(f),
                        "differs from the model's example " + std::to_string(example) + " (" + ex.name +
                          "): not a pose of the same mesh");
  for(int v = 0; v < mesh.number_of_vertices(); ++v)
    if(!mesh.points.row(v).allFinite())
      throw Input_error(mesh_name, "vertex " + std::to_string(v), "non-finite coordinate");

  const auto gather = [&](const std::vector<int>& vertices) {
    Point_matrix p(vertices.size(), 3);
    for(std::size_t i = 0; i < vertices.size(); ++i) p.row(i) = mesh.points.row(vertices[i]);
    return p;
  };
  for(Part_node& node : ex.graph.nodes)
    model.types[node.type].space.fit(gather(node.vertices), node.coordinates, node.motion);
  for(Part_edge& edge : ex.graph.edges)
  {
    const Docking_rule& rule = model.rules[edge.rule];
    std::vector<int> vertices;
    for(const Pair_point& q : rule.points)
      vertices.push_back(ex.graph.nodes[q.side == 0 ? edge.first : edge.second].vertices[q.local]);
    rule.space.fit(gather(vertices), edge.coordinates, edge.motion);
  }
  set_rest_positions(ex, mesh.points);
}

} // namespace MPM
} // namespace CGAL
