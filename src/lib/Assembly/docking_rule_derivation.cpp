// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Docking rules the training did not observe, derived from two sites'
// seams (their samplings merged by arc length and twist): what lets a chain
// grow by one more segment.
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>
#include <CGAL/MPM/internal/Message_text.h>
#include <CGAL/MPM/internal/Part_graph_problem.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace CGAL {
namespace MPM {

using internal::part_graph_source;
using internal::quoted;
using internal::site_text;

namespace {

// The boundary loop of a site, directed as the part's boundary half-edges.
std::vector<int> boundary_loop(const Part_type& type, const Docking_site& site, const std::string& element)
{
  const std::set<int> in_site(site.vertices.begin(), site.vertices.end());
  std::set<std::pair<int, int>> half_edges;
  for(const Triangle& t : type.triangles)
    for(int k = 0; k < 3; ++k) half_edges.insert({t[k], t[(k + 1) % 3]});
  std::map<int, int> next;
  for(const auto& [u, v] : half_edges)
    if(!half_edges.count({v, u}) && in_site.count(u) && in_site.count(v))
    {
      if(next.count(u)) throw Input_error(part_graph_source, element, "the site is not one simple boundary loop");
      next[u] = v;
    }
  std::vector<int> loop;
  if(next.size() != in_site.size()) throw Input_error(part_graph_source, element, "the site is not one boundary loop");
  int v = next.begin()->first;
  for(std::size_t k = 0; k < next.size(); ++k)
  {
    loop.push_back(v);
    v = next.at(v);
  }
  if(v != loop.front() || std::set<int>(loop.begin(), loop.end()).size() != loop.size())
    throw Input_error(part_graph_source, element, "the site is not one simple boundary loop");
  return loop;
}

const Part_type& checked_type(const Morphable_part_model& model, int type)
{
  if(type < 0 || type >= int(model.types.size()))
    throw Input_error(part_graph_source, "part type " + std::to_string(type), "does not exist");
  return model.types[type];
}

// Normalized arc-length parameter of each vertex of a closed loop on `mean`.
std::vector<double> arc_parameters(const Point_matrix& mean, const std::vector<int>& loop)
{
  const std::size_t n = loop.size();
  std::vector<double> t(n, 0.);
  double length = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    t[i] = length;
    length += (mean.row(loop[(i + 1) % n]) - mean.row(loop[i])).norm();
  }
  if(!(length > 0.)) throw Input_error(part_graph_source, "docking site", "its boundary loop has zero length");
  for(double& x : t) x /= length;
  return t;
}

double fraction(double x) { return x - std::floor(x); }

// The point at parameter `t` of the closed loop (parameters `params`).
Eigen::RowVector3d loop_point(const Point_matrix& mean, const std::vector<int>& loop, const std::vector<double>& params,
                              double t)
{
  t = fraction(t);
  const std::size_t n = loop.size();
  std::size_t i = static_cast<std::size_t>(std::upper_bound(params.begin(), params.end(), t) - params.begin());
  i = i == 0 ? n - 1 : i - 1;
  const double t0 = params[i], t1 = i + 1 < n ? params[i + 1] : 1.;
  const double w = t1 > t0 ? std::min(1., std::max(0., (t - t0) / (t1 - t0))) : 0.;
  return (1. - w) * mean.row(loop[i]) + w * mean.row(loop[(i + 1) % n]);
}

// Loops of the same size: a_i ~ b_(shift - i) (opposite directions), the
// shift whose rigid fit of the means is best.
std::vector<std::pair<int, int>> one_to_one_seam(const Point_matrix& mean_a, const std::vector<int>& la,
                                                 const Point_matrix& mean_b, const std::vector<int>& lb)
{
  const int n = static_cast<int>(la.size());
  Point_matrix pa(n, 3), pb(n, 3);
  for(int i = 0; i < n; ++i) pa.row(i) = mean_a.row(la[i]);
  double best = std::numeric_limits<double>::infinity();
  int best_shift = 0;
  for(int shift = 0; shift < n; ++shift)
  {
    for(int i = 0; i < n; ++i) pb.row(i) = mean_b.row(lb[((shift - i) % n + n) % n]);
    const double r = (fit_rigid_motion(pb, pa).apply(pb) - pa).squaredNorm();
    if(r < best)
    {
      best = r;
      best_shift = shift;
    }
  }
  std::vector<std::pair<int, int>> seam;
  for(int i = 0; i < n; ++i) seam.push_back({la[i], lb[((best_shift - i) % n + n) % n]});
  std::sort(seam.begin(), seam.end());
  return seam;
}

// Loops of different sizes: both parametrized by arc length on their means,
// the second traversed backwards (a manifold gluing); among the offsets that
// make a vertex of one meet a vertex of the other, the one whose rigid fit
// of the two parametrized loops (sampled alike) is best. The merged loop is
// the union of both loops' vertices ordered by parameter; vertices closer
// than a fifth of the finer spacing are identified (`rule.seam`).
void merged_seam(const Point_matrix& mean_a, const std::vector<int>& la, const Point_matrix& mean_b,
                 const std::vector<int>& lb, Docking_rule& rule)
{
  const int n = static_cast<int>(la.size()), m = static_cast<int>(lb.size());
  const std::vector<double> ta = arc_parameters(mean_a, la), tb = arc_parameters(mean_b, lb);
  const int samples = 2 * (n + m);
  Point_matrix pa(samples, 3), pb(samples, 3);
  for(int k = 0; k < samples; ++k) pa.row(k) = loop_point(mean_a, la, ta, double(k) / samples);
  double best = std::numeric_limits<double>::infinity(), offset = 0.;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double o = fraction(ta[i] + tb[j]); // a_i meets b_j
      for(int k = 0; k < samples; ++k) pb.row(k) = loop_point(mean_b, lb, tb, o - double(k) / samples);
      const double r = (fit_rigid_motion(pb, pa).apply(pb) - pa).squaredNorm();
      if(r < best * (1. - 1e-9))
      {
        best = r;
        offset = o;
      }
    }
  double spacing = 1.;
  for(int i = 0; i < n; ++i) spacing = std::min(spacing, (i + 1 < n ? ta[i + 1] : 1.) - ta[i]);
  for(int j = 0; j < m; ++j) spacing = std::min(spacing, (j + 1 < m ? tb[j + 1] : 1.) - tb[j]);
  const double tolerance = 0.2 * spacing;
  struct Entry
  {
    double t = 0.;            // parameter along loop a
    int a = -1, b = -1;       // loop positions
    double tb = 0.;           // b's own parameter in a's frame
  };
  std::vector<Entry> entries;
  for(int i = 0; i < n; ++i) entries.push_back({ta[i], i, -1, 0.});
  for(int j = 0; j < m; ++j)
  {
    const double s = fraction(offset - tb[j]);
    int nearest = -1;
    double distance = tolerance;
    for(int i = 0; i < n; ++i)
    {
      const double d = std::min(fraction(s - ta[i]), fraction(ta[i] - s));
      if(d < distance && entries[i].b < 0)
      {
        distance = d;
        nearest = i;
      }
    }
    if(nearest >= 0)
    {
      entries[nearest].b = j;
      entries[nearest].tb = s;
    }
    else
      entries.push_back({s, -1, j, s});
  }
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) { return x.t < y.t; });
  const int size = static_cast<int>(entries.size());
  rule.seam.clear();
  rule.merged_seam.clear();
  for(int k = 0; k < size; ++k)
  {
    const Entry& e = entries[k];
    Seam_vertex v;
    v.parameter = e.t;
    v.local = {{e.a >= 0 ? la[e.a] : -1, e.b >= 0 ? lb[e.b] : -1}};
    if(e.a >= 0 && e.b >= 0) rule.seam.push_back({la[e.a], lb[e.b]});
    if(e.a < 0)
    {
      // Between the previous and the next vertex of loop a (its direction).
      int p = k, q = k;
      do p = (p + size - 1) % size; while(entries[p].a < 0);
      do q = (q + 1) % size; while(entries[q].a < 0);
      v.from[0] = la[entries[p].a];
      v.to[0] = la[entries[q].a];
      v.weight[0] = fraction(e.t - entries[p].t) / fraction(entries[q].t - entries[p].t);
    }
    if(e.b < 0)
    {
      // Loop b runs backwards: from the next vertex (larger parameter) to the previous one.
      int p = k, q = k;
      do p = (p + 1) % size; while(entries[p].b < 0);
      do q = (q + size - 1) % size; while(entries[q].b < 0);
      v.from[1] = lb[entries[p].b];
      v.to[1] = lb[entries[q].b];
      v.weight[1] = fraction(entries[p].tb - e.t) / fraction(entries[p].tb - entries[q].tb);
    }
    rule.merged_seam.push_back(v);
  }
  std::sort(rule.seam.begin(), rule.seam.end());
}

