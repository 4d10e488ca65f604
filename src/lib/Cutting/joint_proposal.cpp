// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Cutting/Joint_proposal.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Joint_finder.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace CGAL {
namespace MPM {

namespace {

using Vector = Eigen::Vector3d;
using internal::Joint_finder;
using internal::Limb_axis;
using internal::Section;

// Skeleton nodes in order along a branch: from the junction (or the body's
// end) outwards.
using Chain = std::vector<int>;

// The middle value (the upper one of an even count); 0 for none.
double median(std::vector<double> values)
{
  if(values.empty()) return 0.;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
  return values[values.size() / 2];
}

// A section across a chain at one of its nodes.
struct Station
{
  int vertex = -1;
  double arc = 0.;       // distance along the chain from its first node
  double weighted = 0.;  // crease-weighted length of the best acceptable section
  double bend = 0.;      // angle (radians) between the chain's directions before and after it
};

// The skeleton with pruned nodes switched off, and per node the limb radius
// and the mesh vertices it stands for.
class Skeleton_branches
{
public:
  explicit Skeleton_branches(const Joint_finder& finder)
    : finder_(finder), skeleton_(finder.skeleton()), alive_(skeleton_.points.size(), 1),
      radius_(skeleton_.points.size(), 0.), vertices_(skeleton_.points.size())
  {
    std::vector<int> count(radius_.size(), 0);
    for(std::size_t e = 0; e < finder.skeleton_edges().size(); ++e) {
      const auto [a, b] = finder.skeleton_edges()[e];
      edge_of_[{a, b}] = e;
      for(int n : {a, b})
        if(finder.edge_radius()[e] > 0) {
          radius_[std::size_t(n)] += finder.edge_radius()[e];
          ++count[std::size_t(n)];
        }
    }
    for(std::size_t n = 0; n < radius_.size(); ++n) radius_[n] = count[n] > 0 ? radius_[n] / count[n] : 0.;
    for(std::size_t v = 0; v < skeleton_.node_of_vertex.size(); ++v)
      if(skeleton_.node_of_vertex[v] >= 0) vertices_[std::size_t(skeleton_.node_of_vertex[v])].push_back(int(v));
  }

  int degree(int n) const
  {
    int d = 0;
    for(int m : skeleton_.neighbours[std::size_t(n)]) d += alive_[std::size_t(m)];
    return d;
  }

  // From leaf `tip` inwards while nodes continue the chain, returned from
  // the far end (a junction, or the other end of a skeleton that is a path).
  Chain leaf_chain(int tip) const
  {
    Chain c{tip};
    int previous = -1, current = tip;
    for(;;) {
      int next = -1;
      for(int m : skeleton_.neighbours[std::size_t(current)])
        if(alive_[std::size_t(m)] && m != previous) next = m;
      if(next < 0) break;
      c.push_back(next);
      if(degree(next) != 2) break;
      previous = current;
      current = next;
    }
    std::reverse(c.begin(), c.end());
    return c;
  }

  double length(const Chain& c) const
  {
    double l = 0.;
    for(std::size_t i = 1; i < c.size(); ++i) l += (point(c[i]) - point(c[i - 1])).norm();
    return l;
  }

  // The limb's radius: the median over the chain's outer two thirds (its
  // first nodes lie in the body).
  double radius(const Chain& c) const
  {
    std::vector<double> r;
    for(std::size_t i = c.size() / 3; i < c.size(); ++i)
      if(radius_[std::size_t(c[i])] > 0) r.push_back(radius_[std::size_t(c[i])]);
    return median(std::move(r));
  }

  // Leaf chains ending at a junction, shorter than `factor` radii, are bumps:
  // switched off until none is left.
  void prune(double factor)
  {
    for(bool changed = true; changed;) {
      changed = false;
      for(std::size_t n = 0; n < alive_.size(); ++n) {
        if(!alive_[n] || degree(int(n)) != 1) continue;
        const Chain c = leaf_chain(int(n));
        if(degree(c.front()) < 3 || length(c) >= factor * radius(c)) continue;
        for(std::size_t i = 1; i < c.size(); ++i) alive_[std::size_t(c[i])] = 0;
        changed = true;
      }
    }
  }

