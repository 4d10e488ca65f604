// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Model/Training_example.h>

#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <stdexcept>
#include <type_traits>

namespace CGAL {
namespace MPM {

// The kernels' halfedge mesh is the example's mesh type, so that an indexed
// mesh becomes an example through the one conversion, to_surface_mesh(),
// with its checks and errors.
static_assert(std::is_same<Example_mesh, internal::Indexed_surface_mesh>::value,
              "Example_mesh and internal::Indexed_surface_mesh must stay one type");

namespace {
const char* const part_property = "f:part";
}

Example_mesh::Property_map<Example_mesh::Face_index, int> Training_example::face_labels() const
{
  const auto found = mesh.property_map<Example_mesh::Face_index, int>(part_property);
  if(!found.second) throw std::logic_error("training example " + name + " has no face property f:part");
  return found.first;
}

Training_example make_training_example(const std::string& name, const Labeled_mesh& surface, Part_graph graph)
{
  Training_example example;
  example.name = name;
  example.mesh = internal::to_surface_mesh(surface.mesh, name, "a training example");
  auto labels = example.mesh.add_property_map<Example_mesh::Face_index, int>(part_property, -1).first;
  for(std::size_t t = 0; t < surface.face_labels.size(); ++t)
    labels[Example_mesh::Face_index(static_cast<Example_mesh::size_type>(t))] = surface.face_labels[t];
  example.graph = std::move(graph);
  return example;
}

Labeled_mesh to_labeled_mesh(const Training_example& example)
{
  return to_labeled_mesh(example.mesh, example.face_labels(), example.name);
}

Point_matrix rest_positions(const Training_example& example)
{
  Point_matrix points(static_cast<Eigen::Index>(example.mesh.number_of_vertices()), 3);
  Eigen::Index row = 0;
  for(Example_mesh::Vertex_index v : example.mesh.vertices()) {
    const Example_mesh::Point& p = example.mesh.point(v);
    points.row(row++) << p.x(), p.y(), p.z();
  }
  return points;
}

void set_rest_positions(Training_example& example, const Point_matrix& positions)
{
  if(positions.rows() != static_cast<Eigen::Index>(example.mesh.number_of_vertices()))
    throw Input_error(example.name, "", "has " + std::to_string(example.mesh.number_of_vertices()) +
                                          " vertices, but " + std::to_string(positions.rows()) +
                                          " positions were given");
  write_positions(positions, example.mesh);
}

} // namespace MPM
} // namespace CGAL