// Pair points, edges and the pair space (no modes: the second type's mean
// docked on the first's by the seam) of a derived rule whose seam is set.
void finish_derived_rule(const Morphable_part_model& model, Docking_rule& rule)
{
  const Part_type& type_a = model.types[rule.first.type];
  const Part_type& type_b = model.types[rule.second.type];
  const Docking_site& A = type_a.sites[rule.first.site];
  const Docking_site& B = type_b.sites[rule.second.site];
  const Point_matrix& mean_a = type_a.space.mean;
  const Point_matrix& mean_b = type_b.space.mean;

  // Pair points: within the docking radius of the seam on either part.
  const double radius = model.parameters.docking_radius;
  const std::vector<double> da = internal::edge_graph_distances(mean_a, type_a.edges, A.vertices);
  const std::vector<double> db = internal::edge_graph_distances(mean_b, type_b.edges, B.vertices);
  std::map<int, int> seam_of_second;
  for(const auto& [l0, l1] : rule.seam) seam_of_second[l1] = l0;
  std::map<int, int> index0, index1;
  for(int v = 0; v < type_a.number_of_vertices; ++v)
    if(da[v] <= radius)
    {
      index0[v] = static_cast<int>(rule.points.size());
      rule.points.push_back({0, v});
    }
  for(int v = 0; v < type_b.number_of_vertices; ++v)
  {
    if(!(db[v] <= radius)) continue;
    const auto it = seam_of_second.find(v);
    if(it != seam_of_second.end())
      index1[v] = index0.at(it->second);
    else
    {
      index1[v] = static_cast<int>(rule.points.size());
      rule.points.push_back({1, v});
    }
  }
  std::map<std::pair<int, int>, bool> edge_is_virtual;
  for(int s = 0; s < 2; ++s)
  {
    const std::map<int, int>* index = s == 0 ? &index0 : &index1;
    for(const Cluster_edge& e : (s == 0 ? type_a : type_b).edges)
    {
      const auto a = index->find(e.source), b = index->find(e.target);
      if(a == index->end() || b == index->end()) continue;
      const std::pair<int, int> key(std::min(a->second, b->second), std::max(a->second, b->second));
      const auto it = edge_is_virtual.find(key);
      if(it == edge_is_virtual.end()) edge_is_virtual[key] = e.is_virtual;
      else it->second = it->second && e.is_virtual;
    }
  }
  for(const auto& [key, is_virtual] : edge_is_virtual) rule.edges.push_back({key.first, key.second, is_virtual});

  // The pair's mean: the second part docked on the first by the seam.
  Point_matrix from, to;
  internal::seam_points(rule, rule.merged_seam, mean_a, mean_b, to, from);
  const Point_matrix second = fit_rigid_motion(from, to).apply(mean_b);
  Point_matrix instance(rule.points.size(), 3);
  for(std::size_t k = 0; k < rule.points.size(); ++k)
    instance.row(k) = (rule.points[k].side == 0 ? mean_a : second).row(rule.points[k].local);
  rule.space = learn_shape_space({instance});
}

} // namespace

