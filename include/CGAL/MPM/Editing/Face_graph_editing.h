// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_FACE_GRAPH_EDITING_H
#define CGAL_MPM_FACE_GRAPH_EDITING_H

#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/internal/Edit_solving.h>
#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/Named_parameters.h>

#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace MPM {

namespace internal {

// Whether each vertex of `mesh` has faces of more than one part.
inline std::vector<bool> seam_vertices(const Indexed_mesh& mesh, const std::vector<int>& face_parts)
{
  std::vector<int> part(std::size_t(mesh.number_of_vertices()), -1);
  std::vector<bool> seam(part.size(), false);
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for(int v : mesh.triangles[t]) {
      int& p = part[std::size_t(v)];
      if(p >= 0 && p != face_parts[t]) seam[std::size_t(v)] = true;
      p = face_parts[t];
    }
  return seam;
}

// Fills the optional maps of `np` on a mesh `copy_to_face_graph()` made
// (`added`: its faces in triangle order): the part type of triangle `t` is
// `type_of(t)`, the seam vertices are `seams()` (one flag per vertex, in
// the order of `vertices(g)`), computed only when asked for.
template <class FaceGraph, class TypeOf, class Seams, class NamedParameters>
void write_type_and_seam_maps(const FaceGraph& g,
                              const std::vector<typename boost::graph_traits<FaceGraph>::face_descriptor>& added,
                              const TypeOf& type_of, const Seams& seams, const NamedParameters& np)
{
  using parameters::get_parameter;
  using Not_given = CGAL::internal_np::Param_not_found;
  const auto type_map = get_parameter(np, internal_np::face_part_type);
  if constexpr(!std::is_same_v<std::decay_t<decltype(type_map)>, Not_given>)
    for(std::size_t t = 0; t < added.size(); ++t) put(type_map, added[t], type_of(t));
  const auto seam_map = get_parameter(np, internal_np::vertex_is_seam);
  if constexpr(!std::is_same_v<std::decay_t<decltype(seam_map)>, Not_given>) {
    const std::vector<bool> seam = seams();
    std::size_t i = 0;
    for(auto v : vertices(g)) put(seam_map, v, seam[i++]);
  }
}

// Fills the part maps of a mesh `copy_to_face_graph()` made from `mesh`:
// `face_parts` always, the part type (`type_of(t)` for triangle `t`) and
// seam maps when `np` has them.
template <class FaceGraph, class FacePartMap, class TypeOf, class NamedParameters>
void write_part_maps(const Indexed_mesh& mesh, const FaceGraph& g,
                     const std::vector<typename boost::graph_traits<FaceGraph>::face_descriptor>& added,
                     const std::vector<int>& face_parts, const TypeOf& type_of, FacePartMap parts,
                     const NamedParameters& np)
{
  for(std::size_t t = 0; t < added.size(); ++t) put(parts, added[t], face_parts[t]);
  write_type_and_seam_maps(g, added, type_of, [&] { return seam_vertices(mesh, face_parts); }, np);
}

} // namespace internal

