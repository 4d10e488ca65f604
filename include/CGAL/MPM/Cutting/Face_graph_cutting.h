// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_FACE_GRAPH_CUTTING_H
#define CGAL_MPM_FACE_GRAPH_CUTTING_H

#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Cutting/Joint_proposal.h>
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/Input_error.h>

#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace MPM {

namespace internal {

// The index in `vertices(g)` of each click, given the `vertex_order()` of
// `g`; a click that is not a vertex of `g` is an `Input_error`.
template <class VertexIndex, class VertexRange>
std::vector<int> click_indices(const VertexIndex& index, const VertexRange& clicks)
{
  std::vector<int> at;
  for(auto v : clicks) {
    const auto i = index.find(v);
    if(i == index.end())
      throw Input_error("face graph", "click " + std::to_string(at.size()), "is not a vertex of the mesh");
    at.push_back(i->second);
  }
  return at;
}

template <class Vertex>
std::vector<Vertex> named(const std::vector<int>& indices, const std::vector<Vertex>& vertex)
{
  std::vector<Vertex> r;
  r.reserve(indices.size());
  for(int i : indices) r.push_back(vertex[std::size_t(i)]);
  return r;
}

// The cuts and skipped clicks of the indexed mesh, their vertices named by
// the face graph's descriptors.
template <class Vertex>
Joint_cuts<Vertex> named(const Joint_cuts<int>& found, const std::vector<Vertex>& vertex)
{
  Joint_cuts<Vertex> r;
  for(const Joint_cut& c : found.cuts)
    r.cuts.push_back({vertex[std::size_t(c.vertex)], named(c.path, vertex), c.length, c.limb_radius, c.shift,
                      c.centre, c.axis});
  for(const Skipped_click& k : found.skipped) r.skipped.push_back({vertex[std::size_t(k.vertex)], k.reason});
  return r;
}

} // namespace internal

/// \ingroup PkgMPMRef
/// Cuts the triangle mesh `g` along the cutting lines of `cuts` (vertex
/// indices in the order of `vertices(g)`, see `vertex_order()`) and writes
/// the label of each face into `face_labels`, as `cut_mesh()` labels the
/// regions. Returns the cuts' paths, as vertex descriptors of `g`, and
/// lengths as `cut_mesh()` does.
///
/// \tparam FaceGraph a model of `FaceListGraph`
/// \tparam FaceLabelMap a `WritablePropertyMap` from the face descriptor to `int`
/// Named parameters: `vertex_point_map`.
template <class FaceGraph, class FaceLabelMap, class NamedParameters = parameters::Default_named_parameters>
Cut_paths<typename boost::graph_traits<FaceGraph>::vertex_descriptor>
cut_mesh(const FaceGraph& g, const Cut_specification& cuts, FaceLabelMap face_labels,
         const Cutting_options& options = Cutting_options(), const NamedParameters& np = parameters::default_values())
{
  const Cutting_result cut = cut_mesh(to_indexed_mesh(g, np), cuts, options, "face graph");
  write_face_labels(cut.mesh.face_labels, g, face_labels);
  const auto vertex = internal::vertex_list(g);
  Cut_paths<typename boost::graph_traits<FaceGraph>::vertex_descriptor> r;
  for(const std::vector<int>& path : cut.paths) r.paths.push_back(internal::named(path, vertex));
  r.lengths = cut.lengths;
  r.regions = cut.regions;
  return r;
}

/// \ingroup PkgMPMRef
/// One click per joint on the user's mesh: cuts the closed triangle mesh `g`
/// around the limb through or next to each vertex of `clicks`, as
/// `cut_at_vertices()` does, and writes the label of each face into
/// `face_labels` (0 for the region of the first face, as `cut_mesh()`
/// numbers regions). Returns the cuts and the clicks left out, their
/// vertices as descriptors of `g`.
///
/// \tparam FaceGraph a model of `FaceListGraph`
/// \tparam VertexRange a range of vertex descriptors of `g`
/// \tparam FaceLabelMap a `WritablePropertyMap` from the face descriptor to `int`
/// Named parameters: `vertex_point_map`.
///
/// Throws `Input_error` as `cut_at_vertices()` does, naming the vertex by
/// its index in `vertices(g)`.
template <class FaceGraph, class VertexRange, class FaceLabelMap,
          class NamedParameters = parameters::Default_named_parameters>
