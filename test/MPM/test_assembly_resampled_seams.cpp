// Seams sampled differently (paper section 4, "Seamless stitching"): a
// derived rule between boundary loops of different vertex counts merges the
// two loops, assembly splits the border triangles of each side so that every
// merged-loop vertex lies on both, and the inserted vertices get statistics
// interpolated from their two loop neighbours. Tubes of 12 and of 16 vertices
// per ring, each type learned from its own chain of tubes; then A - B - A.
//
// Like test_assembly.cpp, this test includes CGAL's self-intersection test.
#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include "Mesh_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>

using namespace CGAL::MPM;

namespace {

constexpr int rings_per_segment = 5; // four bands of quads per tube segment

// A chain of tube segments along z, `ring` vertices per ring, radius 1 at
// the segment ends (so that any two tubes meet) and a bulge in between;
// segment k (label k) has length lengths[k] and bulge bulges[k]. Open at
// both ends, outward-oriented. Every segment lists its faces in the same
// order, so its local numbering is the same.
Training_input tube_chain(int ring, const std::string& type, const std::vector<double>& lengths,
                          const std::vector<double>& bulges, double twist = 0.)
{
  const double pi = std::acos(-1.);
  const int segments = static_cast<int>(lengths.size());
  const int rings = segments * (rings_per_segment - 1) + 1;
  Training_input input;
  Indexed_mesh& mesh = input.mesh.mesh;
  mesh.points.resize(rings * ring, 3);
  double z = 0.;
  for(int s = 0; s < segments; ++s)
    for(int k = (s == 0 ? 0 : 1); k < rings_per_segment; ++k)
    {
      const double u = double(k) / (rings_per_segment - 1);
      const double r = 1. + bulges[s] * std::sin(pi * u);
      const double h = z + u * lengths[s];
      const int row = s * (rings_per_segment - 1) + k;
      for(int j = 0; j < ring; ++j)
      {
        const double a = twist + 2. * pi * j / ring;
        mesh.points.row(row * ring + j) << r * std::cos(a), r * std::sin(a), h;
      }
      if(k == rings_per_segment - 1) z = h;
    }
  for(int s = 0; s < segments; ++s)
    for(int k = 0; k + 1 < rings_per_segment; ++k)
    {
      const int row = s * (rings_per_segment - 1) + k;
      for(int j = 0; j < ring; ++j)
      {
        const int a = row * ring + j, b = row * ring + (j + 1) % ring;
        const int c = (row + 1) * ring + (j + 1) % ring, d = (row + 1) * ring + j;
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
        input.mesh.face_labels.push_back(s);
        input.mesh.face_labels.push_back(s);
      }
    }
  input.mesh.source = type + " chain";
  for(int s = 0; s < segments; ++s) input.annotation.part_type_of_label[s] = type;
  input.annotation.parameters.docking_radius = 0.5; // the seam ring and the next one on either side
  input.annotation.parameters.explained_variance = 0.999;
  return input;
}

// Tube type "A" (`ring_a` per ring, 12 by default) from one chain, "B"
// (`ring_b`, 16) from another.
const Morphable_part_model& tube_model(int ring_a = 12, int ring_b = 16)
{
  static std::map<std::pair<int, int>, Morphable_part_model> cache;
  auto it = cache.find({ring_a, ring_b});
  if(it == cache.end())
  {
    std::vector<Training_input> inputs;
    inputs.push_back(tube_chain(ring_a, "A", {1.6, 1.8, 1.5, 1.7}, {0.10, 0.18, 0.05, 0.14}));
    inputs.push_back(tube_chain(ring_b, "B", {1.7, 1.5, 1.9, 1.6}, {0.16, 0.08, 0.12, 0.20}));
    it = cache.emplace(std::make_pair(ring_a, ring_b), learn_morphable_part_model(inputs)).first;
  }
  return it->second;
}

// The site of type `type` whose loop is at the high (top) or low end of its mean in z.
Site_ref end_site(const Morphable_part_model& m, int type, bool top)
{
  const Part_type& t = m.types[type];
  int best = -1;
  double best_z = 0.;
  for(std::size_t s = 0; s < t.sites.size(); ++s)
  {
    double z = 0.;
    for(int v : t.sites[s].vertices) z += t.space.mean(v, 2);
    z /= double(t.sites[s].vertices.size());
    if(best < 0 || (top ? z > best_z : z < best_z))
    {
      best = int(s);
      best_z = z;
    }
  }
  return {type, best};
}

using mpm_test::border_edges;
using mpm_test::self_intersects;

// Smallest triangle quality 4 sqrt(3) area / (sum of squared edge lengths): 1 for equilateral, 0 for degenerate.
double worst_quality(const Indexed_mesh& mesh)
{
  double worst = 1.;
  for(const Triangle& t : mesh.triangles)
  {
    const Eigen::Vector3d a = mesh.points.row(t[0]), b = mesh.points.row(t[1]), c = mesh.points.row(t[2]);
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    worst = std::min(worst, 4. * std::sqrt(3.) * area / squares);
  }
  return worst;
}

struct Tube_chain
{
  Morphable_part_model model;
  Part_graph graph;
  int a_to_b = -1, b_to_a = -1; // the derived rules
};

// A - B - A: A's top docks to B's bottom, B's top to the second A's bottom.
const Tube_chain& a_b_a(int ring_a = 12, int ring_b = 16)
{
  static std::map<std::pair<int, int>, Tube_chain> cache;
  auto it = cache.find({ring_a, ring_b});
  if(it != cache.end()) return it->second;
  Tube_chain c;
  c.model = tube_model(ring_a, ring_b);
  const int A = c.model.find_type("A"), B = c.model.find_type("B");
  c.a_to_b = add_derived_rule(c.model, end_site(c.model, A, true), end_site(c.model, B, false));
  c.b_to_a = add_derived_rule(c.model, end_site(c.model, B, true), end_site(c.model, A, false));
  for(int type : {A, B, A})
  {
    Part_node node;
    node.type = type;
    node.coordinates = Eigen::VectorXd::Zero(c.model.types[type].space.number_of_modes());
    c.graph.nodes.push_back(node);
  }
  Part_edge e;
  e.first = 0;
  e.second = 1;
  e.rule = c.a_to_b;
  c.graph.edges.push_back(e);
  e.first = 1;
  e.second = 2;
  e.rule = c.b_to_a;
  c.graph.edges.push_back(e);
  return cache.emplace(std::make_pair(ring_a, ring_b), std::move(c)).first->second;
}

// Largest distance of a part's embedded points from its target shape
// (cluster mean, rigidly fitted): the distortion the part takes.
double part_deviation(const Assembly& a, int node)
{
  const Cluster& c = a.problem.clusters[node];
  Point_matrix p(c.vertices.size(), 3);
  for(std::size_t k = 0; k < c.vertices.size(); ++k) p.row(k) = a.mesh.points.row(c.vertices[k]);
  return (fit_rigid_motion(c.mean, p).apply(c.mean) - p).rowwise().norm().maxCoeff();
}

// Distance of a chord's midpoint from the unit circle: how far apart the
// two sides want an inserted vertex (on the chord of one loop, on the
// circle of the other).
double sagitta(int ring) { return 1. - std::cos(std::acos(-1.) / ring); }

} // namespace

