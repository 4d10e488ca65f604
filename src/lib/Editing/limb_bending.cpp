// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Editing/Limb_bending.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
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
  std::vector<int> queue{root};
  toward[std::size_t(root)] = root;
  for(std::size_t k = 0; k < queue.size(); ++k)
    for(auto [e, end] = boost::out_edges(queue[k], g); e != end; ++e)
    {
      const int next = int(boost::target(*e, g));
      if(toward[std::size_t(next)] >= 0) continue;
      toward[std::size_t(next)] = queue[k];
      queue.push_back(next);
    }
  return toward;
}

// The vertices two parts share (their seam in a stitched example).
std::vector<int> shared_vertices(std::vector<int> a, std::vector<int> b)
{
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::vector<int> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  return common;
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
  const Point_matrix& p = ex.mesh.points;
  const double move = relative_move * internal::bounding_box_diagonal(p);
  const std::vector<int>& root_vertices = ex.graph.nodes[std::size_t(root)].vertices;
  std::vector<int> vertices;
  std::vector<Eigen::RowVector3d> targets;
  for(std::size_t i = 0; i < ex.graph.nodes.size(); ++i)
  {
    if(boost::out_degree(i, g) != 1 || int(i) == root || toward_root[i] < 0) continue;
    int first = int(i);
    while(toward_root[std::size_t(first)] != root) first = toward_root[std::size_t(first)];
    const std::vector<int> seam = shared_vertices(ex.graph.nodes[std::size_t(first)].vertices, root_vertices);
    const Eigen::RowVector3d pivot = centre_of(p, seam.empty() ? root_vertices : seam);
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
  // The root is held away from its seams: held up to a seam, it would
  // hold the first ring of the limb too, and the limb could not turn there.
  std::vector<int> seams;
  double radius = 0.;
  int loops = 0;
  for(std::size_t i = 0; i < ex.graph.nodes.size(); ++i)
  {
    if(int(i) == root) continue;
    const std::vector<int> seam = shared_vertices(ex.graph.nodes[i].vertices, root_vertices);
    if(seam.empty()) continue;
    const Eigen::RowVector3d c = centre_of(p, seam);
    for(int x : seam) radius += (p.row(x) - c).norm() / double(seam.size());
    ++loops;
    seams.insert(seams.end(), seam.begin(), seam.end());
  }
  std::vector<double> from_seams(std::size_t(p.rows()), std::numeric_limits<double>::infinity());
  if(!seams.empty())
  {
    std::vector<Triangle> root_triangles;
    for(std::size_t f = 0; f < ex.mesh.triangles.size(); ++f)
      if(ex.face_labels[f] == ex.graph.nodes[std::size_t(root)].label) root_triangles.push_back(ex.mesh.triangles[f]);
    from_seams = internal::edge_graph_distances(p, internal::mesh_edges(root_triangles), seams);
  }
  const double margin = loops > 0 ? radius / loops : 0.;
  for(int x : root_vertices)
    if(from_seams[std::size_t(x)] > margin && std::find(vertices.begin(), vertices.end(), x) == vertices.end())
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
