// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Merged seams of a training mesh whose parts were rebuilt by dense
// correspondence. Every part's border vertex is located on the original
// seam polylines, which give all parts one common parameter; the union of
// the points, split into each part's border edges, is the merged seam.
#include <CGAL/MPM/internal/Seam_stitching.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Edge_key = std::pair<int, int>;

Edge_key edge_key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// A point of the seam graph: an original vertex `a` (b < 0) or the point at
// `t` from `a` on the edge {a, b}, a < b.
struct Location
{
  int a = -1, b = -1;
  double t = 0.;
  friend bool operator<(const Location& x, const Location& y) { return std::tie(x.a, x.b, x.t) < std::tie(y.a, y.b, y.t); }
};

// A closed border chain of one label's faces, oriented like them: edge k
// runs from vertices[k] to vertices[k + 1], s[k] is the arc length at vertices[k].
struct Seam_loop
{
  int label = -1;
  std::vector<int> vertices;
  std::vector<double> s;
  double length = 0.;
  std::map<int, int> index_of_vertex;
  std::map<Edge_key, int> index_of_edge;

  double wrap(double d) const { return d - length * std::floor(d / length); }
};

// Chains directed border half-edges (a -> b) into closed loops. Where a
// label's border passes a vertex twice (a ring cut down to nothing at one
// vertex, so that its two loops touch), each visit closes a loop of its
// own: every loop is simple, whichever way the chain turned there, so the
// original mesh and a kept part chained in another order get the same loops.
std::vector<std::vector<int>> chain_loops(std::multimap<int, int> out)
{
  std::vector<std::vector<int>> loops;
  while(!out.empty())
  {
    auto it = out.begin();
    const int start = it->first;
    std::vector<int> path;
    std::map<int, std::size_t> position;
    while(it != out.end())
    {
      const int v = it->first;
      if(const auto seen = position.find(v); seen != position.end())
      {
        const std::size_t first = seen->second; // `seen` goes with the erasures below
        loops.emplace_back(path.begin() + std::ptrdiff_t(first), path.end());
        for(std::size_t k = first; k < path.size(); ++k) position.erase(path[k]);
        path.resize(first);
      }
      position[v] = path.size();
      path.push_back(v);
      const int next = it->second;
      out.erase(it);
      if(next == start) break;
      it = out.find(next);
    }
    loops.push_back(std::move(path));
  }
  return loops;
}