TEST(Resampled_seams, tube_types_learned_with_modes)
{
  const Morphable_part_model& m = tube_model();
  ASSERT_EQ(m.types.size(), 2u);
  for(const std::string& name : {"A", "B"})
  {
    const Part_type& t = m.types[m.find_type(name)];
    const int ring = name == "A" ? 12 : 16;
    EXPECT_EQ(t.number_of_vertices, rings_per_segment * ring) << name;
    ASSERT_EQ(t.sites.size(), 2u) << name;
    for(const Docking_site& s : t.sites) EXPECT_EQ(int(s.vertices.size()), ring) << name;
    EXPECT_GE(t.space.number_of_modes(), 1) << name;
  }
}

TEST(Resampled_seams, derived_rule_merges_the_two_loops)
{
  const Tube_chain& c = a_b_a();
  const Docking_rule& rule = c.model.rules[c.a_to_b];
  // Uniform loops of 12 and 16 aligned on a vertex pair meet at gcd(12, 16) = 4 vertices.
  EXPECT_EQ(rule.seam.size(), 4u);
  ASSERT_EQ(rule.merged_seam.size(), 12u + 16u - 4u);
  std::set<int> first, second;
  for(std::size_t k = 0; k < rule.merged_seam.size(); ++k)
  {
    const Seam_vertex& v = rule.merged_seam[k];
    if(k > 0) EXPECT_GT(v.parameter, rule.merged_seam[k - 1].parameter);
    ASSERT_TRUE(v.local[0] >= 0 || v.local[1] >= 0);
    for(int s = 0; s < 2; ++s)
      if(v.local[s] >= 0) (s == 0 ? first : second).insert(v.local[s]);
      else
      {
        EXPECT_GT(v.weight[s], 0.);
        EXPECT_LT(v.weight[s], 1.);
        EXPECT_GE(v.from[s], 0);
        EXPECT_GE(v.to[s], 0);
      }
  }
  EXPECT_EQ(first.size(), 12u);
  EXPECT_EQ(second.size(), 16u);
  const Part_type& A = c.model.types[rule.first.type];
  const Part_type& B = c.model.types[rule.second.type];
  EXPECT_EQ(std::vector<int>(first.begin(), first.end()), A.sites[rule.first.site].vertices);
  EXPECT_EQ(std::vector<int>(second.begin(), second.end()), B.sites[rule.second.site].vertices);
  // The pair space: B's mean docked on A's top, no modes.
  EXPECT_EQ(rule.space.number_of_modes(), 0);
  EXPECT_TRUE(rule.space.mean.allFinite());
  // Asking again returns the same rule; sites that are not boundary loops are rejected.
  Morphable_part_model m = c.model;
  EXPECT_EQ(add_derived_rule(m, rule.first, rule.second), c.a_to_b);
  EXPECT_EQ(m.rules.size(), c.model.rules.size());
  EXPECT_THROW(derive_docking_rule(m, {rule.first.type, 7}, rule.second), Input_error);
  EXPECT_THROW(derive_docking_rule(m, {42, 0}, rule.second), Input_error);
  // A model holding the derived rule saves and loads it whole.
  const std::string bytes = serialize_model(c.model);
  const Morphable_part_model loaded = deserialize_model(bytes, "memory");
  EXPECT_EQ(serialize_model(loaded), bytes);
  ASSERT_EQ(loaded.rules[c.a_to_b].merged_seam.size(), rule.merged_seam.size());
  EXPECT_EQ(loaded.rules[c.a_to_b].merged_seam.back().weight[1], rule.merged_seam.back().weight[1]);
}