  // The limbs: leaf chains ending at a junction.
  std::vector<Chain> limbs() const
  {
    std::vector<Chain> r;
    for(std::size_t n = 0; n < alive_.size(); ++n)
      if(alive_[n] && degree(int(n)) == 1) {
        Chain c = leaf_chain(int(n));
        if(degree(c.front()) >= 3) r.push_back(std::move(c));
      }
    return r;
  }

  // The branches thinner than `factor` times the body they leave (the
  // median radius of the nodes in no branch): a forearm or an abdomen as
  // thick as the body is body, cut where it narrows along the body's axis.
  std::vector<Chain> thinner_than_body(const std::vector<Chain>& branches, double factor) const
  {
    const std::vector<char> body = body_nodes(branches);
    std::vector<double> r;
    for(std::size_t n = 0; n < body.size(); ++n)
      if(body[n] && radius_[n] > 0) r.push_back(radius_[n]);
    if(r.empty()) return branches;
    const double body_radius = median(std::move(r));
    std::vector<Chain> thin;
    for(const Chain& c : branches)
      if(radius(c) <= factor * body_radius) thin.push_back(c);
    return thin;
  }

  // The longest path through the nodes in no limb (junctions included).
  Chain body_axis(const std::vector<Chain>& limbs) const
  {
    const std::vector<char> body = body_nodes(limbs);
    const auto start = std::find(body.begin(), body.end(), 1);
    if(start == body.end()) return {};
    std::vector<int> parent;
    const int far = farthest(body, int(start - body.begin()), parent);
    const int other = farthest(body, far, parent);
    Chain c;
    for(int n = other; n >= 0; n = parent[std::size_t(n)]) c.push_back(n);
    return c;
  }

  // A section across the chain at each of its nodes after the first that
  // stands for mesh vertices: through the vertex nearest the node's plane,
  // across the chain's direction there or tilted by 10 degrees, the
  // acceptable one of lowest crease-weighted length. Acceptable is judged
  // against the chain's radius: near the body, the skeleton's local radius
  // is the body's. Stations without an acceptable section are left out.
  std::vector<Station> stations(const Chain& c, double radius, double reach) const
  {
    std::vector<Station> r;
    std::vector<double> arcs{0.};
    for(std::size_t i = 1; i < c.size(); ++i) arcs.push_back(arcs.back() + (point(c[i]) - point(c[i - 1])).norm());
    for(std::size_t i = 1; i < c.size(); ++i) {
      const double arc = arcs[i];
      const auto e = edge_of_.find({std::min(c[i - 1], c[i]), std::max(c[i - 1], c[i])});
      if(e == edge_of_.end() || vertices_[std::size_t(c[i])].empty()) continue;
      Limb_axis axis = finder_.edge_axis(e->second, point(c[i]));
      if(!axis.direction.allFinite()) continue;
      axis.radius = radius;
      Station s;
      s.arc = arc;
      s.vertex = nearest_to_plane(c[i], axis.direction);
      s.weighted = std::numeric_limits<double>::infinity();
      for(const Vector& n : Joint_finder::tilted(axis.direction, {10.})) {
        const Section section = finder_.section(s.vertex, axis, 0., n, true);
        if(finder_.acceptable(section)) s.weighted = std::min(s.weighted, section.weighted);
      }
      const Vector before = point(c[i]) - point_at(c, arcs, arc - reach),
                   after = point_at(c, arcs, arc + reach) - point(c[i]);
      if(before.norm() > 0 && after.norm() > 0)
        s.bend = std::acos(std::clamp(before.normalized().dot(after.normalized()), -1., 1.));
      if(std::isfinite(s.weighted)) r.push_back(s);
    }
    return r;
  }

private:
  Vector point(int n) const { return skeleton_.points[std::size_t(n)]; }

  std::vector<char> body_nodes(const std::vector<Chain>& limbs) const
  {
    std::vector<char> body = alive_;
    for(const Chain& c : limbs)
      for(std::size_t i = 1; i < c.size(); ++i) body[std::size_t(c[i])] = 0;
    return body;
  }