Docking_rule derive_docking_rule(const Morphable_part_model& model, const Site_ref& a, const Site_ref& b)
{
  const Part_type& type_a = checked_type(model, a.type);
  const Part_type& type_b = checked_type(model, b.type);
  for(const auto& [type, site] : {std::make_pair(&type_a, a), std::make_pair(&type_b, b)})
  {
    if(site.site < 0 || site.site >= int(type->sites.size()))
      throw Input_error(part_graph_source, "part type " + quoted(type->name),
                        "has no docking site " + std::to_string(site.site));
    if(type->sites[site.site].kind != Docking_kind::boundary)
      throw Input_error(part_graph_source, site_text(model, site), "is not a boundary site (a derived rule docks two boundary loops)");
  }
  const std::vector<int> la = boundary_loop(type_a, type_a.sites[a.site], site_text(model, a));
  const std::vector<int> lb = boundary_loop(type_b, type_b.sites[b.site], site_text(model, b));
  Docking_rule rule;
  rule.first = a;
  rule.second = b;
  rule.kind = Docking_kind::boundary;
  if(la.size() == lb.size()) rule.seam = one_to_one_seam(type_a.space.mean, la, type_b.space.mean, lb);
  else merged_seam(type_a.space.mean, la, type_b.space.mean, lb, rule);
  finish_derived_rule(model, rule);
  return rule;
}

