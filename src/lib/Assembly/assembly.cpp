// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/internal/Elapsed_time.h>
#include <CGAL/MPM/internal/Part_graph_problem.h>

#include <boost/graph/breadth_first_search.hpp>
#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <chrono>
#include <cmath>
#include <map>

namespace CGAL {
namespace MPM {

namespace {

using internal::gather_rows;
using internal::Clock;
using internal::milliseconds_since;

Rigid_motion compose(const Rigid_motion& a, const Rigid_motion& b) // a after b
{
  Rigid_motion r;
  r.rotation = a.rotation * b.rotation;
  r.translation = a.rotation * b.translation + a.translation;
  return r;
}

// The points of a rule's pair geometry that belong to side `side`, as
// (pair point, local vertex of that side's part); seam points count for both.
std::vector<std::pair<int, int>> side_points(const Docking_rule& rule, int side)
{
  std::map<int, int> second_of_first;
  for(const auto& [l0, l1] : rule.seam) second_of_first[l0] = l1;
  std::vector<std::pair<int, int>> r;
  for(std::size_t k = 0; k < rule.points.size(); ++k)
  {
    const Pair_point& q = rule.points[k];
    if(q.side == side) r.push_back({int(k), q.local});
    else if(side == 1 && q.side == 0)
    {
      const auto it = second_of_first.find(q.local);
      if(it != second_of_first.end()) r.push_back({int(k), it->second});
    }
  }
  return r;
}

// Places node `v`'s target (space frame) next to the placed node `u` docked
// by edge `e`: on the seam (Kabsch) for a boundary docking whose seam fixes
// a rotation, else by the relative placement of the rule's pair geometry.
Rigid_motion place_neighbour(const Docking_rule& rule, const Part_edge& e, int u, const Point_matrix& placed_u,
                             const Point_matrix& target_v)
{
  const int side_u = e.first == u ? 0 : 1;
  const std::vector<Seam_vertex>& merged = internal::merged_seam_of(rule, e);
  if(rule.kind == Docking_kind::boundary && !merged.empty())
  {
    // A merged seam: Kabsch on every merged vertex (interpolated where inserted).
    Point_matrix on_first, on_second;
    if(side_u == 0)
    {
      internal::seam_points(rule, merged, placed_u, target_v, on_first, on_second);
      if(!internal::seam_is_collinear(on_first)) return fit_rigid_motion(on_second, on_first);
    }
    else
    {
      internal::seam_points(rule, merged, target_v, placed_u, on_first, on_second);
      if(!internal::seam_is_collinear(on_second)) return fit_rigid_motion(on_first, on_second);
    }
  }
  if(rule.kind == Docking_kind::boundary && !rule.seam.empty() && merged.empty())
  {
    Point_matrix from(rule.seam.size(), 3), to(rule.seam.size(), 3);
    for(std::size_t k = 0; k < rule.seam.size(); ++k)
    {
      const int lu = side_u == 0 ? rule.seam[k].first : rule.seam[k].second;
      const int lv = side_u == 0 ? rule.seam[k].second : rule.seam[k].first;
      from.row(k) = target_v.row(lv);
      to.row(k) = placed_u.row(lu);
    }
    if(!internal::seam_is_collinear(to) && !internal::seam_is_collinear(from)) return fit_rigid_motion(from, to);
  }
  const Eigen::VectorXd c = e.coordinates.size() == rule.space.number_of_modes()
                              ? e.coordinates
                              : Eigen::VectorXd::Zero(rule.space.number_of_modes());
  const Point_matrix pair = rule.space.shape(c);
  const auto pu = side_points(rule, side_u), pv = side_points(rule, 1 - side_u);
  Point_matrix a(pu.size(), 3), b(pu.size(), 3);
  for(std::size_t k = 0; k < pu.size(); ++k)
  {
    a.row(k) = pair.row(pu[k].first);
    b.row(k) = placed_u.row(pu[k].second);
  }
  const Point_matrix carried = fit_rigid_motion(a, b).apply(pair);
  Point_matrix from(pv.size(), 3), to(pv.size(), 3);
  for(std::size_t k = 0; k < pv.size(); ++k)
  {
    from.row(k) = target_v.row(pv[k].second);
    to.row(k) = carried.row(pv[k].first);
  }
  Rigid_motion m = fit_rigid_motion(from, to);
  if(rule.kind == Docking_kind::boundary && !rule.seam.empty())
  {
    // Thin seam: the pair geometry gave the orientation; the seams meet.
    Eigen::Vector3d su = Eigen::Vector3d::Zero(), sv = Eigen::Vector3d::Zero();
    for(const auto& [l0, l1] : rule.seam)
    {
      su += placed_u.row(side_u == 0 ? l0 : l1).transpose();
      sv += m.rotation * target_v.row(side_u == 0 ? l1 : l0).transpose() + m.translation;
    }
    m.translation += (su - sv) / double(rule.seam.size());
  }
  return m;
}

// Places each node next to its parent in the breadth-first tree from the
// root, so that each docks to an already placed part.
class Placement_visitor : public boost::default_bfs_visitor
{
public:
  using edge_descriptor = boost::graph_traits<Part_adjacency_graph>::edge_descriptor;