Joint_cuts<typename boost::graph_traits<FaceGraph>::vertex_descriptor>
cut_at_vertices(const FaceGraph& g, const VertexRange& clicks, FaceLabelMap face_labels,
                const Joint_cutting_options& options = Joint_cutting_options(),
                const NamedParameters& np = parameters::default_values())
{
  const Joint_cutting_result cut =
    cut_at_vertices(to_indexed_mesh(g, np), internal::click_indices(vertex_order(g), clicks), options, "face graph");
  write_face_labels(cut.mesh.face_labels, g, face_labels);
  return internal::named(cut, internal::vertex_list(g));
}

/// \ingroup PkgMPMRef
/// `Joint_cutter` on the user's mesh: `cut_at_vertices()` over the face
/// graph `g`, click after click, with the curve skeleton and the crease
/// weights computed once, when the cutter is made (an interactive tool
/// re-cuts at each new click without them). The cutter keeps its own copy
/// of the points and triangles; `g` must outlive it, and its vertices and
/// faces must not change meanwhile (the cuts are found on the mesh as it
/// was given).
///
/// \tparam FaceGraph a model of `FaceListGraph`
template <class FaceGraph>
class Face_graph_joint_cutter
{
public:
  /// Named parameters: `vertex_point_map`. Throws `Input_error` as
  /// `Joint_cutter`'s constructor does.
  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Face_graph_joint_cutter(const FaceGraph& g, const Joint_cutting_options& options = Joint_cutting_options(),
                                   const NamedParameters& np = parameters::default_values())
    : g_(g), index_(vertex_order(g)), vertex_(internal::vertex_list(g)), mesh_(to_indexed_mesh(g, np)),
      cutter_(mesh_, options, "face graph")
  {
  }
  // The cutter refers to the copy of the mesh it holds.
  Face_graph_joint_cutter(const Face_graph_joint_cutter&) = delete;
  Face_graph_joint_cutter& operator=(const Face_graph_joint_cutter&) = delete;

  /// The cuts at `clicks` (vertex descriptors of `g`), as `cut_at_vertices()`
  /// over a face graph gives them; writes the label of each face into
  /// `face_labels` (a `WritablePropertyMap` from the face descriptor to `int`).
  template <class VertexRange, class FaceLabelMap>
  Joint_cuts<typename boost::graph_traits<FaceGraph>::vertex_descriptor> cut(const VertexRange& clicks,
                                                                            FaceLabelMap face_labels) const
  {
    const Joint_cutting_result cut = cutter_.cut(internal::click_indices(index_, clicks));
    write_face_labels(cut.mesh.face_labels, g_, face_labels);
    return internal::named(cut, vertex_);
  }

private:
  const FaceGraph& g_;
  std::unordered_map<typename boost::graph_traits<FaceGraph>::vertex_descriptor, int> index_;
  std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor> vertex_;
  Indexed_mesh mesh_;
  Joint_cutter cutter_;
};

/// \ingroup PkgMPMRef
/// Joints proposed automatically on the user's mesh: cuts the closed
/// triangle mesh `g` into a body and limb segments as
/// `cut_at_proposed_joints()` does, with no click, and writes the label of
/// each face into `face_labels`. The proposal's vertices are descriptors
/// of `g`. The labels are ready for
/// `propose_part_types()` and `learn_morphable_part_model()` over the same
/// face graph: a raw mesh becomes a model with no file written by hand.
///
/// \tparam FaceGraph a model of `FaceListGraph`
/// \tparam FaceLabelMap a `WritablePropertyMap` from the face descriptor to `int`
/// Named parameters: `vertex_point_map`.
///
/// Throws `Input_error` as `cut_at_proposed_joints()` does.
template <class FaceGraph, class FaceLabelMap, class NamedParameters = parameters::Default_named_parameters>
Basic_joint_proposal<typename boost::graph_traits<FaceGraph>::vertex_descriptor,
                     Joint_cuts<typename boost::graph_traits<FaceGraph>::vertex_descriptor>>
cut_at_proposed_joints(const FaceGraph& g, FaceLabelMap face_labels,
                       const Joint_proposal_options& options = Joint_proposal_options(),
                       const NamedParameters& np = parameters::default_values())
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  const Joint_proposal proposal = cut_at_proposed_joints(to_indexed_mesh(g, np), options, "face graph");
  write_face_labels(proposal.cutting.mesh.face_labels, g, face_labels);
  const std::vector<vertex_descriptor> vertex = internal::vertex_list(g);
  Basic_joint_proposal<vertex_descriptor, Joint_cuts<vertex_descriptor>> r;
  for(const Proposed_joint& j : proposal.joints)
    r.joints.push_back({vertex[std::size_t(j.vertex)], j.limb, j.at_base, j.strength, j.by_analogy});
  r.limbs = proposal.limbs;
  r.cutting = internal::named(proposal.cutting, vertex);
  return r;
}

} // namespace MPM
} // namespace CGAL

#endif
