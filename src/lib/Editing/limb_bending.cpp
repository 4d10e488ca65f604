// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Editing/Limb_bending.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <boost/graph/breadth_first_search.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <string>

namespace CGAL {
namespace MPM {

namespace {

Eigen::RowVector3d centre_of(const Point_matrix& p, const std::vector<int>& vertices)
{
  Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
  for(int v : vertices) c += p.row(v);
  return c / double(vertices.size());
}

// Per node, its neighbour toward `root` (the root's is itself; -1 where
// no docking leads to the root).
std::vector<int> steps_toward(int root, const Part_adjacency_graph& g)
{
  std::vector<int> toward(boost::num_vertices(g), -1);
  toward[std::size_t(root)] = root;
  boost::breadth_first_search(
    g, boost::vertex(root, g),
    boost::visitor(boost::make_bfs_visitor(boost::record_predecessors(toward.data(), boost::on_tree_edge()))));
  return toward;
}

// Per neighbour of the root, the vertices it shares with it: their seam in
// a stitched example.
std::map<int, std::vector<int>> seams_of_root(const Training_example& ex, int root)
{
  std::vector<int> own = ex.graph.nodes[std::size_t(root)].vertices;
  std::sort(own.begin(), own.end());
  std::map<int, std::vector<int>> seams;
  for(std::size_t i = 0; i < ex.graph.nodes.size(); ++i)
  {
    if(int(i) == root) continue;
    std::vector<int> other = ex.graph.nodes[i].vertices, common;
    std::sort(other.begin(), other.end());
    std::set_intersection(own.begin(), own.end(), other.begin(), other.end(), std::back_inserter(common));
    if(!common.empty()) seams[int(i)] = std::move(common);
  }
  return seams;
}

// The root's vertices away from its seams: farther along its edges from
// every seam than the seams' mean radius. Held up to a seam, the root would
// hold the first ring of the limb too, and the limb could not turn there.
std::vector<int> root_away_from_seams(const Training_example& ex, const Labeled_mesh& rest, int root,
                                      const std::map<int, std::vector<int>>& seams)
{
  const Point_matrix& p = rest.mesh.points;
  std::vector<int> all;
  double radius = 0.;
  for(const auto& [node, seam] : seams)
  {
    const Eigen::RowVector3d c = centre_of(p, seam);
    for(int x : seam) radius += (p.row(x) - c).norm() / double(seam.size());
    all.insert(all.end(), seam.begin(), seam.end());
  }
  std::vector<double> from_seams(std::size_t(p.rows()), std::numeric_limits<double>::infinity());
  if(!seams.empty())
  {
    std::vector<Triangle> root_triangles;
    for(std::size_t f = 0; f < rest.mesh.triangles.size(); ++f)
      if(rest.face_labels[f] == ex.graph.nodes[std::size_t(root)].label) root_triangles.push_back(rest.mesh.triangles[f]);
    from_seams = internal::edge_graph_distances(p, internal::mesh_edges(root_triangles), all);
  }
  const double margin = seams.empty() ? 0. : radius / double(seams.size());
  std::vector<int> held;
  for(int x : ex.graph.nodes[std::size_t(root)].vertices)
    if(from_seams[std::size_t(x)] > margin) held.push_back(x);
  return held;
}

} // namespace

Handle_set limb_bending_handles(const Morphable_part_model& model, int example, double relative_move)
{
  if(example < 0 || example >= static_cast<int>(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  if(!(relative_move > 0.) || !std::isfinite(relative_move))
    throw Input_error("limb bending", "move " + std::to_string(relative_move), "is not a positive fraction of the diagonal");
  const Training_example& ex = model.examples[std::size_t(example)];
  const Part_adjacency_graph g = adjacency_graph(ex.graph);
  int root = 0;
  for(std::size_t i = 0; i < ex.graph.nodes.size(); ++i)
    if(ex.graph.nodes[i].vertices.size() > ex.graph.nodes[std::size_t(root)].vertices.size()) root = int(i);
  const std::vector<int> toward_root = steps_toward(root, g);
  const std::map<int, std::vector<int>> seams = seams_of_root(ex, root);
  const Labeled_mesh rest = to_labeled_mesh(ex);
  const Point_matrix& p = rest.mesh.points;
  const double move = relative_move * internal::bounding_box_diagonal(p);
  std::vector<int> vertices;
  std::vector<Eigen::RowVector3d> targets;
  for(std::size_t i = 0; i < ex.graph.nodes.size(); ++i)
  {
    if(boost::out_degree(i, g) != 1 || int(i) == root || toward_root[i] < 0) continue;
    int first = int(i);
    while(toward_root[std::size_t(first)] != root) first = toward_root[std::size_t(first)];
    const auto seam = seams.find(first);
    const Eigen::RowVector3d pivot =
      centre_of(p, seam == seams.end() ? ex.graph.nodes[std::size_t(root)].vertices : seam->second);
    int tip = ex.graph.nodes[i].vertices.front();
    for(int x : ex.graph.nodes[i].vertices)
      if((p.row(x) - pivot).norm() > (p.row(tip) - pivot).norm()) tip = x;
    const Eigen::Vector3d arm = (p.row(tip) - pivot).transpose();
    if(!(arm.norm() > 0.)) continue;
    Eigen::Vector3d side = arm.normalized().cross(Eigen::Vector3d::UnitZ());
    if(side.norm() < 0.1) side = arm.normalized().cross(Eigen::Vector3d::UnitX());
    const double angle = 2. * std::asin(std::min(1., 0.5 * move / arm.norm()));
    vertices.push_back(tip);
    targets.push_back(pivot + (Eigen::AngleAxisd(angle, arm.cross(side).normalized()) * arm).transpose());
  }
  for(int x : root_away_from_seams(ex, rest, root, seams))
    if(std::find(vertices.begin(), vertices.end(), x) == vertices.end())
    {
      vertices.push_back(x);
      targets.push_back(p.row(x));
    }
  Handle_set handles;
  handles.vertices = vertices;
  handles.targets.resize(Eigen::Index(targets.size()), 3);
  for(std::size_t k = 0; k < targets.size(); ++k) handles.targets.row(Eigen::Index(k)) = targets[k];
  return handles;
}

} // namespace MPM
} // namespace CGAL