  Placement_visitor(const Morphable_part_model& model, const Part_graph& graph,
                    const std::vector<Point_matrix>& targets, std::vector<Rigid_motion>& motion, Point_matrix& placed_u)
    : model_(model), graph_(graph), targets_(targets), motion_(motion), placed_u_(placed_u)
  {}

  void examine_vertex(std::size_t u, const Part_adjacency_graph&) { placed_u_ = motion_[u].apply(targets_[u]); }

  void tree_edge(const edge_descriptor& d, const Part_adjacency_graph& g)
  {
    const Part_edge& e = graph_.edges[g[d]];
    const std::size_t v = boost::target(d, g);
    motion_[v] = place_neighbour(model_.rules[e.rule], e, int(boost::source(d, g)), placed_u_, targets_[v]);
  }

private:
  // References: Boost.Graph copies its visitor.
  const Morphable_part_model& model_;
  const Part_graph& graph_;
  const std::vector<Point_matrix>& targets_;
  std::vector<Rigid_motion>& motion_;
  Point_matrix& placed_u_; // the part whose dockings are examined, placed
};

// The graph is valid and the options fit it: one target and one placement
// per node when given, a root among the nodes.
void check_assembly_input(const Morphable_part_model& model, const Part_graph& input, const Assembly_options& options)
{
  validate_part_graph(model, input);
  const int n = static_cast<int>(input.nodes.size());
  if(!options.targets.empty() && int(options.targets.size()) != n)
    throw Input_error("assembly options", "targets", "give one target per node (" + std::to_string(n) + ")");
  if(!options.placements.empty() && int(options.placements.size()) != n)
    throw Input_error("assembly options", "placements", "give one placement per node (" + std::to_string(n) + ")");
  if(options.root >= n) throw Input_error("assembly options", "root", "node " + std::to_string(options.root) + " does not exist");
}

// Each node's target shape in the frame of its type's space: the type's
// shape at the node's coordinates, or the given target moved into that
// frame by `given_frame` (identity for the former).
std::vector<Point_matrix> target_shapes(const Morphable_part_model& model, const Part_graph& graph,
                                        const Assembly_options& options, std::vector<Rigid_motion>& given_frame)
{
  const int n = static_cast<int>(graph.nodes.size());
  std::vector<Point_matrix> targets(n);
  given_frame.assign(n, Rigid_motion());
  for(int i = 0; i < n; ++i)
  {
    const Part_type& type = model.types[graph.nodes[i].type];
    if(options.targets.empty())
      targets[i] = type.space.shape(graph.nodes[i].coordinates);
    else
    {
      const Point_matrix& t = options.targets[i];
      if(t.rows() != type.number_of_vertices || !t.allFinite())
        throw Input_error("assembly options", "target of node " + std::to_string(i),
                          "needs " + std::to_string(type.number_of_vertices) + " finite points");
      given_frame[i] = fit_rigid_motion(t, type.space.mean);
      targets[i] = given_frame[i].apply(t);
    }
  }
  return targets;
}

// Each node's rigid placement: given, or breadth-first from the root along
// the dockings.
std::vector<Rigid_motion> place_parts(const Morphable_part_model& model, const Part_graph& graph,
                                      const std::vector<Point_matrix>& targets,
                                      const std::vector<Rigid_motion>& given_frame, const Assembly_options& options)
{
  const int n = static_cast<int>(graph.nodes.size());
  std::vector<Rigid_motion> motion(n);
  if(!options.placements.empty())
    for(int i = 0; i < n; ++i) motion[i] = compose(options.placements[i], given_frame[i].inverse());
  else
  {
    Point_matrix placed_u;
    boost::breadth_first_search(adjacency_graph(graph), std::size_t(options.root >= 0 ? options.root : 0),
                                boost::visitor(Placement_visitor(model, graph, targets, motion, placed_u)));
  }
  return motion;
}

// Stitching: one vertex per class of identified (node, local) pairs.
// Differently sampled seams (merged seams) first insert their vertices
// into the parts that lack them: node i's inserted vertices follow its
// type's locals, each splitting a border edge of the part. Fills the
// nodes' motions and vertices, each face's node and type and the merged
// seams' vertices of `result`; returns the stitched mesh at the placement.
Indexed_mesh stitch_parts(const Morphable_part_model& model, const internal::Graph_refinement& refined,
                          const std::vector<Point_matrix>& targets, const std::vector<Rigid_motion>& motion,
                          Assembly& result)
{
  Part_graph& graph = result.graph;
  const int n = static_cast<int>(graph.nodes.size());
  std::vector<Point_matrix> placed_points(n);
  for(int i = 0; i < n; ++i)
  {
    const Point_matrix placed_target = motion[i].apply(targets[i]);
    const std::vector<internal::Inserted_vertex>& inserted = refined.nodes[i].inserted;
    placed_points[i] = inserted.empty() ? placed_target : internal::refine_points(placed_target, inserted);
    graph.nodes[i].motion = motion[i];
    graph.nodes[i].label = -1;
  }
  Indexed_mesh mesh = internal::stitch_part_graph(model, graph, refined, placed_points, &result.face_nodes);
  for(int node : result.face_nodes) result.face_types.push_back(graph.nodes[node].type);
  result.seam_vertices.assign(graph.edges.size(), {});
  for(std::size_t k = 0; k < graph.edges.size(); ++k)
    for(const std::array<int, 2>& l : refined.merged_locals[k])
      result.seam_vertices[k].push_back(graph.nodes[graph.edges[k].first].vertices[l[0]]);
  return mesh;
}

// Each edge's motion: from its rule's mean pair geometry to where the
// stitched placement `initial` puts the pair's points.
void fit_edge_motions(const Morphable_part_model& model, const Point_matrix& initial, Part_graph& graph)
{
  for(Part_edge& e : graph.edges)
  {
    const Docking_rule& rule = model.rules[e.rule];
    Point_matrix rest(rule.points.size(), 3);
    for(std::size_t k = 0; k < rule.points.size(); ++k)
      rest.row(k) = initial.row(graph.nodes[rule.points[k].side == 0 ? e.first : e.second].vertices[rule.points[k].local]);
    e.motion = fit_rigid_motion(rule.space.mean, rest);
  }
}

// Runs the embedding solver without handles on `result.problem` from the
// placement and records the embedding, its energies and timings.
void embed(Assembly& result, const Assembly_options& options, Clock::time_point setup_start)
{
  const int n = static_cast<int>(result.graph.nodes.size());
  Embedding_solver solver(result.problem, options.solver);
  result.setup_ms = milliseconds_since(setup_start);
  const Clock::time_point solve_start = Clock::now();
  result.report = solver.solve();
  result.mesh.points = solver.positions();
  result.solve_ms = milliseconds_since(solve_start);
  result.residual_energy = result.report.energy();
  for(int c = 0; c < solver.number_of_clusters(); ++c)
    (c < n ? result.part_energies : result.docking_energies).push_back(solver.cluster_energy(c));
  if(!result.mesh.points.allFinite() || !std::isfinite(result.residual_energy))
    throw Computation_error("the assembly of " + std::to_string(n) + " parts produced non-finite positions or energy");
}

} // namespace

Assembly_options training_assembly_options(const Morphable_part_model& model, int example)
{
  if(example < 0 || example >= int(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  const Training_example& ex = model.examples[example];
  const Point_matrix rest = rest_positions(ex);
  Assembly_options o;
  for(const Part_node& node : ex.graph.nodes)
  {
    // A node of a stitched example lists the seam vertices inserted into it
    // after its type's own: the target is its own vertices.
    const auto own = std::size_t(model.types[std::size_t(node.type)].number_of_vertices);
    o.targets.push_back(gather_rows(rest, std::vector<int>(node.vertices.begin(), node.vertices.begin() + std::ptrdiff_t(own))));
    o.placements.push_back(Rigid_motion());
  }
  return o;
}

Assembly assemble(const Morphable_part_model& model, const Part_graph& input, const Assembly_options& options)
{
  const Clock::time_point setup_start = Clock::now();
  check_assembly_input(model, input, options);
  Assembly result;
  result.graph = input;
  std::vector<Rigid_motion> given_frame; // given target frame -> space frame
  const std::vector<Point_matrix> targets = target_shapes(model, result.graph, options, given_frame);
  const std::vector<Rigid_motion> motion = place_parts(model, result.graph, targets, given_frame, options);
  const internal::Graph_refinement refined = internal::refine_part_graph(model, result.graph);
  const Indexed_mesh mesh = stitch_parts(model, refined, targets, motion, result);
  fit_edge_motions(model, mesh.points, result.graph);

  result.problem = internal::make_part_graph_problem(
    model, result.graph, mesh,
    [&targets](int node, const Shape_space& space, const Eigen::VectorXd&, const Point_matrix&, const std::string&) {
      return internal::Part_target{targets[node], space.sigmas};
    },
    [](const Shape_space& space) { return space.sigmas; }, &refined.nodes);
  result.initial_positions = mesh.points;
  result.mesh = mesh;

  if(!options.solve)
  {
    result.setup_ms = milliseconds_since(setup_start);
    return result;
  }
  embed(result, options, setup_start);
  return result;
}

std::vector<Spawned_graph> spawn_part_graphs(const Morphable_part_model& model, const Part_graph& start,
                                             const Spawn_options& options)
{
  if(options.count < 0) throw Input_error("spawn options", "count", "must not be negative");
  if(!options.assembly.targets.empty() || !options.assembly.placements.empty())
    throw Input_error("spawn options", "assembly", "targets and placements do not apply to spawned graphs");
  validate_part_graph(model, start, "start graph");
  std::mt19937 rng(options.seed);
  std::vector<Spawned_graph> spawned;
  for(int i = 0; i < options.count; ++i)
  {
    internal::throw_if_cancelled(options.assembly.solver.cancel, "spawning");
    Spawned_graph s;
    s.index = i;
    s.graph = random_part_graph(model, start, rng, options.edits, &s.edits);
    s.assembly = assemble(model, s.graph, options.assembly);
    spawned.push_back(std::move(s));
    if(options.progress) options.progress(i + 1, options.count);
  }
  std::stable_sort(spawned.begin(), spawned.end(), [](const Spawned_graph& a, const Spawned_graph& b) {
    return a.assembly.energy_per_part() < b.assembly.energy_per_part();
  });
  return spawned;
}

int crossings_of_node(const Assembly& a, int node)
{
  std::vector<std::pair<int, int>> pairs;
  self_intersecting_faces(a.mesh, pairs);
  int crossing = 0;
  for(const auto& [f, g] : pairs) crossing += (a.face_nodes[std::size_t(f)] == node) != (a.face_nodes[std::size_t(g)] == node);
  return crossing;
}

} // namespace MPM
} // namespace CGAL