  // The point of chain `c` at distance `arc` along it (clamped to its ends).
  Vector point_at(const Chain& c, const std::vector<double>& arcs, double arc) const
  {
    if(arc <= 0) return point(c.front());
    const std::size_t k = std::size_t(std::lower_bound(arcs.begin(), arcs.end(), arc) - arcs.begin());
    if(k >= arcs.size()) return point(c.back());
    const double t = (arc - arcs[k - 1]) / std::max(arcs[k] - arcs[k - 1], 1e-300);
    return (1. - t) * point(c[k - 1]) + t * point(c[k]);
  }

  int nearest_to_plane(int node, const Vector& direction) const
  {
    int best = -1;
    double distance = std::numeric_limits<double>::infinity();
    for(int v : vertices_[std::size_t(node)]) {
      const double d = std::abs((finder_.mesh().points.row(v).transpose() - point(node)).dot(direction));
      if(d < distance) {
        distance = d;
        best = v;
      }
    }
    return best;
  }

  // The node of `in` farthest along the skeleton from `from`, with the tree of paths to it.
  int farthest(const std::vector<char>& in, int from, std::vector<int>& parent) const
  {
    std::vector<double> distance(in.size(), -1.);
    parent.assign(in.size(), -1);
    std::vector<int> stack{from};
    distance[std::size_t(from)] = 0.;
    int best = from;
    while(!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      if(distance[std::size_t(n)] > distance[std::size_t(best)]) best = n;
      for(int m : skeleton_.neighbours[std::size_t(n)])
        if(in[std::size_t(m)] && distance[std::size_t(m)] < 0) {
          distance[std::size_t(m)] = distance[std::size_t(n)] + (point(m) - point(n)).norm();
          parent[std::size_t(m)] = n;
          stack.push_back(m);
        }
    }
    return best;
  }