std::vector<Seam_loop> label_loops(const Labeled_mesh& m)
{
  const long long n = m.mesh.number_of_vertices();
  std::unordered_map<long long, int> face_of;
  for(int f = 0; f < m.mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k) face_of[m.mesh.triangles[f][k] * n + m.mesh.triangles[f][(k + 1) % 3]] = f;
  std::map<int, std::multimap<int, int>> out;
  for(int f = 0; f < m.mesh.number_of_faces(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const int a = m.mesh.triangles[f][k], b = m.mesh.triangles[f][(k + 1) % 3];
      const auto twin = face_of.find(b * n + a);
      if(twin == face_of.end() || m.face_labels[twin->second] != m.face_labels[f]) out[m.face_labels[f]].insert({a, b});
    }
  std::vector<Seam_loop> loops;
  for(const auto& [label, half_edges] : out)
    for(std::vector<int>& chain : chain_loops(half_edges))
    {
      Seam_loop l;
      l.label = label;
      l.vertices = std::move(chain);
      const std::size_t k_max = l.vertices.size();
      for(std::size_t k = 0; k < k_max; ++k)
      {
        const int a = l.vertices[k], b = l.vertices[(k + 1) % k_max];
        l.s.push_back(l.length);
        l.length += (m.mesh.points.row(a) - m.mesh.points.row(b)).norm();
        l.index_of_vertex.insert({a, int(k)});
        l.index_of_edge[edge_key(a, b)] = int(k);
      }
      if(l.length > 0.) loops.push_back(std::move(l));
    }
  return loops;
}

// Parameter of `x` on `loop`, or -1 when it is not on it.
double parameter_on(const Seam_loop& loop, const Location& x, const Point_matrix& points)
{
  if(x.b < 0)
  {
    const auto it = loop.index_of_vertex.find(x.a);
    return it == loop.index_of_vertex.end() ? -1. : loop.s[it->second];
  }
  const auto it = loop.index_of_edge.find({x.a, x.b});
  if(it == loop.index_of_edge.end()) return -1.;
  const int k = it->second;
  const double t = loop.vertices[k] == x.a ? x.t : 1. - x.t;
  return loop.s[k] + t * (points.row(x.a) - points.row(x.b)).norm();
}

// The nearest point of `loop` to `p`, and its squared distance.
std::pair<Location, double> project(const Seam_loop& loop, const Eigen::RowVector3d& p, const Point_matrix& points)
{
  std::pair<Location, double> best{Location(), std::numeric_limits<double>::infinity()};
  const std::size_t m = loop.vertices.size();
  for(std::size_t k = 0; k < m; ++k)
  {
    const int a = loop.vertices[k], b = loop.vertices[(k + 1) % m];
    const Eigen::RowVector3d d = points.row(b) - points.row(a);
    const double t = d.squaredNorm() > 0. ? std::clamp((p - points.row(a)).dot(d) / d.squaredNorm(), 0., 1.) : 0.;
    const double dist = (points.row(a) + t * d - p).squaredNorm();
    if(dist < best.second) best = {a < b ? Location{a, b, t} : Location{b, a, 1. - t}, dist};
  }
  Location& x = best.first;
  if(x.t < 1e-9) x = {x.a, -1, 0.};
  else if(x.t > 1. - 1e-9) x = {x.b, -1, 0.};
  return best;
}

// The point of `loop` at arc length `parameter` (taken modulo its length).
Location location_at(const Seam_loop& loop, double parameter, const Point_matrix& points)
{
  const double p = loop.wrap(parameter);
  const std::size_t k = std::size_t(std::upper_bound(loop.s.begin(), loop.s.end(), p) - loop.s.begin()) - 1;
  const int a = loop.vertices[k], b = loop.vertices[(k + 1) % loop.vertices.size()];
  const double length = (points.row(a) - points.row(b)).norm();
  const double t = length > 0. ? std::clamp((p - loop.s[k]) / length, 0., 1.) : 0.;
  if(t < 1e-9) return {a, -1, 0.};
  if(t > 1. - 1e-9) return {b, -1, 0.};
  return a < b ? Location{a, b, t} : Location{b, a, 1. - t};
}

// A rebuilt part's border loop located on its original loop goes along it
// one way; where two of its vertices lie almost on one spot, their
// projections can come in the other order, and the merged seam then
// crossed itself (a quad left open between a corresponded leg segment and
// its neighbour on a subdivided ant). Each such vertex is moved along the
// loop to just past the one before it.
void make_monotone(const Seam_loop& loop, const Point_matrix& points, std::vector<double>& parameter,
                   std::vector<Location>& at)
{
  const std::size_t m = parameter.size();
  if(m < 3) return;
  const auto step = [&](double d) { // signed, in (-length / 2, length / 2]
    d = loop.wrap(d);
    return d > 0.5 * loop.length ? d - loop.length : d;
  };
  double turn = 0.;
  for(std::size_t k = 0; k < m; ++k) turn += step(parameter[(k + 1) % m] - parameter[k]);
  const double direction = turn >= 0. ? 1. : -1., gap = 1e-6 * loop.length;
  for(std::size_t k = 1; k < m; ++k)
  {
    if(direction * step(parameter[k] - parameter[k - 1]) > 0.) continue;
    parameter[k] = loop.wrap(parameter[k - 1] + direction * gap);
    at[k] = location_at(loop, parameter[k], points);
  }
}

// One point of the union: an own border vertex of a part (`label`,
// `local`) or a junction of three or more parts (label -1).
struct Seam_point
{
  int label = -1, local = -1;
  Location at;
  Eigen::RowVector3d position;
};

// What a part has at a class of identified points: its own vertex, or a
// vertex inserted into its border edge from -> to at `weight`; and where
// it is on each of the part's border loops through it (two where the
// part's border touches itself there). A rebuilt part whose original
// border touched itself at a junction, but whose template's loops do not,
// has a side there on each loop: each seam neighbour is stitched to the
// loop it borders (octopus_124 subdivided was left open at two such
// junctions of a root, a chain segment and a tip).
struct Part_side
{
  int local = -1, from = -1, to = -1;
  double weight = 0.;
  std::map<int, double> parameter; // border loop -> parameter on its original loop, in [0, 1)
};

// A part's own border loops (local ids, oriented like its faces) and the
// original loop each one lies on with the parameter of each vertex.
struct Part_border
{
  std::vector<std::vector<int>> loops;
  std::vector<int> on_loop;
  std::vector<std::vector<int>> point; // per loop and vertex: its Seam_point
  std::vector<std::vector<double>> parameter;
  double mean_edge = 0.;
};

class Stitcher
{
public:
  Stitcher(const Labeled_mesh& original, const Labeled_mesh& rebuilt, const std::vector<int>& original_vertex,
           const std::map<int, std::vector<int>>& part_vertices, const std::set<int>& detached)
    : original_(original), rebuilt_(rebuilt), original_vertex_(original_vertex), part_vertices_(part_vertices),
      detached_(detached), loops_(label_loops(original))
  {
    for(std::size_t l = 0; l < loops_.size(); ++l) loops_of_label_[loops_[l].label].push_back(int(l));
  }

  std::vector<Stitched_seam> run()
  {
    for(const auto& [label, vertices] : part_vertices_) locate_part(label, vertices);
    add_junctions();
    classes_.resize(points_.size());
    for(std::size_t i = 0; i < points_.size(); ++i) classes_[i] = int(i);
    identify_equal_locations();
    merge_close_points();
    for(auto& [label, border] : borders_) split_border(label, border);
    return seams();
  }

private:
  double sl_length(int loop) const { return loop >= 0 ? loops_[loop].length : 1.; }

  int find(int i) { return classes_[i] == i ? i : classes_[i] = find(classes_[i]); }

  // A kept part's border is chained over its original vertex ids, so that
  // where it passes a vertex twice (two seams touching) it takes the same
  // turns as the original loop it lies on.
  Part_border border_of(int label, const std::vector<int>& vertices) const
  {
    const bool rebuilt = detached_.count(label) > 0;
    std::unordered_map<int, int> key_of_vertex, local_of_key;
    for(std::size_t i = 0; i < vertices.size(); ++i)
    {
      const int key = rebuilt ? int(i) : original_vertex_[vertices[i]];
      key_of_vertex[vertices[i]] = key;
      local_of_key[key] = int(i);
    }
    std::set<Edge_key> half_edges;
    for(int f = 0; f < rebuilt_.mesh.number_of_faces(); ++f)
      if(rebuilt_.face_labels[f] == label)
        for(int k = 0; k < 3; ++k)
          half_edges.insert({key_of_vertex.at(rebuilt_.mesh.triangles[f][k]),
                             key_of_vertex.at(rebuilt_.mesh.triangles[f][(k + 1) % 3])});
    std::multimap<int, int> out;
    for(const auto& [a, b] : half_edges)
      if(!half_edges.count({b, a})) out.insert({a, b});
    Part_border border;
    border.loops = chain_loops(out);
    for(std::vector<int>& loop : border.loops)
      for(int& x : loop) x = local_of_key.at(x);
    double sum = 0.;
    for(const auto& [a, b] : out)
      sum += (rebuilt_.mesh.points.row(vertices[local_of_key.at(a)]) - rebuilt_.mesh.points.row(vertices[local_of_key.at(b)])).norm();
    border.mean_edge = out.empty() ? 0. : sum / double(out.size());
    return border;
  }

  // The original loop of `label` a part's border loop lies on: for a kept
  // part the one through its vertices, for a rebuilt part the nearest to most.
  int choose_loop(int label, const std::vector<Eigen::RowVector3d>& p, const std::vector<int>& original) const
  {
    const auto it = loops_of_label_.find(label);
    if(it == loops_of_label_.end()) return -1;
    std::map<int, int> votes;
    for(std::size_t k = 0; k < p.size(); ++k)
    {
      int best = -1;
      double d = std::numeric_limits<double>::infinity();
      for(int l : it->second)
      {
        if(original[k] >= 0)
        {
          if(loops_[l].index_of_vertex.count(original[k])) best = l;
          continue;
        }
        const double dl = project(loops_[l], p[k], original_.mesh.points).second;
        if(dl < d) { d = dl; best = l; }
      }
      if(best >= 0) ++votes[best];
    }
    int chosen = -1;
    for(const auto& [l, count] : votes)
      if(chosen < 0 || count > votes[chosen]) chosen = l;
    return chosen;
  }

  void locate_part(int label, const std::vector<int>& vertices)
  {
    Part_border border = border_of(label, vertices);
    const bool rebuilt = detached_.count(label) > 0;
    for(const std::vector<int>& loop : border.loops)
    {
      std::vector<Eigen::RowVector3d> p;
      std::vector<int> original;
      for(int x : loop)
      {
        p.push_back(rebuilt_.mesh.points.row(vertices[x]));
        original.push_back(rebuilt ? -1 : original_vertex_[vertices[x]]);
      }
      const int l = choose_loop(label, p, original);
      border.on_loop.push_back(l);
      border.point.emplace_back();
      border.parameter.emplace_back();
      std::vector<Location> at;
      std::vector<double> parameter;
      for(std::size_t k = 0; k < loop.size(); ++k)
      {
        at.push_back(original[k] >= 0 ? Location{original[k], -1, 0.}
                     : l >= 0         ? project(loops_[l], p[k], original_.mesh.points).first
                                      : Location());
        parameter.push_back(l >= 0 ? parameter_on(loops_[l], at.back(), original_.mesh.points) : -1.);
      }
      if(rebuilt && l >= 0) make_monotone(loops_[l], original_.mesh.points, parameter, at);
      for(std::size_t k = 0; k < loop.size(); ++k)
      {
        border.point.back().push_back(int(points_.size()));
        border.parameter.back().push_back(parameter[k]);
        points_.push_back({label, loop[k], at[k], p[k]});
      }
    }
    borders_[label] = std::move(border);
  }

  void add_junctions()
  {
    std::vector<std::set<int>> labels(original_.mesh.number_of_vertices());
    for(int f = 0; f < original_.mesh.number_of_faces(); ++f)
      for(int v : original_.mesh.triangles[f]) labels[v].insert(original_.face_labels[f]);
    for(int v = 0; v < original_.mesh.number_of_vertices(); ++v)
      if(labels[v].size() >= 3)
        points_.push_back({-1, -1, Location{v, -1, 0.}, original_.mesh.points.row(v)});
  }

  void unite(int i, int j) { classes_[find(i)] = find(j); }

  void identify_equal_locations()
  {
    std::map<Location, int> first;
    for(std::size_t i = 0; i < points_.size(); ++i)
    {
      if(points_[i].at.a < 0) continue;
      const auto [it, added] = first.insert({points_[i].at, int(i)});
      // A vertex where a part's border passes twice (two seams touching) is
      // one point; two own vertices of one part on one point (a degenerate
      // template border) stay apart.
      const Seam_point& other = points_[it->second];
      if(!added && (other.label != points_[i].label || other.local == points_[i].local)) unite(int(i), it->second);
    }
  }

  // Points on each original loop, by parameter.
  std::vector<std::vector<std::pair<double, int>>> points_on_loops() const
  {
    std::vector<std::vector<std::pair<double, int>>> on(loops_.size());
    std::map<int, std::vector<int>> loops_of_vertex;
    std::map<Edge_key, std::vector<int>> loops_of_edge;
    for(std::size_t l = 0; l < loops_.size(); ++l)
    {
      for(const auto& [v, k] : loops_[l].index_of_vertex) loops_of_vertex[v].push_back(int(l));
      for(const auto& [e, k] : loops_[l].index_of_edge) loops_of_edge[e].push_back(int(l));
    }
    for(std::size_t i = 0; i < points_.size(); ++i)
    {
      const Location& x = points_[i].at;
      if(x.a < 0) continue;
      const auto& candidates = x.b < 0 ? loops_of_vertex[x.a] : loops_of_edge[{x.a, x.b}];
      for(int l : candidates) on[l].push_back({parameter_on(loops_[l], x, original_.mesh.points), int(i)});
    }
    for(auto& list : on) std::sort(list.begin(), list.end());
    return on;
  }

  // Neighbouring points of different parts closer than half the finer
  // border edge become one vertex, so that no sliver fan joins them (a
  // fifth left twice as many flipped seam faces after symmetrize on the
  // hands); never two vertices of one part, never two original vertices.
  void merge_close_points()
  {
    const auto on = points_on_loops();
    std::vector<std::set<int>> labels(points_.size());
    std::vector<bool> original(points_.size(), false);
    for(std::size_t i = 0; i < points_.size(); ++i)
    {
      if(points_[i].label >= 0) labels[i].insert(points_[i].label);
      original[i] = points_[i].at.b < 0;
    }
    for(std::size_t i = 0; i < points_.size(); ++i)
      if(find(int(i)) != int(i))
      {
        const int r = find(int(i));
        labels[r].insert(labels[i].begin(), labels[i].end());
        original[r] = original[r] || original[i];
      }
    for(const auto& list : on)
      for(std::size_t k = 0; list.size() > 1 && k < list.size(); ++k)
      {
        const int i = list[k].second, j = list[(k + 1) % list.size()].second;
        const int ri = find(i), rj = find(j);
        if(ri == rj || (original[ri] && original[rj])) continue;
        if(std::any_of(labels[ri].begin(), labels[ri].end(), [&](int l) { return labels[rj].count(l) > 0; })) continue;
        double tolerance = std::numeric_limits<double>::infinity();
        for(int p : {i, j})
          if(points_[p].label >= 0) tolerance = std::min(tolerance, 0.5 * borders_.at(points_[p].label).mean_edge);
        if(!((points_[i].position - points_[j].position).norm() < tolerance)) continue;
        classes_[ri] = rj;
        labels[rj].insert(labels[ri].begin(), labels[ri].end());
        original[rj] = original[rj] || original[ri];
      }
  }

  // Whether the part has a side at class `c` on a border loop that lies on
  // original loop `l`.
  bool has_side_on(int label, int c, int l) const
  {
    const auto sides = sides_.at(label).find(c);
    if(sides == sides_.at(label).end()) return false;
    const Part_border& border = borders_.at(label);
    for(const Part_side& side : sides->second)
      for(const auto& on : side.parameter)
        if(border.on_loop[std::size_t(on.first)] == l) return true;
    return false;
  }

  // The part's side at class `c` on original loop `l`; its own vertex there
  // when `l` is -1 or none is on `l`.
  const Part_side& side_on(int label, int c, int l) const
  {
    const std::vector<Part_side>& sides = sides_.at(label).at(c);
    const Part_border& border = borders_.at(label);
    for(const Part_side& side : sides)
      for(const auto& on : side.parameter)
        if(l >= 0 && border.on_loop[std::size_t(on.first)] == l) return side;
    const auto own = std::find_if(sides.begin(), sides.end(), [](const Part_side& s) { return s.local >= 0; });
    return own != sides.end() ? *own : sides.front();
  }

  // Each part's side at every class on its border: its own vertices, and
  // every other class on its original loop between two of its own vertices.
  void split_border(int label, const Part_border& border)
  {
    std::map<int, std::vector<Part_side>>& sides = sides_[label];
    if(on_loops_.empty()) on_loops_ = points_on_loops();
    // Own vertices of every loop first: a point of one of the part's loops
    // is inserted into another only where that one lies on another
    // original loop (the junction where the original border touched
    // itself).
    for(std::size_t b = 0; b < border.loops.size(); ++b)
      for(std::size_t k = 0; k < border.loops[b].size(); ++k)
      {
        std::vector<Part_side>& at = sides[find(border.point[b][k])];
        auto side = std::find_if(at.begin(), at.end(), [&](const Part_side& s) { return s.local == border.loops[b][k]; });
        if(side == at.end()) side = at.insert(at.end(), {border.loops[b][k], -1, -1, 0., {}});
        side->parameter.insert({int(b), border.parameter[b][k] / sl_length(border.on_loop[b])});
      }
    for(std::size_t b = 0; b < border.loops.size(); ++b)
    {
      const std::vector<int>& loop = border.loops[b];
      const int l = border.on_loop[b];
      if(l < 0) continue;
      const Seam_loop& sl = loops_[l];
      double turn = 0.; // along the original loop or against it
      for(std::size_t k = 0; k < loop.size(); ++k)
      {
        const double d = sl.wrap(border.parameter[b][(k + 1) % loop.size()] - border.parameter[b][k]);
        turn += d < 0.5 * sl.length ? d : d - sl.length;
      }
      const double direction = turn >= 0. ? 1. : -1.;
      for(std::size_t k = 0; k < loop.size(); ++k)
      {
        const std::size_t next = (k + 1) % loop.size();
        const double start = border.parameter[b][k];
        const double span = sl.wrap(direction * (border.parameter[b][next] - start));
        if(!(span > 0.)) continue;
        for(const auto& [parameter, i] : on_loops_[l])
        {
          const int c = find(i);
          const double d = sl.wrap(direction * (parameter - start));
          if(!(d > 0. && d < span) || has_side_on(label, c, l)) continue;
          sides[c].push_back({-1, loop[k], loop[next], d / span, {{int(b), parameter / sl.length}}});
        }
      }
    }
  }

  // The original loop of `label` through its border edge `e`.
  int loop_through(int label, const Edge_key& e) const
  {
    for(int l : loops_of_label_.at(label))
      if(loops_[std::size_t(l)].index_of_edge.count(e)) return l;
    return -1;
  }

  // Per pair of labels sharing an original seam edge, one of them rebuilt:
  // the classes on those edges (and their end points) with both sides.
  std::vector<Stitched_seam> seams()
  {
    std::map<Edge_key, std::vector<int>> points_of_edge;
    std::map<int, std::vector<int>> points_of_vertex;
    for(std::size_t i = 0; i < points_.size(); ++i)
    {
      const Location& x = points_[i].at;
      if(x.a < 0) continue;
      if(x.b < 0) points_of_vertex[x.a].push_back(int(i));
      else points_of_edge[{x.a, x.b}].push_back(int(i));
    }
    std::map<Edge_key, std::set<int>> labels_of_edge;
    for(int f = 0; f < original_.mesh.number_of_faces(); ++f)
      for(int k = 0; k < 3; ++k)
        labels_of_edge[edge_key(original_.mesh.triangles[f][k], original_.mesh.triangles[f][(k + 1) % 3])].insert(
          original_.face_labels[f]);
    // Per pair of labels, per class: the original loops of both labels
    // through the seam edges it lies on.
    std::map<Edge_key, std::map<int, std::set<Edge_key>>> classes_of_pair;
    for(const auto& [e, labels] : labels_of_edge)
    {
      if(labels.size() != 2) continue;
      const int p = *labels.begin(), q = *labels.rbegin();
      if(!detached_.count(p) && !detached_.count(q)) continue;
      const Edge_key on{loop_through(p, e), loop_through(q, e)};
      std::map<int, std::set<Edge_key>>& classes = classes_of_pair[{p, q}];
      for(int i : points_of_edge[e]) classes[find(i)].insert(on);
      for(int v : {e.first, e.second})
        for(int i : points_of_vertex[v]) classes[find(i)].insert(on);
    }
    std::vector<Stitched_seam> result;
    for(const auto& [pq, classes] : classes_of_pair)
    {
      Stitched_seam seam;
      seam.label_a = pq.first;
      seam.label_b = pq.second;
      const auto& a = sides_[pq.first];
      const auto& b = sides_[pq.second];
      // Each side on the loop that borders the other part; where the seam
      // passes a class on two loops (the parts touch there twice), the own
      // vertex, so that no part is stitched to itself.
      std::vector<std::pair<const Part_side*, const Part_side*>> stitched;
      for(const auto& [c, on] : classes)
      {
        if(!a.count(c) || !b.count(c)) continue;
        const Edge_key loops = on.size() == 1 ? *on.begin() : Edge_key{-1, -1};
        stitched.push_back({&side_on(pq.first, c, loops.first), &side_on(pq.second, c, loops.second)});
      }
      // The seam is ordered along the first part's border loop that most
      // of its points lie on.
      std::map<int, int> votes;
      for(const auto& sides : stitched)
        for(const auto& [loop, parameter] : sides.first->parameter) ++votes[loop];
      const auto along = std::max_element(votes.begin(), votes.end(),
                                          [](const auto& x, const auto& y) { return x.second < y.second; });
      for(const auto& [sa, sb] : stitched)
      {
        Seam_vertex v;
        const auto on_loop = sa->parameter.find(along->first);
        v.parameter = on_loop != sa->parameter.end() ? on_loop->second : sa->parameter.begin()->second;
        int side = 0;
        for(const Part_side& s : {*sa, *sb})
        {
          v.local[side] = s.local;
          v.from[side] = s.from;
          v.to[side] = s.to;
          v.weight[side] = s.weight;
          ++side;
        }
        seam.merged.push_back(v);
      }
      if(seam.merged.size() < 2) continue;
      std::sort(seam.merged.begin(), seam.merged.end(),
                [](const Seam_vertex& x, const Seam_vertex& y) { return x.parameter < y.parameter; });
      result.push_back(std::move(seam));
    }
    return result;
  }

  const Labeled_mesh& original_;
  const Labeled_mesh& rebuilt_;
  const std::vector<int>& original_vertex_;
  const std::map<int, std::vector<int>>& part_vertices_;
  const std::set<int>& detached_;
  std::vector<Seam_loop> loops_;
  std::map<int, std::vector<int>> loops_of_label_;
  std::vector<Seam_point> points_;
  std::vector<int> classes_;
  std::map<int, Part_border> borders_;
  std::map<int, std::map<int, std::vector<Part_side>>> sides_;
  std::vector<std::vector<std::pair<double, int>>> on_loops_;
};

} // namespace

std::vector<Stitched_seam> stitch_seams(const Labeled_mesh& original, const Labeled_mesh& rebuilt,
                                        const std::vector<int>& original_vertex,
                                        const std::map<int, std::vector<int>>& part_vertices,
                                        const std::set<int>& detached)
{
  return Stitcher(original, rebuilt, original_vertex, part_vertices, detached).run();
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
