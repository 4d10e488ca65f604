// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/internal/Part_graph_problem.h>
#include <CGAL/MPM/internal/Shape_exaggeration.h>
#include <CGAL/MPM/internal/Target_unfolding.h>

#include <functional>
#include <set>

namespace CGAL {
namespace MPM {

namespace {

using internal::Part_target;
using Target_policy = std::function<Part_target(const Part_type& type, const Eigen::VectorXd& coordinates,
                                                const Point_matrix& rest_in_space_frame)>;

// The clusters of example `example` over its own mesh (the construction is
// shared with assembly, see internal/Part_graph_problem.h).
Embedding_problem make_problem(const Morphable_part_model& model, int example, const Target_policy& policy,
                               const std::function<Eigen::VectorXd(const Shape_space&)>& pair_sigmas)
{
  if(example < 0 || example >= static_cast<int>(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  const Training_example& ex = model.examples[example];
  // A stitched example (parts corresponded separately) has merged seams.
  const internal::Graph_refinement refined = internal::refine_part_graph(model, ex.graph);
  return internal::make_part_graph_problem(
    model, ex.graph, to_labeled_mesh(ex).mesh,
    [&](int node, const Shape_space&, const Eigen::VectorXd& coordinates, const Point_matrix& rest,
        const std::string&) { return policy(model.types[ex.graph.nodes[node].type], coordinates, rest); },
    pair_sigmas, refined.empty() ? nullptr : &refined.nodes, true);
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

// The paper's caricature: the part's coordinates scaled (`by_rotations`
// false), or the same deviation scaled as local rotations and stretches
// (see exaggeration_offsets()). What the subspace does not explain stays.
Point_matrix exaggerated_target(const Part_type& type, const Eigen::VectorXd& coordinates, const Point_matrix& rest,
                                double factor, bool by_rotations)
{
  const Shape_space& space = type.space;
  if(by_rotations)
    return rest + internal::exaggeration_offsets(space.mean, space.shape(coordinates), type.triangles, factor);
  return rest + (factor - 1.) * (space.shape(coordinates) - space.mean);
}

// Whether scaling the coordinates of some part of example `example` by
// `factor` would turn a face of it inside out, its rest (in its space's
// frame) against its target.
bool scaled_coordinates_fold(const Morphable_part_model& model, int example, double factor)
{
  // A missing example is make_problem()'s to report.
  if(factor == 1. || example < 0 || example >= static_cast<int>(model.examples.size())) return false;
  const Point_matrix rest = rest_positions(model.examples[example]);
  for(const Part_node& node : model.examples[example].graph.nodes)
  {
    const Part_type& type = model.types[node.type];
    const std::vector<int> own(node.vertices.begin(), node.vertices.begin() + type.number_of_vertices);
    Indexed_mesh before, after;
    before.triangles = after.triangles = type.triangles;
    before.points = internal::to_space_frame(node.motion, internal::gather_rows(rest, own));
    after.points = exaggerated_target(type, node.coordinates, before.points, factor, false);
    if(!inverted_faces(after, before).empty()) return true;
  }
  return false;
}

} // namespace

Embedding_problem make_caricature_problem(const Morphable_part_model& model, double factor, int example)
{
  if(!std::isfinite(factor)) throw Input_error("caricature", "factor", "must be finite");
  // Scaled coordinates are exact for proportions but fold a part whose
  // deviation is a bend (the inside of a knuckle turns over). When they
  // would turn a face of some part inside out, every part is exaggerated by
  // its local rotations instead: one rule for all, so that neighbouring
  // parts agree at their seams (mixing the two left more folds).
  const bool by_rotations = scaled_coordinates_fold(model, example, factor);
  return make_problem(model, example, [factor, by_rotations](const Part_type& type, const Eigen::VectorXd& coordinates,
                                                             const Point_matrix& rest) {
    Part_target t;
    t.mean = exaggerated_target(type, coordinates, rest, factor, by_rotations);
    // Factor 1 (deformation) asks for the rest itself: nothing to unfold.
    if(factor != 1.) t.mean = internal::unfold_target(t.mean, rest, type.triangles);
    t.sigmas = type.space.sigmas;
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
  return make_problem(model, example, [&options](const Part_type& type, const Eigen::VectorXd&,
                                                 const Point_matrix& rest) {
    const Shape_space& space = type.space;
    Part_target t;
    if(space.number_of_instances() < 2)
      t.mean = rest; // a single instance has nothing to be symmetric with
    else
    {
      const auto it = options.type_coordinates.find(type.name);
      t.mean = internal::unfold_target(it == options.type_coordinates.end() ? space.mean : space.shape(it->second),
                                       rest, type.triangles);
    }
    t.sigmas = isotropic_sigmas(space, options.relative_sigma);
    return t;
  }, [&options](const Shape_space& space) { return isotropic_sigmas(space, options.relative_sigma); });
}

Point_matrix unfold_faces(const Indexed_mesh& rest, const Point_matrix& positions, const std::vector<int>& held)
{
  if(positions.rows() != rest.points.rows() || positions.cols() != 3)
    throw Input_error("unfold_faces", "positions",
                      "are " + std::to_string(positions.rows()) + " x " + std::to_string(positions.cols()) +
                        " for a mesh of " + std::to_string(rest.points.rows()) + " vertices");
  for(int v : held)
    if(v < 0 || v >= rest.number_of_vertices())
      throw Input_error("unfold_faces", "held vertex " + std::to_string(v),
                        "is out of range (the mesh has " + std::to_string(rest.number_of_vertices()) + " vertices)");
  return internal::unfold_target(positions, rest.points, rest.triangles, held);
}

} // namespace MPM
} // namespace CGAL
