// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Clusters of a part graph: one per part instance, one per docking (pair
// geometry). Used by the editing problems and by assembly.
#include <CGAL/MPM/internal/Part_graph_problem.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>

#include <Eigen/SVD>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

namespace CGAL {
namespace MPM {
namespace internal {

Point_matrix gather_rows(const Point_matrix& points, const std::vector<int>& vertices)
{
  Point_matrix p(vertices.size(), 3);
  for(std::size_t i = 0; i < vertices.size(); ++i) p.row(i) = points.row(vertices[i]);
  return p;
}

Point_matrix to_space_frame(const Rigid_motion& motion, const Point_matrix& points)
{
  return motion.inverse().apply(points);
}

bool seam_is_collinear(const Point_matrix& p)
{
  if(p.rows() < 3) return true;
  const Eigen::Vector3d spread = Eigen::JacobiSVD<Point_matrix>(p.rowwise() - p.colwise().mean()).singularValues();
  return !(spread[1] > 1e-3 * spread[0]);
}

Point_matrix refine_points(const Point_matrix& points, const std::vector<Inserted_vertex>& inserted)
{
  Point_matrix r(points.rows() + Eigen::Index(inserted.size()), 3);
  r.topRows(points.rows()) = points;
  for(std::size_t k = 0; k < inserted.size(); ++k)
    r.row(points.rows() + Eigen::Index(k)) =
      (1. - inserted[k].weight) * points.row(inserted[k].from) + inserted[k].weight * points.row(inserted[k].to);
  return r;
}

Eigen::MatrixXd refine_modes(const Eigen::MatrixXd& modes, const std::vector<Inserted_vertex>& inserted)
{
  Eigen::MatrixXd r(modes.rows() + 3 * Eigen::Index(inserted.size()), modes.cols());
  if(modes.cols() == 0) return r; // no modes: no data to take row blocks of
  r.topRows(modes.rows()) = modes;
  for(std::size_t k = 0; k < inserted.size(); ++k)
    r.middleRows(modes.rows() + 3 * Eigen::Index(k), 3) =
      (1. - inserted[k].weight) * modes.middleRows(3 * inserted[k].from, 3) +
      inserted[k].weight * modes.middleRows(3 * inserted[k].to, 3);
  return r;
}

const std::vector<Seam_vertex>& merged_seam_of(const Docking_rule& rule, const Part_edge& edge)
{
  return edge.merged_seam.empty() ? rule.merged_seam : edge.merged_seam;
}

void seam_points(const Docking_rule& rule, const std::vector<Seam_vertex>& merged, const Point_matrix& first,
                 const Point_matrix& second, Point_matrix& on_first, Point_matrix& on_second)
{
  if(merged.empty())
  {
    on_first.resize(rule.seam.size(), 3);
    on_second.resize(rule.seam.size(), 3);
    for(std::size_t k = 0; k < rule.seam.size(); ++k)
    {
      on_first.row(k) = first.row(rule.seam[k].first);
      on_second.row(k) = second.row(rule.seam[k].second);
    }
    return;
  }
  on_first.resize(merged.size(), 3);
  on_second.resize(merged.size(), 3);
  for(std::size_t k = 0; k < merged.size(); ++k)
  {
    const Seam_vertex& v = merged[k];
    for(int s = 0; s < 2; ++s)
    {
      const Point_matrix& p = s == 0 ? first : second;
      (s == 0 ? on_first : on_second).row(k) =
        v.local[s] >= 0 ? Eigen::RowVector3d(p.row(v.local[s]))
                        : Eigen::RowVector3d((1. - v.weight[s]) * p.row(v.from[s]) + v.weight[s] * p.row(v.to[s]));
    }
  }
}

bool Graph_refinement::empty() const
{
  return std::all_of(nodes.begin(), nodes.end(), [](const Part_refinement& r) { return r.inserted.empty(); });
}

namespace {

// Splits each border edge (from, to) of `type` at its inserted vertices, in
// order: the triangle (from, to, c) becomes the fan (from, x1, c) ... (xk, to, c).
void split_border_edges(const Part_type& type, int node, Part_refinement& r)
{
  std::map<std::pair<int, int>, std::vector<std::pair<double, int>>> on_edge;
  for(std::size_t k = 0; k < r.inserted.size(); ++k)
    on_edge[{r.inserted[k].from, r.inserted[k].to}].push_back({r.inserted[k].weight, type.number_of_vertices + int(k)});
  r.triangles = type.triangles;
  std::set<std::pair<int, int>> split;
  for(auto& [edge, inserted] : on_edge)
  {
    std::sort(inserted.begin(), inserted.end());
    bool found = false;
    for(std::size_t t = 0; t < r.triangles.size() && !found; ++t)
      for(int c = 0; c < 3 && !found; ++c)
      {
        const Triangle tri = r.triangles[t];
        if(tri[c] != edge.first || tri[(c + 1) % 3] != edge.second) continue;
        found = true;
        const int apex = tri[(c + 2) % 3];
        int previous = edge.first;
        std::vector<Triangle> fan;
        for(const auto& [w, x] : inserted)
        {
          fan.push_back({previous, x, apex});
          previous = x;
        }
        fan.push_back({previous, edge.second, apex});
        r.triangles[t] = fan.front();
        r.triangles.insert(r.triangles.end(), fan.begin() + 1, fan.end());
        split.insert({std::min(edge.first, edge.second), std::max(edge.first, edge.second)});
      }
    if(!found)
      throw Input_error(part_graph_source, "node " + std::to_string(node) + " (" + type.name + ")",
                        "a merged seam splits its edge " + std::to_string(edge.first) + " - " +
                          std::to_string(edge.second) + ", which is not a border edge of its type");
  }
  std::set<std::pair<int, int>> edges;
  for(const Cluster_edge& ce : type.edges)
    if(!ce.is_virtual && !split.count({ce.source, ce.target})) edges.insert({ce.source, ce.target});
  for(const Triangle& t : r.triangles)
    for(int c = 0; c < 3; ++c) edges.insert({std::min(t[c], t[(c + 1) % 3]), std::max(t[c], t[(c + 1) % 3])});
  for(const auto& [a, b] : edges) r.edges.push_back({a, b, false});
  for(const Cluster_edge& ce : type.edges)
    if(ce.is_virtual) r.edges.push_back(ce);
}

} // namespace

Graph_refinement refine_part_graph(const Morphable_part_model& model, const Part_graph& graph)
{
  Graph_refinement result;
  result.nodes.resize(graph.nodes.size());
  result.merged_locals.resize(graph.edges.size());
  // Per node: inserted vertex of each (from, to, weight), so that dockings
  // meeting at one point of a border edge insert it once.
  std::vector<std::map<std::tuple<int, int, double>, int>> inserted_at(graph.nodes.size());
  for(std::size_t k = 0; k < graph.edges.size(); ++k)
  {
    const Part_edge& e = graph.edges[k];
    for(const Seam_vertex& v : merged_seam_of(model.rules[e.rule], e))
    {
      std::array<int, 2> local = v.local;
      for(int s = 0; s < 2; ++s)
        if(local[s] < 0)
        {
          const int node = s == 0 ? e.first : e.second;
          Part_refinement& r = result.nodes[node];
          const auto [it, added] = inserted_at[node].insert(
            {{v.from[s], v.to[s], v.weight[s]}, model.types[graph.nodes[node].type].number_of_vertices + int(r.inserted.size())});
          if(added) r.inserted.push_back({v.from[s], v.to[s], v.weight[s]});
          local[s] = it->second;
        }
      result.merged_locals[k].push_back(local);
    }
  }
  for(std::size_t i = 0; i < graph.nodes.size(); ++i)
    if(!result.nodes[i].inserted.empty())
      split_border_edges(model.types[graph.nodes[i].type], static_cast<int>(i), result.nodes[i]);
  return result;
}

Indexed_mesh stitch_part_graph(const Morphable_part_model& model, Part_graph& graph, const Graph_refinement& refined,
                               const std::vector<Point_matrix>& placed, std::vector<int>* face_nodes)
{
  const std::size_t n = graph.nodes.size();
  std::vector<int> offset(n + 1, 0);
  for(std::size_t i = 0; i < n; ++i)
    offset[i + 1] = offset[i] + model.types[graph.nodes[i].type].number_of_vertices + int(refined.nodes[i].inserted.size());
  const int total = offset[n];
  std::vector<int> rank(total), parent(total);
  boost::disjoint_sets<int*, int*> classes(rank.data(), parent.data());
  for(int v = 0; v < total; ++v) classes.make_set(v);
  for(std::size_t k = 0; k < graph.edges.size(); ++k)
  {
    const Part_edge& e = graph.edges[k];
    if(e.merged_seam.empty())
      for(const auto& [l0, l1] : model.rules[e.rule].seam) classes.union_set(offset[e.first] + l0, offset[e.second] + l1);
    for(const std::array<int, 2>& l : refined.merged_locals[k])
      classes.union_set(offset[e.first] + l[0], offset[e.second] + l[1]);
  }
  std::vector<int> vertex_of_class(total, -1);
  int vertices = 0;
  for(int v = 0; v < total; ++v)
  {
    const int c = classes.find_set(v);
    if(vertex_of_class[c] < 0) vertex_of_class[c] = vertices++;
  }
  Point_matrix sum = Point_matrix::Zero(vertices, 3);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(vertices);
  for(std::size_t i = 0; i < n; ++i)
  {
    Part_node& node = graph.nodes[i];
    const int locals = offset[i + 1] - offset[i];
    node.vertices.assign(locals, -1);
    std::map<int, int> local_of_vertex;
    for(int l = 0; l < locals; ++l)
    {
      const int v = vertex_of_class[classes.find_set(offset[i] + l)];
      const auto [it, inserted] = local_of_vertex.insert({v, l});
      if(!inserted)
        throw Input_error(part_graph_source, "node " + std::to_string(i) + " (" + model.types[node.type].name + ")",
                          "its dockings identify its local vertices " + std::to_string(it->second) + " and " +
                            std::to_string(l) + " (a cycle of dockings that does not close consistently)");
      node.vertices[l] = v;
      sum.row(v) += placed[i].row(l);
      count[v] += 1.;
    }
  }
  Indexed_mesh mesh;
  mesh.points.resize(vertices, 3);
  for(int v = 0; v < vertices; ++v) mesh.points.row(v) = sum.row(v) / count[v];
  for(std::size_t i = 0; i < n; ++i)
    for(const Triangle& t : refined.nodes[i].inserted.empty() ? model.types[graph.nodes[i].type].triangles
                                                              : refined.nodes[i].triangles)
    {
      mesh.triangles.push_back({graph.nodes[i].vertices[t[0]], graph.nodes[i].vertices[t[1]], graph.nodes[i].vertices[t[2]]});
      if(face_nodes) face_nodes->push_back(static_cast<int>(i));
    }
  return mesh;
}

namespace {

// Where two placed part targets disagree on their common seam (their types'
// shapes differ there), both meet halfway and the difference fades out over
// half the seam's radius on either side. Left to the pair cluster alone, it
// crumpled the first ring of triangles of one side (symmetrize and
// caricature turned them inside out); given to the pairs but not to the
// parts, the two fought and the solve ran twice as long.
// Only what the targets add to the disagreement at rest counts: a vertex
// inserted into one side's border edge lies off that side's chord at rest,
// and the rest must stay a solution.
void meet_halfway(const Docking_rule& rule, const std::vector<Seam_vertex>& merged, const Point_matrix& first_rest,
                  const Point_matrix& second_rest, Point_matrix& first, Point_matrix& second)
{
  Point_matrix on_first, on_second, rest_on_first, rest_on_second;
  seam_points(rule, merged, first, second, on_first, on_second);
  if(on_first.rows() == 0 || seam_is_collinear(on_second)) return;
  seam_points(rule, merged, first_rest, second_rest, rest_on_first, rest_on_second);
  // The disagreements on the seam, in the first part's frame.
  const Rigid_motion onto_first = fit_rigid_motion(on_second, on_first);
  const Point_matrix gap = on_first - onto_first.apply(on_second) -
                           (rest_on_first - fit_rigid_motion(rest_on_second, rest_on_first).apply(rest_on_second));
  const Eigen::RowVector3d centre = on_first.colwise().mean();
  const double radius = std::sqrt((on_first.rowwise() - centre).rowwise().squaredNorm().mean());
  if(!(radius > 0.) || !(gap.norm() > 0.)) return;
  const double width = 0.5 * radius;
  // Offsets of the points of `p` near `seam`, in the frame of `seam`.
  const auto spread = [&](const Point_matrix& p, const Point_matrix& seam) {
    Point_matrix offsets(p.rows(), 3);
    for(Eigen::Index i = 0; i < p.rows(); ++i)
    {
      Eigen::Index k = 0;
      const double d2 = (seam.rowwise() - p.row(i)).rowwise().squaredNorm().minCoeff(&k);
      offsets.row(i) = 0.5 * std::exp(-d2 / (width * width)) * gap.row(k);
    }
    return offsets;
  };
  first -= spread(first, on_first);
  second += spread(second, on_second) * onto_first.rotation; // gap turned into the second part's frame
}

} // namespace

Point_matrix pair_target(const Docking_rule& rule, const std::vector<Seam_vertex>& merged, const Point_matrix& first,
                         Point_matrix second, const Point_matrix& first_rest, const Point_matrix& second_rest,
                         const Rigid_motion& pair_motion, const Point_matrix& rest)
{
  if(!merged.empty())
  {
    // A merged seam: the second part is placed on the first by every merged
    // vertex (interpolated where it is inserted); a merged loop is never
    // collinear (it has at least as many points as either loop). An
    // interpolated vertex lies off the seam at rest, which tilts that fit:
    // the tilt the rest has is taken back (moving the first rest seam onto
    // the second's is the inverse of the rest fit), so the rest stays a
    // solution.
    Point_matrix on_first, on_second, rest_on_first, rest_on_second;
    seam_points(rule, merged, first, second, on_first, on_second);
    seam_points(rule, merged, first_rest, second_rest, rest_on_first, rest_on_second);
    if(!seam_is_collinear(on_second))
      second = fit_rigid_motion(rest_on_first, rest_on_second).apply(fit_rigid_motion(on_second, on_first).apply(second));
  }
  else if(!rule.seam.empty())
  {
    Point_matrix from(rule.seam.size(), 3), to(rule.seam.size(), 3);
    for(std::size_t k = 0; k < rule.seam.size(); ++k)
    {
      from.row(k) = second.row(rule.seam[k].second);
      to.row(k) = first.row(rule.seam[k].first);
    }
    if(!seam_is_collinear(from))
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

Embedding_problem make_part_graph_problem(const Morphable_part_model& model, const Part_graph& graph,
                                          const Indexed_mesh& mesh, const Part_target_policy& policy,
                                          const Pair_sigma_policy& pair_sigmas,
                                          const std::vector<Part_refinement>* refinements, bool keep_inserted_offsets)
{
  Embedding_problem problem;
  problem.mesh = mesh;
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
    for(const Seam_vertex& v : merged_seam_of(rule, e))
      for(int s = 0; s < 2; ++s)
        if(v.local[s] >= 0) (s == 0 ? seams[e.first] : seams[e.second]).insert(v.local[s]);
  }
  // Inserted seam vertices fade like the seam they lie on.
  if(refinements)
    for(std::size_t i = 0; i < graph.nodes.size() && i < refinements->size(); ++i)
      for(std::size_t k = 0; k < (*refinements)[i].inserted.size(); ++k)
        seams[i].insert(model.types[graph.nodes[i].type].number_of_vertices + int(k));
  // The type's own local vertices of a node (a refined node lists its
  // inserted vertices after them).
  const auto type_vertices = [&](const Part_node& node) {
    const std::size_t n = static_cast<std::size_t>(model.types[node.type].number_of_vertices);
    return node.vertices.size() > n ? std::vector<int>(node.vertices.begin(), node.vertices.begin() + n)
                                    : node.vertices;
  };

  // Each part's target shape, placed where the part rests: pair targets are
  // assembled from them, so that parts and pairs ask for the same shape.
  // Neighbours meet halfway where their targets disagree on a seam.
  std::vector<Point_matrix> rest_of_node; // each node's own points where the mesh rests
  std::vector<Part_target> targets;
  std::vector<Point_matrix> placed_targets;
  for(std::size_t i = 0; i < graph.nodes.size(); ++i)
  {
    const Part_node& node = graph.nodes[i];
    rest_of_node.push_back(gather_rows(mesh.points, type_vertices(node)));
    targets.push_back(policy(static_cast<int>(i), model.types[node.type].space, node.coordinates,
                             to_space_frame(node.motion, rest_of_node.back()), model.types[node.type].name));
    placed_targets.push_back(node.motion.apply(targets.back().mean));
  }
  for(const Part_edge& e : graph.edges)
    meet_halfway(model.rules[e.rule], merged_seam_of(model.rules[e.rule], e), rest_of_node[e.first],
                 rest_of_node[e.second], placed_targets[e.first], placed_targets[e.second]);
  for(std::size_t i = 0; i < graph.nodes.size(); ++i)
  {
    const Part_node& node = graph.nodes[i];
    const Part_type& type = model.types[node.type];
    Part_target& t = targets[i];
    t.mean = to_space_frame(node.motion, placed_targets[i]);
    Cluster c;
    c.name = "part " + std::to_string(i) + " (" + type.name +
             (node.label >= 0 ? ", label " + std::to_string(node.label) : std::string()) + ")";
    c.vertices = node.vertices;
    c.triangles = type.triangles;
    c.edges = type.edges;
    c.mean = t.mean;
    c.modes = type.space.modes;
    if(refinements && i < refinements->size() && !(*refinements)[i].inserted.empty())
    {
      const Part_refinement& r = (*refinements)[i];
      c.triangles = r.triangles;
      c.edges = r.edges;
      c.mean = refine_points(t.mean, r.inserted);
      c.modes = refine_modes(type.space.modes, r.inserted);
      const Eigen::Index n = type.number_of_vertices, k = Eigen::Index(r.inserted.size());
      if(keep_inserted_offsets && Eigen::Index(node.vertices.size()) == n + k)
      {
        // An inserted vertex keeps its rest offset from the chord of its
        // split edge: where the other side's triangle has two edges on the
        // seam, the chord would flatten that triangle.
        const Point_matrix rest = to_space_frame(node.motion, gather_rows(mesh.points, node.vertices));
        c.mean.bottomRows(k) += rest.bottomRows(k) - refine_points(rest.topRows(n), r.inserted).bottomRows(k);
      }
    }
    c.sigmas = t.sigmas;
    c.border.assign(seams[i].begin(), seams[i].end());
    c.sigma_bound = model.parameters.sigma_bound;
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
    c.mean = pair_target(rule, merged_seam_of(rule, e), placed_targets[e.first], placed_targets[e.second],
                         rest_of_node[e.first], rest_of_node[e.second], e.motion, gather_rows(mesh.points, c.vertices));
    c.modes = rule.space.modes;
    c.sigmas = pair_sigmas(rule.space);
    c.sigma_bound = model.parameters.sigma_bound;
    problem.clusters.push_back(std::move(c));
  }

  // Neighbouring instances of one type: docked to each other or to a common part.
  const Part_adjacency_graph g = adjacency_graph(graph);
  std::set<std::pair<int, int>> coupled;
  const auto couple = [&](int a, int c) {
    if(c != a && graph.nodes[c].type == graph.nodes[a].type &&
       model.types[graph.nodes[a].type].space.number_of_modes() > 0)
      coupled.insert({std::min(a, c), std::max(a, c)});
  };
  for(int a = 0; a < int(graph.nodes.size()); ++a)
    for(auto [b, b_end] = boost::adjacent_vertices(a, g); b != b_end; ++b)
    {
      couple(a, int(*b));
      for(auto [c, c_end] = boost::adjacent_vertices(*b, g); c != c_end; ++c) couple(a, int(*c));
    }
  problem.coupled_clusters.assign(coupled.begin(), coupled.end());
  return problem;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