TEST(Resampled_seams, a_b_a_assembles_seamlessly)
{
  const Tube_chain& c = a_b_a();
  const Morphable_part_model& m = c.model;
  EXPECT_NO_THROW(validate_part_graph(m, c.graph));
  const Assembly a = assemble(m, c.graph);
  const int nA = m.types[m.find_type("A")].number_of_vertices, nB = m.types[m.find_type("B")].number_of_vertices;
  const std::size_t merged = m.rules[c.a_to_b].merged_seam.size();

  // Every merged-loop vertex is one mesh vertex, on both sides.
  ASSERT_EQ(a.seam_vertices.size(), 2u);
  for(int k = 0; k < 2; ++k)
  {
    const Part_edge& e = a.graph.edges[k];
    const Docking_rule& rule = m.rules[e.rule];
    ASSERT_EQ(a.seam_vertices[k].size(), rule.merged_seam.size());
    EXPECT_EQ(std::set<int>(a.seam_vertices[k].begin(), a.seam_vertices[k].end()).size(), rule.merged_seam.size());
    for(std::size_t i = 0; i < rule.merged_seam.size(); ++i)
      for(int s = 0; s < 2; ++s)
        if(rule.merged_seam[i].local[s] >= 0)
          EXPECT_EQ(a.vertex(s == 0 ? e.first : e.second, rule.merged_seam[i].local[s]), a.seam_vertices[k][i]);
    for(const auto& [l0, l1] : rule.seam) EXPECT_EQ(a.vertex(e.first, l0), a.vertex(e.second, l1));
  }
  // Inserted vertices: the other side's loop vertices, listed after the type's own.
  EXPECT_EQ(a.graph.nodes[0].vertices.size(), std::size_t(nA) + 16u - 4u);
  EXPECT_EQ(a.graph.nodes[1].vertices.size(), std::size_t(nB) + 2u * (12u - 4u));
  EXPECT_EQ(a.graph.nodes[2].vertices.size(), std::size_t(nA) + 16u - 4u);
  EXPECT_EQ(a.mesh.number_of_vertices(), 2 * nA + nB - 2 * 4);
  // The part clusters carry the inserted vertices with interpolated statistics.
  for(int i = 0; i < 3; ++i)
  {
    const Cluster& cl = a.problem.clusters[i];
    EXPECT_EQ(cl.vertices, a.graph.nodes[i].vertices);
    EXPECT_EQ(cl.mean.rows(), Eigen::Index(cl.vertices.size()));
    EXPECT_EQ(cl.modes.rows(), 3 * Eigen::Index(cl.vertices.size()));
    EXPECT_TRUE(cl.mean.allFinite());
  }

  // Closed at the seams, no degenerate triangle, no self-intersection.
  EXPECT_EQ(border_edges(a.mesh.triangles), 12 + 12);
  const double quality = worst_quality(a.mesh);
  EXPECT_GT(quality, 0.05);
  EXPECT_TRUE(a.mesh.points.allFinite());
  EXPECT_FALSE(self_intersects(a.mesh));

  // Residual energy per part against the training chains': these rebuild
  // their meshes exactly (about 1e-21), so the factor is reported, not
  // bounded. What bounds the distortion: each part is off its target by
  // less than the sagitta of the coarser loop (an inserted vertex sits on
  // one side's chord and on the other side's circle), the price of
  // interpolated statistics.
  double training = 0.;
  for(int example = 0; example < 2; ++example)
    training = std::max(training, assemble(m, part_graph_of_example(m, example)).energy_per_part());
  std::cout << "[ resampled seams ] A - B - A: " << a.mesh.number_of_vertices() << " vertices, "
            << a.mesh.number_of_faces() << " faces, merged loops of " << merged << " vertices, worst triangle quality "
            << quality << ", energy per part " << a.energy_per_part() << " (training chains " << training
            << "), part energies";
  for(double e : a.part_energies) std::cout << " " << e;
  std::cout << ", docking energies";
  for(double e : a.docking_energies) std::cout << " " << e;
  std::cout << ", part deviations";
  for(int i = 0; i < 3; ++i) std::cout << " " << part_deviation(a, i);
  std::cout << " (sagitta of the 12-gon " << sagitta(12) << ")\n";
  EXPECT_TRUE(std::isfinite(a.residual_energy));
  for(int i = 0; i < 3; ++i) EXPECT_LT(part_deviation(a, i), sagitta(12));

  // The seam stays round: the merged loop's vertices keep the tubes' radius.
  for(const std::vector<int>& loop : a.seam_vertices)
  {
    Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
    for(int v : loop) centre += a.mesh.points.row(v);
    centre /= double(loop.size());
    double lo = 1e9, hi = 0.;
    for(int v : loop)
    {
      const double r = (a.mesh.points.row(v) - centre).norm();
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
    EXPECT_GT(lo, 0.9);
    EXPECT_LT(hi, 1.1);
  }
}

TEST(Resampled_seams, longer_chain_with_a_cycle_of_rules)
{
  // A - B - A - B - A through the two derived rules, non-mean coordinates.
  const Tube_chain& c = a_b_a();
  const Morphable_part_model& m = c.model;
  Part_graph g = c.graph;
  g.nodes.push_back(g.nodes[1]);
  g.nodes.push_back(g.nodes[0]);
  g.nodes[3].coordinates.setConstant(0.5 * m.types[g.nodes[3].type].space.sigmas[0]);
  g.nodes[4].coordinates.setConstant(-0.5 * m.types[g.nodes[4].type].space.sigmas[0]);
  Part_edge e = g.edges[0];
  e.first = 2;
  e.second = 3;
  g.edges.push_back(e);
  e = g.edges[1];
  e.first = 3;
  e.second = 4;
  g.edges.push_back(e);
  const Assembly a = assemble(m, g);
  EXPECT_EQ(border_edges(a.mesh.triangles), 24);
  EXPECT_GT(worst_quality(a.mesh), 0.05);
  EXPECT_FALSE(self_intersects(a.mesh));
  std::cout << "[ resampled seams ] A - B - A - B - A: energy per part " << a.energy_per_part() << "\n";
}

// The distortion is the discretization of the coarser loop: doubling both
// samplings (24 and 32 per ring) divides the deviation by about 4 and the
// energy per part by about 16 (energies are squared deviations).
TEST(Resampled_seams, distortion_shrinks_with_finer_loops)
{
  double energy[2], deviation[2];
  for(int k = 0; k < 2; ++k)
  {
    const Tube_chain& c = a_b_a(12 << k, 16 << k);
    const Assembly a = assemble(c.model, c.graph);
    EXPECT_EQ(border_edges(a.mesh.triangles), 2 * (12 << k));
    EXPECT_FALSE(self_intersects(a.mesh));
    energy[k] = a.energy_per_part();
    deviation[k] = std::max({part_deviation(a, 0), part_deviation(a, 1), part_deviation(a, 2)});
    std::cout << "[ resampled seams ] " << (12 << k) << " / " << (16 << k) << " per ring: energy per part "
              << energy[k] << ", largest part deviation " << deviation[k] << "\n";
  }
  EXPECT_LT(deviation[1], 0.4 * deviation[0]);
  EXPECT_LT(energy[1], 0.2 * energy[0]);
}

// Equal loops: the derived rule is the repetition rule, one to one, no
// merged seam, and assembling with it is the assembly as before (no split).
TEST(Resampled_seams, equal_loops_are_matched_one_to_one_as_before)
{
  Synthetic_options o;
  o.vertices = 3000;
  const Synthetic_model s = make_synthetic_model(Synthetic_family::hand, o);
  Morphable_part_model repeated = learn_morphable_part_model(s.mesh, s.annotation);
  Morphable_part_model derived = repeated;
  const std::vector<int> added = add_repetition_rules(repeated);
  ASSERT_FALSE(added.empty());
  for(int r : added)
  {
    const Docking_rule& rule = repeated.rules[r];
    EXPECT_TRUE(rule.merged_seam.empty());
    EXPECT_EQ(add_derived_rule(derived, rule.first, rule.second), r);
    const Docking_rule& d = derived.rules[r];
    EXPECT_TRUE(d.merged_seam.empty());
    EXPECT_EQ(d.seam, rule.seam);
    ASSERT_EQ(d.points.size(), rule.points.size());
    for(std::size_t k = 0; k < d.points.size(); ++k)
    {
      EXPECT_EQ(d.points[k].side, rule.points[k].side);
      EXPECT_EQ(d.points[k].local, rule.points[k].local);
    }
    EXPECT_EQ(d.edges.size(), rule.edges.size());
    EXPECT_EQ(d.space.mean, rule.space.mean);
  }
  // A finger with an inserted middle through the derived rule: bit for bit
  // the assembly through the repetition rule, with the type's own triangles.
  Part_graph g = part_graph_of_example(repeated);
  int middle = -1, distal = -1;
  for(std::size_t i = 0; i < g.nodes.size(); ++i)
  {
    const std::string& name = repeated.types[g.nodes[i].type].name;
    if(name == "middle" && middle < 0) middle = int(i);
    if(name == "distal" && distal < 0) distal = int(i);
  }
  int edge = -1;
  for(std::size_t k = 0; k < g.edges.size(); ++k)
    if((g.edges[k].first == middle && g.edges[k].second == distal) ||
       (g.edges[k].first == distal && g.edges[k].second == middle))
      edge = int(k);
  ASSERT_GE(edge, 0);
  insert_segment(repeated, g, edge);
  const Assembly a = assemble(repeated, g), b = assemble(derived, g);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.points, b.mesh.points);
  EXPECT_EQ(a.residual_energy, b.residual_energy);
  std::size_t faces = 0;
  for(const Part_node& node : g.nodes) faces += repeated.types[node.type].triangles.size();
  EXPECT_EQ(a.mesh.triangles.size(), faces);
  for(std::size_t i = 0; i < g.nodes.size(); ++i)
    EXPECT_EQ(a.graph.nodes[i].vertices.size(), std::size_t(repeated.types[g.nodes[i].type].number_of_vertices));
  for(const std::vector<int>& v : a.seam_vertices) EXPECT_TRUE(v.empty());
  std::cout << "[ resampled seams ] hand, inserted middle through the derived rule: energy per part "
            << a.energy_per_part() << "\n";
}

