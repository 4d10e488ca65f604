// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Editing.h>
#include <CGAL/MPM/Input_error.h>

#include <Eigen/SVD>

#include <functional>
#include <set>

namespace CGAL {
namespace MPM {

namespace {

// What a cluster is attracted to, given its space, its instance's learned
// coordinates, and its rest geometry expressed in the space's frame.
struct Target
{
  Point_matrix mean;
  Eigen::VectorXd sigmas;
};
using Target_policy = std::function<Target(const Shape_space& space, const Eigen::VectorXd& coordinates,
                                           const Point_matrix& rest_in_space_frame, const std::string& type_name)>;

Point_matrix gather(const Point_matrix& points, const std::vector<int>& vertices)
{
  Point_matrix p(vertices.size(), 3);
  for(std::size_t i = 0; i < vertices.size(); ++i) p.row(i) = points.row(vertices[i]);
  return p;
}

Point_matrix to_space_frame(const Rigid_motion& motion, const Point_matrix& points)
{
  Rigid_motion inverse;
  inverse.rotation = motion.rotation.transpose();
  inverse.translation = -(inverse.rotation * motion.translation);
  return inverse.apply(points);
}

Point_matrix mode_displacement(const Shape_space& space, const Eigen::VectorXd& coordinates)
{
  return space.shape(coordinates) - space.mean;
}

// The pair geometry of two parts' targets. The second part is placed on the
// first by their shared seam (boundary docking); a seam too thin to fix a
// rotation (collinear, as a straight tile side) only fixes the translation
// and the second part keeps its rest orientation. Without a seam (generalized
// docking) both keep their rest placement. The result is expressed in the
// pair space's frame.
Point_matrix pair_target(const Docking_rule& rule, const Point_matrix& first, Point_matrix second,
                         const Point_matrix& second_rest, const Rigid_motion& pair_motion, const Point_matrix& rest)
{
  if(!rule.seam.empty())
  {
    Point_matrix from(rule.seam.size(), 3), to(rule.seam.size(), 3);
    for(std::size_t k = 0; k < rule.seam.size(); ++k)
    {
      from.row(k) = second.row(rule.seam[k].second);
      to.row(k) = first.row(rule.seam[k].first);
    }
    const Eigen::Vector3d spread =
      Eigen::JacobiSVD<Point_matrix>(from.rowwise() - from.colwise().mean()).singularValues();
    if(spread[1] > 1e-3 * spread[0])
      second = fit_rigid_motion(from, to).apply(second);
    else
    {
      second = fit_rigid_motion(second, second_rest).apply(second);
      Point_matrix seam(rule.seam.size(), 3);
      for(std::size_t k = 0; k < rule.seam.size(); ++k) seam.row(k) = second.row(rule.seam[k].second);
      second.rowwise() += to.colwise().mean() - seam.colwise().mean();
    }
  }
  Point_matrix target(rule.points.size(), 3);
  for(std::size_t k = 0; k < rule.points.size(); ++k)
    target.row(k) = (rule.points[k].side == 0 ? first : second).row(rule.points[k].local);
  return to_space_frame(pair_motion, fit_rigid_motion(target, rest).apply(target));
}

Embedding_problem make_problem(const Morphable_part_model& model, int example, const Target_policy& policy,
                               const std::function<Eigen::VectorXd(const Shape_space&)>& pair_sigmas)
{
  if(example < 0 || example >= static_cast<int>(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  const Training_example& ex = model.examples[example];
  const Part_graph& graph = ex.graph;
  Embedding_problem problem;
  problem.mesh = ex.mesh;
  problem.sigma_sub = model.parameters.sigma_sub;

  // Seam vertices of each node: where its part cluster fades out.
  std::vector<std::set<int>> seams(graph.nodes.size());
  for(const Part_edge& e : graph.edges)
  {
    const Docking_rule& rule = model.rules[e.rule];
    for(const auto& [l0, l1] : rule.seam)
    {
      seams[e.first].insert(l0);
      seams[e.second].insert(l1);
    }
  }

  // Each part's target shape, placed where the part rests: pair targets are
  // assembled from them, so that parts and pairs ask for the same shape.
  std::vector<Point_matrix> placed_targets;
  for(std::size_t i = 0; i < graph.nodes.size(); ++i)
  {
    const Part_node& node = graph.nodes[i];
    const Part_type& type = model.types[node.type];
    Cluster c;
    c.name = "part " + std::to_string(i) + " (" + type.name + ", label " + std::to_string(node.label) + ")";
    c.vertices = node.vertices;
    c.triangles = type.triangles;
    c.edges = type.edges;
    const Target t = policy(type.space, node.coordinates, to_space_frame(node.motion, gather(ex.mesh.points, node.vertices)),
                            type.name);
    c.mean = t.mean;
    c.modes = type.space.modes;
    c.sigmas = t.sigmas;
    c.border.assign(seams[i].begin(), seams[i].end());
    c.sigma_bound = model.parameters.sigma_bound;
    placed_targets.push_back(node.motion.apply(t.mean));
    problem.clusters.push_back(std::move(c));
  }

  for(std::size_t i = 0; i < graph.edges.size(); ++i)
  {
    const Part_edge& e = graph.edges[i];
    const Docking_rule& rule = model.rules[e.rule];
    const Part_node* side[2] = {&graph.nodes[e.first], &graph.nodes[e.second]};
    const Part_type* type[2] = {&model.types[rule.first.type], &model.types[rule.second.type]};
    Cluster c;
    c.name = "docking " + std::to_string(i) + " (rule " + std::to_string(e.rule) + ", " + type[0]->name + " - " +
             type[1]->name + ")";
    std::map<std::pair<int, int>, int> index;
    for(std::size_t k = 0; k < rule.points.size(); ++k)
    {
      const Pair_point& q = rule.points[k];
      c.vertices.push_back(side[q.side]->vertices[q.local]);
      index[{q.side, q.local}] = static_cast<int>(k);
    }
    // A seam vertex of the second part is the first part's point.
    for(const auto& [l0, l1] : rule.seam)
    {
      const auto it = index.find({0, l0});
      if(it != index.end()) index[{1, l1}] = it->second;
    }
    for(int s = 0; s < 2; ++s)
    {
      for(const Triangle& t : type[s]->triangles)
      {
        Triangle mapped;
        bool inside = true;
        for(int k = 0; k < 3 && inside; ++k)
        {
          const auto it = index.find({s, t[k]});
          inside = it != index.end();
          if(inside) mapped[k] = it->second;
        }
        if(inside) c.triangles.push_back(mapped);
      }
      // The pair cluster fades out where its region ends inside a part.
      for(const Cluster_edge& edge : type[s]->edges)
      {
        const bool a = index.count({s, edge.source}) > 0, b = index.count({s, edge.target}) > 0;
        if(a != b) c.border.push_back(index.at({s, a ? edge.source : edge.target}));
      }
    }
    std::sort(c.border.begin(), c.border.end());
    c.border.erase(std::unique(c.border.begin(), c.border.end()), c.border.end());
    c.edges = rule.edges;
    c.mean = pair_target(rule, placed_targets[e.first], placed_targets[e.second],
                         gather(ex.mesh.points, side[1]->vertices), e.motion, gather(ex.mesh.points, c.vertices));
    c.modes = rule.space.modes;
    c.sigmas = pair_sigmas(rule.space);
    c.sigma_bound = model.parameters.sigma_bound;
    problem.clusters.push_back(std::move(c));
  }

  // Neighbouring instances of one type: docked to each other or to a common part.
  std::vector<std::set<int>> neighbours(graph.nodes.size());
  for(const Part_edge& e : graph.edges)
  {
    neighbours[e.first].insert(e.second);
    neighbours[e.second].insert(e.first);
  }
  std::set<std::pair<int, int>> coupled;
  for(std::size_t a = 0; a < graph.nodes.size(); ++a)
    for(int b : neighbours[a])
    {
      std::set<int> near = neighbours[b];
      near.insert(b);
      for(int c : near)
        if(c != int(a) && graph.nodes[c].type == graph.nodes[a].type &&
           model.types[graph.nodes[a].type].space.number_of_modes() > 0)
          coupled.insert({std::min<int>(a, c), std::max<int>(a, c)});
    }
  problem.coupled_clusters.assign(coupled.begin(), coupled.end());
  return problem;
}

} // namespace

Embedding_problem make_deformation_problem(const Morphable_part_model& model, int example)
{
  return make_caricature_problem(model, 1., example);
}

namespace {

Eigen::VectorXd learned_sigmas(const Shape_space& space) { return space.sigmas; }

// Small isotropic deviations relative to the space's largest one.
Eigen::VectorXd isotropic_sigmas(const Shape_space& space, double relative)
{
  const double largest = space.sigmas.size() > 0 ? space.sigmas.maxCoeff() : 0.;
  return Eigen::VectorXd::Constant(space.sigmas.size(), relative * largest);
}

} // namespace

Embedding_problem make_caricature_problem(const Morphable_part_model& model, double factor, int example)
{
  if(!std::isfinite(factor)) throw Input_error("caricature", "factor", "must be finite");
  return make_problem(model, example, [factor](const Shape_space& space, const Eigen::VectorXd& coordinates,
                                               const Point_matrix& rest, const std::string&) {
    Target t;
    t.mean = rest;
    if(factor != 1.) t.mean += (factor - 1.) * mode_displacement(space, coordinates);
    t.sigmas = space.sigmas;
    return t;
  }, learned_sigmas);
}

Embedding_problem make_symmetrization_problem(const Morphable_part_model& model, int example,
                                              const Symmetrization_options& options)
{
  if(!(options.relative_sigma > 0) || !std::isfinite(options.relative_sigma))
    throw Input_error("symmetrization", "relative_sigma", "must be positive");
  for(const auto& [name, coordinates] : options.type_coordinates)
  {
    const int t = model.find_type(name);
    if(t < 0) throw Input_error("symmetrization", "part type \"" + name + "\"", "is not a type of the model");
    if(coordinates.size() != model.types[t].space.number_of_modes() || !coordinates.allFinite())
      throw Input_error("symmetrization", "part type \"" + name + "\"",
                        "needs " + std::to_string(model.types[t].space.number_of_modes()) + " finite coordinates");
  }
  return make_problem(model, example, [&options](const Shape_space& space, const Eigen::VectorXd&,
                                                 const Point_matrix& rest, const std::string& type_name) {
    Target t;
    if(space.number_of_instances() < 2)
      t.mean = rest; // a single instance has nothing to be symmetric with
    else
    {
      const auto it = options.type_coordinates.find(type_name);
      t.mean = it == options.type_coordinates.end() ? space.mean : space.shape(it->second);
    }
    t.sigmas = isotropic_sigmas(space, options.relative_sigma);
    return t;
  }, [&options](const Shape_space& space) { return isotropic_sigmas(space, options.relative_sigma); });
}

} // namespace MPM
} // namespace CGAL