int add_derived_rule(Morphable_part_model& model, const Site_ref& a, const Site_ref& b)
{
  const std::vector<int> existing = model.grammar().rules_between(a, b);
  if(!existing.empty()) return existing.front();
  Docking_rule rule = derive_docking_rule(model, a, b);
  model.rules.push_back(std::move(rule));
  model.update_grammar();
  return static_cast<int>(model.rules.size()) - 1;
}

Docking_rule derive_repetition_rule(const Morphable_part_model& model, int type_index, int site_a, int site_b)
{
  const Part_type& type = checked_type(model, type_index);
  const std::string element = "part type " + quoted(type.name);
  if(site_a == site_b || site_a < 0 || site_b < 0 || site_a >= int(type.sites.size()) ||
     site_b >= int(type.sites.size()))
    throw Input_error(part_graph_source, element, "a repetition rule needs two distinct sites of the type");
  if(site_b < site_a) std::swap(site_a, site_b);
  if(type.sites[site_a].kind != Docking_kind::boundary || type.sites[site_b].kind != Docking_kind::boundary)
    throw Input_error(part_graph_source, element, "a repetition rule docks two boundary sites");
  return derive_docking_rule(model, {type_index, site_a}, {type_index, site_b});
}

namespace {

// Appends the derived rule of each pair that no rule docks yet, skipping
// pairs whose sites are not two simple loops, and rebuilds the grammar
// once: the pairs are distinct, so no added rule allows a later pair.
std::vector<int> add_derived_rules(Morphable_part_model& model, const std::vector<std::pair<Site_ref, Site_ref>>& pairs)
{
  std::vector<int> added;
  const Shape_grammar& grammar = model.grammar();
  for(const auto& [a, b] : pairs)
  {
    if(grammar.allows(a, b)) continue;
    Docking_rule rule;
    try {
      rule = derive_docking_rule(model, a, b);
    } catch(const Input_error&) {
      continue;
    }
    added.push_back(static_cast<int>(model.rules.size()));
    model.rules.push_back(std::move(rule));
  }
  if(!added.empty()) model.update_grammar();
  return added;
}

} // namespace

std::vector<int> add_repetition_rules(Morphable_part_model& model)
{
  // Each type with two boundary sites docked to a copy of itself.
  std::vector<std::pair<Site_ref, Site_ref>> repetitions;
  for(int t = 0; t < int(model.types.size()); ++t)
  {
    const Part_type& type = model.types[t];
    if(type.sites.size() == 2 && type.sites[0].kind == Docking_kind::boundary &&
       type.sites[1].kind == Docking_kind::boundary)
      repetitions.push_back({{t, 0}, {t, 1}});
  }
  return add_derived_rules(model, repetitions);
}

std::vector<int> add_bridging_rules(Morphable_part_model& model)
{
  // The two sites each segment of a training example hangs between: what
  // its neighbours dock at once it is removed.
  std::set<std::pair<Site_ref, Site_ref>> bridges;
  for(const Training_example& example : model.examples)
  {
    std::vector<std::vector<Site_ref>> neighbour_sites(example.graph.nodes.size());
    std::vector<int> dockings(example.graph.nodes.size(), 0);
    for(const Part_edge& e : example.graph.edges)
    {
      const Docking_rule& r = model.rules[std::size_t(e.rule)];
      ++dockings[std::size_t(e.first)];
      ++dockings[std::size_t(e.second)];
      if(r.kind != Docking_kind::boundary) continue;
      neighbour_sites[std::size_t(e.first)].push_back(r.second);
      neighbour_sites[std::size_t(e.second)].push_back(r.first);
    }
    for(std::size_t n = 0; n < neighbour_sites.size(); ++n)
    {
      const std::vector<Site_ref>& sites = neighbour_sites[n];
      if(dockings[n] == 2 && sites.size() == 2 && !(sites[0] == sites[1]))
        bridges.insert({std::min(sites[0], sites[1]), std::max(sites[0], sites[1])});
    }
  }
  return add_derived_rules(model, {bridges.begin(), bridges.end()});
}

} // namespace MPM
} // namespace CGAL