  const Joint_finder& finder_;
  const internal::Curve_skeleton& skeleton_;
  std::vector<char> alive_;
  std::vector<double> radius_;
  std::vector<std::vector<int>> vertices_;
  std::map<std::pair<int, int>, std::size_t> edge_of_;
};

// What a joint must show at a sensitivity: a section narrower or more
// concave than its surroundings by `narrowing` (relative), or a bend of the
// limb by `bend` radians, or a mix of both. Almost nothing at 1, infinite at 0;
// at 0.5 (0.4 and 35 degrees) above the noise of the sections of scanned
// limbs and the curl of a smooth arm over a limb radius.
struct Joint_thresholds
{
  double narrowing, bend;
  explicit Joint_thresholds(double sensitivity)
  {
    const double f = sensitivity > 0 ? std::max((1. - sensitivity) / sensitivity, 1e-6)
                                     : std::numeric_limits<double>::infinity();
    narrowing = 0.4 * f;
    bend = 35. * M_PI / 180. * f;
  }
  Joint_thresholds times(double k) const
  {
    Joint_thresholds r = *this;
    r.narrowing *= k;
    r.bend *= k;
    return r;
  }
};

// Joints along a chain: stations whose score (narrowing over its threshold
// plus bend over its threshold) reaches 1 and is the highest within half
// `spacing`, strongest first, at least `spacing` from each other, from the
// `taken` ones and from the chain's start, and half that from its end (the
// skeleton stops about a limb radius short of a limb's tip). Narrowing is
// how much the section's weighted length lies below the highest within
// `spacing` on each side, relative to its own.
std::vector<std::pair<double, int>> joints_along(const std::vector<Station>& stations, double spacing,
                                                 const Joint_thresholds& thresholds, std::vector<double> taken,
                                                 double end)
{
  std::vector<double> score(stations.size(), 0.);
  for(std::size_t i = 0; i < stations.size(); ++i) {
    const Station& s = stations[i];
    double left = 0., right = 0.;
    for(const Station& t : stations) {
      const double d = t.arc - s.arc;
      if(d < 0 && -d <= spacing) left = std::max(left, t.weighted);
      if(d > 0 && d <= spacing) right = std::max(right, t.weighted);
    }
    const double narrowing = std::max(0., (std::min(left, right) - s.weighted) / s.weighted);
    score[i] = narrowing / thresholds.narrowing + s.bend / thresholds.bend;
  }
  std::vector<std::pair<double, int>> candidates;
  for(std::size_t i = 0; i < stations.size(); ++i) {
    const Station& s = stations[i];
    if(s.arc < spacing || end - s.arc < 0.5 * spacing || !(score[i] >= 1.)) continue;
    bool highest = true;
    for(std::size_t j = 0; j < stations.size(); ++j)
      if(std::abs(stations[j].arc - s.arc) <= 0.5 * spacing && score[j] > score[i]) highest = false;
    if(highest) candidates.emplace_back(score[i], int(i));
  }
  std::sort(candidates.rbegin(), candidates.rend());
  std::vector<std::pair<double, int>> chosen;
  for(const auto& [strength, i] : candidates) {
    const double arc = stations[std::size_t(i)].arc;
    if(std::all_of(taken.begin(), taken.end(), [&](double a) { return std::abs(a - arc) >= spacing; })) {
      chosen.emplace_back(strength, i);
      taken.push_back(arc);
    }
  }
  return chosen;
}

// A joint along a limb: its station and how clearly it shows.
struct Limb_joint
{
  int station = -1;
  double strength = 0.;
  bool by_analogy = false;
};

// A limb's sections from its base (arc 0) outwards and the joints found.
struct Limb_profile
{
  int limb = -1;
  double radius = 0., spacing = 0.;
  double length = 0.; // from the base to the end of the limb's skeleton branch
  int base_vertex = -1; // -1: not a limb after all
  std::vector<Station> stations;
  std::vector<Limb_joint> joints;
};

Limb_profile limb_profile(const Skeleton_branches& branches, const Chain& limb, const Joint_proposal_options& options)
{
  Limb_profile p;
  p.radius = branches.radius(limb);
  p.spacing = options.minimum_segment_length * p.radius;
  const std::vector<Station> stations = branches.stations(limb, p.radius, 0.5 * p.spacing);
  const double end = branches.length(limb);
  // A limb is a tube for at least its minimum length: sections across a
  // branch to the corner of a box-like body close around it only near its end.
  if(stations.empty() || end - stations.front().arc < options.minimum_limb_length * p.radius) return p;
  // The base: the narrowest, most concave section within a limb radius of
  // where sections first close around the limb alone.
  std::size_t base = 0;
  for(std::size_t i = 0; i < stations.size() && stations[i].arc <= stations.front().arc + p.radius; ++i)
    if(stations[i].weighted < stations[base].weighted) base = i;
  p.base_vertex = stations[base].vertex;
  p.stations.assign(stations.begin() + std::ptrdiff_t(base), stations.end());
  const double from = p.stations.front().arc;
  for(Station& s : p.stations) s.arc -= from;
  p.length = end - from;
  return p;
}

// Adds a joint by analogy at the best section within half a spacing of
// `fraction` of the limb's length, if one keeps the spacing to the others.
void add_joint_near(Limb_profile& p, double fraction)
{
  const double target = fraction * p.length;
  int best = -1;
  for(std::size_t i = 0; i < p.stations.size(); ++i)
    if(std::abs(p.stations[i].arc - target) <= 0.5 * p.spacing &&
       (best < 0 || p.stations[i].weighted < p.stations[std::size_t(best)].weighted))
      best = int(i);
  if(best < 0) return;
  const double arc = p.stations[std::size_t(best)].arc;
  if(arc < p.spacing || p.length - arc < 0.5 * p.spacing) return;
  for(const Limb_joint& j : p.joints)
    if(std::abs(p.stations[std::size_t(j.station)].arc - arc) < p.spacing) return;
  p.joints.push_back({best, 0., true});
}

// Limbs that look alike (radius and length within a factor 1.5) are cut
// alike: a joint found at about the same fraction of the length (within
// 0.1) on at least two of them and a third of the group is added, at the
// best section near that fraction, to the ones of the group where nothing
// showed there (a straight finger whose neighbour is bent; an arm whose
// narrowing is too faint).
void add_joints_by_analogy(std::vector<Limb_profile>& profiles)
{
  auto similar = [](const Limb_profile& a, const Limb_profile& b) {
    return std::max(a.radius, b.radius) <= 1.5 * std::min(a.radius, b.radius) &&
           std::max(a.length, b.length) <= 1.5 * std::min(a.length, b.length);
  };
  std::vector<std::size_t> group(profiles.size());
  for(std::size_t i = 0; i < profiles.size(); ++i) {
    group[i] = i;
    for(std::size_t j = 0; j < i && group[i] == i; ++j)
      if(similar(profiles[i], profiles[j])) group[i] = group[j];
  }
  for(std::size_t g = 0; g < profiles.size(); ++g) {
    std::vector<std::size_t> members;
    for(std::size_t i = 0; i < profiles.size(); ++i)
      if(group[i] == g) members.push_back(i);
    if(members.size() < 2) continue;
    std::vector<std::pair<double, std::size_t>> found; // (fraction of the length, member)
    for(std::size_t i : members)
      for(const Limb_joint& j : profiles[i].joints)
        found.emplace_back(profiles[i].stations[std::size_t(j.station)].arc / profiles[i].length, i);
    std::sort(found.begin(), found.end());
    for(std::size_t a = 0; a < found.size();) {
      std::size_t b = a + 1;
      while(b < found.size() && found[b].first - found[b - 1].first <= 0.1) ++b;
      std::set<std::size_t> limbs;
      double sum = 0.;
      for(std::size_t k = a; k < b; ++k) {
        limbs.insert(found[k].second);
        sum += found[k].first;
      }
      if(limbs.size() >= 2 && 3 * limbs.size() >= members.size())
        for(std::size_t i : members)
          if(!limbs.count(i)) add_joint_near(profiles[i], sum / double(b - a));
      a = b;
    }
  }
}

void check_options(const Joint_proposal_options& o)
{
  auto bad = [](const std::string& name, const std::string& problem) {
    throw Input_error("joint proposal options", name, problem);
  };
  if(!(o.sensitivity >= 0 && o.sensitivity <= 1)) bad("sensitivity", "must be between 0 and 1");
  if(!(o.minimum_limb_length > 0) || !std::isfinite(o.minimum_limb_length))
    bad("minimum_limb_length", "must be finite and > 0");
  if(!(o.minimum_segment_length > 0) || !std::isfinite(o.minimum_segment_length))
    bad("minimum_segment_length", "must be finite and > 0");
}

} // namespace

Joint_proposal cut_at_proposed_joints(const Indexed_mesh& mesh, const Joint_proposal_options& options,
                                      const std::string& mesh_source)
{
  check_options(options);
  Joint_cutting_options cutting = options.cutting;
  cutting.skip_unfound = true;
  const Joint_finder finder(mesh, cutting, mesh_source);
  Skeleton_branches branches(finder);
  branches.prune(options.minimum_limb_length);
  const std::vector<Chain> limbs = branches.thinner_than_body(branches.limbs(), 0.75);
  const Joint_thresholds thresholds(options.sensitivity);

  Joint_proposal proposal;
  std::vector<Limb_profile> profiles;
  for(std::size_t l = 0; l < limbs.size(); ++l) {
    Limb_profile p = limb_profile(branches, limbs[l], options);
    if(p.base_vertex < 0) continue;
    p.limb = int(l);
    for(const auto& [strength, i] : joints_along(p.stations, p.spacing, thresholds, {0.}, p.length))
      p.joints.push_back({i, strength, false});
    profiles.push_back(std::move(p));
  }
  // A branch without a base (no cut found where it leaves the body) is no limb.
  proposal.limbs = int(profiles.size());
  add_joints_by_analogy(profiles);
  for(const Limb_profile& p : profiles) {
    proposal.joints.push_back({p.base_vertex, p.limb, true, 0.});
    for(const Limb_joint& j : p.joints)
      proposal.joints.push_back({p.stations[std::size_t(j.station)].vertex, p.limb, false, j.strength, j.by_analogy});
  }
  const Chain body = branches.body_axis(limbs);
  if(body.size() > 1) {
    const double radius = branches.radius(body), spacing = options.minimum_segment_length * radius;
    const std::vector<Station> stations = branches.stations(body, radius, 0.5 * spacing);
    // Only a waist: a body's axis bends and swells where limbs leave it.
    for(const auto& [strength, i] : joints_along(stations, spacing, thresholds.times(4.), {}, branches.length(body)))
      proposal.joints.push_back({stations[std::size_t(i)].vertex, -1, false, strength});
  }
  std::vector<int> vertices;
  for(const Proposed_joint& j : proposal.joints) vertices.push_back(j.vertex);
  proposal.cutting = internal::cut_at_vertices(finder, vertices);
  return proposal;
}

} // namespace MPM
} // namespace CGAL
