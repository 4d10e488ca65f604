// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Assembly/Free_site_capping.h>

#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>
#include <CGAL/MPM/internal/Part_graph_problem.h>
#include <CGAL/MPM/internal/Training_segments.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

namespace PMP = CGAL::Polygon_mesh_processing;
// The hole filling searches a 3D Delaunay triangulation of the loop, which
// needs exact predicates: with inexact ones a loop of nearly coplanar,
// nearly cocircular points (a docking seam) kept it searching for minutes.
using Capped_mesh = internal::Exact_predicates_surface_mesh;

namespace {

// The cap as it was made (its faces over the capped mesh, with the loop it
// closes) is the cluster's target: it keeps its shape, turned with its loop,
// as a part with one instance does.
Cluster cap_cluster(const Indexed_mesh& mesh, const std::vector<int>& faces, const std::string& name)
{
  Cluster c;
  c.name = name;
  std::vector<int> local_of(std::size_t(mesh.number_of_vertices()), -1);
  internal::local_part(mesh, faces, local_of, c.vertices, c.triangles);
  c.edges = internal::mesh_edges(c.triangles);
  c.mean = internal::gather_rows(mesh.points, c.vertices);
  c.modes = Eigen::MatrixXd::Zero(c.mean.rows() * 3, 0);
  c.sigmas = Eigen::VectorXd::Zero(0);
  return c;
}

} // namespace

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
  Capped_mesh surface = internal::to_surface_mesh_of<Capped_mesh::Point>(a.mesh, "assembly", "capping free sites");
  std::vector<Capped_mesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(surface, std::back_inserter(borders));
  std::vector<std::vector<int>> cap_faces;
  std::vector<int> cap_nodes;
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
    std::vector<Capped_mesh::Face_index> faces;
    PMP::triangulate_refine_and_fair_hole(surface, h, std::back_inserter(faces), CGAL::Emptyset_iterator());
    const int type = a.graph.nodes[std::size_t(node)].type;
    a.face_nodes.resize(surface.number_of_faces(), -1);
    a.face_types.resize(surface.number_of_faces(), -1);
    cap_faces.emplace_back();
    cap_nodes.push_back(node);
    for(const auto f : faces)
    {
      a.face_nodes[std::size_t(f)] = node;
      a.face_types[std::size_t(f)] = type;
      cap_faces.back().push_back(int(f));
    }
  }
  if(cap_faces.empty()) return 0;
  // Vertices and faces were only added, so the first keep their indices.
  a.mesh = to_indexed_mesh(surface);
  const Eigen::Index solved = a.problem.mesh.points.rows();
  a.problem.mesh.triangles = a.mesh.triangles;
  a.problem.mesh.points.conservativeResize(a.mesh.points.rows(), 3);
  a.problem.mesh.points.bottomRows(a.mesh.points.rows() - solved) = a.mesh.points.bottomRows(a.mesh.points.rows() - solved);
  for(std::size_t c = 0; c < cap_faces.size(); ++c)
    a.problem.clusters.push_back(cap_cluster(a.mesh, cap_faces[c],
                                             "cap of part " + std::to_string(cap_nodes[c]) + " (" +
                                               model.types[std::size_t(a.graph.nodes[std::size_t(cap_nodes[c])].type)].name + ")"));
  return int(cap_faces.size());
}

} // namespace MPM
} // namespace CGAL
