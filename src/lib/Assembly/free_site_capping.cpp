// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Assembly/Free_site_capping.h>

#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <iterator>
#include <vector>

namespace CGAL {
namespace MPM {

namespace PMP = CGAL::Polygon_mesh_processing;
using internal::Indexed_surface_mesh;

int cap_free_sites(const Morphable_part_model& model, Assembly& a)
{
  const int n = a.mesh.number_of_vertices();
  std::vector<int> free_site_node(std::size_t(n), -1);
  for(int node = 0; node < int(a.graph.nodes.size()); ++node)
  {
    const Part_type& type = model.types[std::size_t(a.graph.nodes[std::size_t(node)].type)];
    for(int s : free_sites(model, a.graph, node))
      if(type.sites[std::size_t(s)].kind == Docking_kind::boundary)
        for(int local : type.sites[std::size_t(s)].vertices) free_site_node[std::size_t(a.vertex(node, local))] = node;
  }
  if(std::all_of(free_site_node.begin(), free_site_node.end(), [](int node) { return node < 0; })) return 0;
  Indexed_surface_mesh surface = internal::to_surface_mesh(a.mesh, "assembly", "capping free sites");
  std::vector<Indexed_surface_mesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(surface, std::back_inserter(borders));
  int capped = 0;
  for(const auto h : borders)
  {
    int node = -1;
    bool free_loop = true;
    for(const auto b : CGAL::halfedges_around_face(h, surface))
    {
      node = free_site_node[std::size_t(surface.target(b))];
      free_loop = free_loop && node >= 0;
    }
    if(!free_loop) continue;
    std::vector<Indexed_surface_mesh::Face_index> faces;
    PMP::triangulate_refine_and_fair_hole(surface, h, std::back_inserter(faces), CGAL::Emptyset_iterator());
    const int type = a.graph.nodes[std::size_t(node)].type;
    a.face_nodes.resize(surface.number_of_faces(), -1);
    a.face_types.resize(surface.number_of_faces(), -1);
    for(const auto f : faces)
    {
      a.face_nodes[std::size_t(f)] = node;
      a.face_types[std::size_t(f)] = type;
    }
    ++capped;
  }
  // Vertices and faces were only added, so the first keep their indices.
  if(capped > 0) a.mesh = to_indexed_mesh(surface);
  return capped;
}

} // namespace MPM
} // namespace CGAL