/// \ingroup PkgMPMRef
/// Fills the empty `g` with training example `example` of `model` as
/// learned (a part rebuilt by correspondence has its type's triangles) and
/// writes each face's part label into `face_labels`. The editing functions
/// below edit this mesh.
///
/// \tparam MutableFaceGraph a model of `MutableFaceGraph`
/// \tparam FaceLabelMap a `WritablePropertyMap` from the face descriptor to `int`
/// Named parameters: `vertex_point_map`, and the package's
/// `face_part_type_map` (each face's part type) and `vertex_is_seam_map`
/// (whether a vertex lies between two parts), see `Named_parameters.h`.
template <class MutableFaceGraph, class FaceLabelMap, class NamedParameters = parameters::Default_named_parameters>
void copy_training_example(const Morphable_part_model& model, int example, MutableFaceGraph& g,
                           FaceLabelMap face_labels, const NamedParameters& np = parameters::default_values())
{
  if(example < 0 || example >= static_cast<int>(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  const Training_example& e = model.examples[std::size_t(example)];
  const Labeled_mesh rest = to_labeled_mesh(e);
  std::map<int, int> type_of_label;
  for(const Part_node& node : e.graph.nodes) type_of_label[node.label] = node.type;
  const auto type_of = [&](std::size_t t) {
    const auto it = type_of_label.find(rest.face_labels[t]);
    return it == type_of_label.end() ? -1 : it->second;
  };
  internal::write_part_maps(rest.mesh, g, copy_to_face_graph(rest.mesh, g, np), rest.face_labels, type_of,
                            face_labels, np);
}

/// \ingroup PkgMPMRef
/// Fills the empty `g` with one shape of part type `type` of `model`: its
/// triangles at `mean + sum_k coordinates[k] * modes[k]`
/// (`Shape_space::shape()`, the mean when `coordinates` is empty), in the
/// frame of the mean. So a learned part can be looked at, written or
/// processed as the user's own mesh type, for instance along a mode at two
/// standard deviations.
///
/// \tparam MutableFaceGraph a model of `MutableFaceGraph`
/// Named parameters: `vertex_point_map`, and the package's
/// `face_part_type_map` (`type` on every face) and `vertex_is_seam_map`
/// (the vertices of the type's boundary docking sites, where the part meets
/// its neighbours).
///
/// Throws `Input_error` naming the type when it does not exist or when
/// `coordinates` is neither empty nor one value per mode.
template <class MutableFaceGraph, class NamedParameters = parameters::Default_named_parameters>
void copy_part_shape(const Morphable_part_model& model, int type, const Eigen::VectorXd& coordinates,
                     MutableFaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  if(type < 0 || type >= static_cast<int>(model.types.size()))
    throw Input_error("model", "part type " + std::to_string(type),
                      "does not exist (the model has " + std::to_string(model.types.size()) + " part types)");
  const Part_type& t = model.types[std::size_t(type)];
  if(coordinates.size() != 0 && coordinates.size() != t.space.number_of_modes())
    throw Input_error("model", "part type " + std::to_string(type) + " (" + t.name + ")",
                      "has " + std::to_string(t.space.number_of_modes()) + " modes, but " +
                        std::to_string(coordinates.size()) + " coordinates were given");
  Indexed_mesh part;
  part.points = t.space.shape(coordinates);
  part.triangles = t.triangles;
  const auto seams = [&] {
    std::vector<bool> seam(std::size_t(t.number_of_vertices), false);
    for(const Docking_site& site : t.sites)
      if(site.kind == Docking_kind::boundary)
        for(int v : site.vertices) seam[std::size_t(v)] = true;
    return seam;
  };
  internal::write_type_and_seam_maps(g, copy_to_face_graph(part, g, np), [type](std::size_t) { return type; }, seams,
                                     np);
}

namespace internal {

// Solves an editing problem of the example `g` holds and writes the result
// into `g`; the handles `h` index the vertices in the order of `vertices(g)`
// (symmetrization and caricature pass none).
template <class FaceGraph, class NamedParameters>
Edit_result edit_face_graph(const Morphable_part_model& model, const Embedding_problem& problem, FaceGraph& g,
                            const Handle_set& h, const Edit_options& options, const NamedParameters& np)
{
  const Solved_edit edit = solve_edit(model, problem, h, options);
  write_positions(edit.mesh.points, g, np);
  return edit.result;
}

// The same with handles given as (vertex descriptor, target point) pairs,
// as `deform()` takes them.
template <class FaceGraph, class HandleRange, class NamedParameters>
Edit_result edit_face_graph(const Morphable_part_model& model, const Embedding_problem& problem, FaceGraph& g,
                            const HandleRange& handles, const Edit_options& options, const NamedParameters& np)
{
  const auto index = vertex_order(g);
  Handle_set h;
  h.targets.resize(static_cast<Eigen::Index>(std::size(handles)), 3);
  for(const auto& [vertex, target] : handles) {
    const auto it = index.find(vertex);
    if(it == index.end())
      throw Input_error(options.handles_source, "handle " + std::to_string(h.vertices.size()),
                        "its vertex is not a vertex of the face graph");
    h.targets.row(Eigen::Index(h.vertices.size())) << CGAL::to_double(target.x()), CGAL::to_double(target.y()),
      CGAL::to_double(target.z());
    h.vertices.push_back(it->second);
  }
  return edit_face_graph(model, problem, g, h, options, np);
}

} // namespace internal

/// \ingroup PkgMPMRef
/// Free-form deformation (`make_deformation_problem()`) of training example
/// `options.example`, held in `g` (see `copy_training_example()`): each
/// handle, a pair of a vertex descriptor of `g` and its target point, pulls
/// its vertex; the result is written into `g` through its vertex point map.
///
/// \tparam FaceGraph a model of `FaceListGraph` with as many vertices as the example
/// \tparam HandleRange a range of `std::pair<vertex_descriptor, Point>`, `Point` with `x()`, `y()`, `z()`
/// Named parameters: `vertex_point_map`.
template <class FaceGraph, class HandleRange, class NamedParameters = parameters::Default_named_parameters>
Edit_result deform(const Morphable_part_model& model, FaceGraph& g, const HandleRange& handles,
                   const Edit_options& options = Edit_options(), const NamedParameters& np = parameters::default_values())
{
  return internal::edit_face_graph(model, make_deformation_problem(model, options.example), g, handles, options, np);
}

/// \ingroup PkgMPMRef
/// Partial symmetrization (`make_symmetrization_problem()`) of training
/// example `options.example`, held in `g`; the result is written into `g`.
template <class FaceGraph, class NamedParameters = parameters::Default_named_parameters>
Edit_result symmetrize(const Morphable_part_model& model, FaceGraph& g,
                       const Symmetrization_options& symmetrization = Symmetrization_options(),
                       const Edit_options& options = Edit_options(),
                       const NamedParameters& np = parameters::default_values())
{
  return internal::edit_face_graph(model, make_symmetrization_problem(model, options.example, symmetrization), g,
                                   Handle_set(), options, np);
}

/// \ingroup PkgMPMRef
/// Caricature by `factor` (`make_caricature_problem()`) of training example
/// `options.example`, held in `g`; the result is written into `g`.
template <class FaceGraph, class NamedParameters = parameters::Default_named_parameters>
Edit_result caricature(const Morphable_part_model& model, double factor, FaceGraph& g,
                       const Edit_options& options = Edit_options(),
                       const NamedParameters& np = parameters::default_values())
{
  return internal::edit_face_graph(model, make_caricature_problem(model, factor, options.example), g, Handle_set(),
                                   options, np);
}

/// \ingroup PkgMPMRef
/// Assembles and embeds `graph` (`assemble()`) into the empty `g` and
/// writes the part graph node of each face into `face_nodes` (its part type
/// is `graph.nodes[node].type`). Returns what the assembly did; the mesh is
/// `g` (the indices in `Part_node::vertices` count the vertices of `g` in
/// the order they were added).
///
/// \tparam MutableFaceGraph a model of `MutableFaceGraph`
/// \tparam FaceNodeMap a `WritablePropertyMap` from the face descriptor to `int`
/// Named parameters: `vertex_point_map`, `face_part_type_map` and
/// `vertex_is_seam_map` (the seams between nodes), as for `copy_training_example()`.
template <class MutableFaceGraph, class FaceNodeMap, class NamedParameters = parameters::Default_named_parameters>
Assembly_result assemble(const Morphable_part_model& model, const Part_graph& graph, MutableFaceGraph& g,
                  FaceNodeMap face_nodes, const Assembly_options& options = Assembly_options(),
                  const NamedParameters& np = parameters::default_values())
{
  Assembly a = assemble(model, graph, options);
  internal::write_part_maps(
    a.mesh, g, copy_to_face_graph(a.mesh, g, np), a.face_nodes, [&](std::size_t t) { return a.face_types[t]; },
    face_nodes, np);
  return std::move(static_cast<Assembly_result&>(a));
}

} // namespace MPM
} // namespace CGAL

#endif
