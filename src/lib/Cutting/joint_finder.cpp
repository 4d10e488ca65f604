// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Joint_finder.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Mesh_file_checks.h>
#include <CGAL/MPM/internal/Crease_weights.h>
#include <CGAL/MPM/internal/Vertex_components.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <set>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Vector = Eigen::Vector3d;

using internal::vertex_name;

double distance_to_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const double t = std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0., 1.);
  return (p - (a + t * (b - a))).norm();
}

// Checked first, before the mesh is copied and its skeleton computed.
const Joint_cutting_options& checked(const Joint_cutting_options& o)
{
  auto bad = [](const std::string& name, const std::string& problem) {
    throw Input_error("joint cutting options", name, problem);
  };
  if(!(o.feature_weight >= 0) || !std::isfinite(o.feature_weight)) bad("feature_weight", "must be finite and >= 0");
  if(!(o.search_range >= 0) || !std::isfinite(o.search_range)) bad("search_range", "must be finite and >= 0");
  if(!(o.snap_band >= 0) || !std::isfinite(o.snap_band)) bad("snap_band", "must be finite and >= 0");
  if(o.anchors < 3) bad("anchors", "must be at least 3");
  if(o.minimum_section_vertices < 3) bad("minimum_section_vertices", "must be at least 3");
  return o;
}

} // namespace

Joint_finder::Joint_finder(const Indexed_mesh& m, const Joint_cutting_options& options, const std::string& source)
  : m_(m), options_(checked(options)), source_(source), surface_(to_surface_mesh(m, source, "joint cutting"))
{
  check_closed_and_connected();
  skeleton_ = curve_skeleton(m, source);
  measure_skeleton_edges();
  weight_ = crease_edge_weights(surface_, m, 1.);
}

Section Joint_finder::find(int v) const
{
  const std::vector<Limb_axis> axes = limb_axes(v);
  // The section through the click is where the user asked for the cut:
  // across the limb under the click whose section there is the narrowest
  // small loop around its axis (at a joint, the limb's, not the body's),
  // tilted by up to 20 degrees to follow an oblique crease.
  Section best;
  std::size_t most_vertices = 0;
  for(const Limb_axis& axis : axes)
    for(const Vector& n : tilted(axis.direction, {10., 20.})) {
      const Section s = section(v, axis, 0., n, true);
      const std::size_t vertices = std::set<int>(s.loop.begin(), s.loop.end()).size();
      most_vertices = std::max(most_vertices, vertices);
      if(acceptable(s) && (best.loop.empty() || s.weighted < best.weighted)) best = s;
    }
  if(!best.loop.empty()) return best;
  if(most_vertices < std::size_t(options_.minimum_section_vertices))
    fail(v, "the mesh is too coarse there: the section across the limb has " + std::to_string(most_vertices) +
              " vertices (at least " + std::to_string(options_.minimum_section_vertices) + " needed)");
  // It runs into the body or a neighbouring limb: take the narrowest small
  // section moved along the best-fitting limb or tilted, within the search range.
  const Limb_axis& axis = axes.front();
  best = narrowest_within_range(v, axis);
  if(best.loop.empty())
    fail(v, "the section across the limb there is not a small closed loop around the skeleton (the limb's radius "
            "is " + std::to_string(axis.radius) + "), nor is any section within the search range: click on a "
            "limb, near its joint");
  return best;
}

// Where a limb flares into a thicker body (a finger's base on the palm),
// the click lies off the limb's own axis and the body's axes fit it
// better: the section across the limb much thinner than `found`'s whose
// axis passes within two and a half of its radii of the click, the
// narrowest small one within the search range.
Section Joint_finder::thinner_limb_section(int v, const Section& found) const
{
  const Vector p = point(v);
  std::size_t thin = skeleton_edges_.size();
  double best_misfit = 1.5;
  for(std::size_t e = 0; e < skeleton_edges_.size(); ++e) {
    if(!(edge_radius_[e] > 0) || edge_radius_[e] >= 0.6 * found.axis.radius) continue;
    if(const double misfit = edge_misfit(e, p); misfit < best_misfit) best_misfit = misfit, thin = e;
  }
  Section best;
  if(thin == skeleton_edges_.size()) return best;
  const Limb_axis axis = edge_axis(thin, p);
  if(!axis.direction.allFinite()) return best;
  // None when `found`, measured around that limb's axis, already is a
  // small loop around it.
  Section around = found;
  around.axis = axis;
  const Vector centre = axis.point + (found.centre - axis.point).dot(axis.direction) * axis.direction;
  around.off_axis = (found.centre - centre).norm();
  around.spread = 0.;
  for(int u : found.loop) around.spread = std::max(around.spread, (point(u) - centre).norm());
  if(acceptable(around)) return best;
  return narrowest_within_range(v, axis);
}

// How far `p` is from lying on the limb surface of skeleton edge `e`: its
// distance to the edge minus the limb's radius there, relative to that radius.
double Joint_finder::edge_misfit(std::size_t e, const Vector& p) const
{
  const auto [a, b] = skeleton_edges_[e];
  const double d = distance_to_segment(p, skeleton_.points[std::size_t(a)], skeleton_.points[std::size_t(b)]);
  return std::abs(d - edge_radius_[e]) / edge_radius_[e];
}

// The narrowest small section across `axis` with its plane moved along it
// from `v` or tilted, within the search range; an empty loop if none.
Section Joint_finder::narrowest_within_range(int v, const Limb_axis& axis) const
{
  Section best;
  const std::vector<Vector> normals = tilted(axis.direction, {20., 40.});
  const int steps = 4;
  for(int k = -steps; k <= steps && options_.search_range > 0; ++k)
    for(const Vector& n : normals) {
      const Section s = section(v, axis, options_.search_range * axis.radius * k / steps, n, false);
      if(acceptable(s) && (best.loop.empty() || s.weighted < best.weighted)) best = s;
    }
  return best;
}

// A shortest path on the surface cut open along the half-plane from the
// limb's axis through `v`: a vertex is reached on sheet 0 or 1, and an edge
// that crosses the half-plane changes the sheet, so the shortest path from
// `v` on sheet 0 to `v` on sheet 1 goes once around the limb.
Section Joint_finder::snapped(int v, const Section& s, double band, const std::vector<int>& avoid) const
{
  std::set<std::pair<int, int>> avoided;
  for(std::size_t k = 0; k + 1 < avoid.size(); ++k) avoided.insert(std::minmax(avoid[k], avoid[k + 1]));
  const Vector d = s.axis.direction.normalized(), e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  const Vector c = s.centre, pv = point(v);
  const auto radial = [&](const Vector& q) { return (q - d.dot(q) * d).norm(); };
  double reach = 0.;
  for(int u : s.loop) reach = std::max(reach, radial(point(u) - c));
  reach *= 1.5;
  const double low = -band * s.axis.radius, high = band * s.axis.radius;
  const std::size_t n = std::size_t(m_.number_of_vertices());
  const auto angle = [&](const Vector& q) { return std::atan2(e2.dot(q), e1.dot(q)); };
  const double start = angle(pv - c);
  std::vector<double> phi(n, -1.); // angle around the axis from `v`, in [0, 2 pi); -1 outside the band
  for(std::size_t u = 0; u < n; ++u) {
    const Vector q = point(int(u)) - c;
    const double along = s.normal.dot(point(int(u)) - pv);
    if(along < low || along > high || radial(q) > reach) continue;
    phi[u] = std::fmod(angle(q) - start + 4. * M_PI, 2. * M_PI);
  }
  phi[std::size_t(v)] = 0.;
  using Item = std::pair<double, std::size_t>; // distance, 2 * vertex + sheet
  std::vector<double> distance(2 * n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> previous(2 * n, std::size_t(-1));
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  const std::size_t source = 2 * std::size_t(v), target = source + 1;
  distance[source] = 0.;
  queue.push({0., source});
  while(!queue.empty()) {
    const auto [dist, node] = queue.top();
    queue.pop();
    if(node == target) break;
    if(dist > distance[node]) continue;
    const std::size_t u = node / 2;
    const int sheet = int(node % 2);
    for(auto h : CGAL::halfedges_around_target(Indexed_surface_mesh::Vertex_index(std::uint32_t(u)), surface_)) {
      const std::size_t w = std::size_t(surface_.source(h));
      if(phi[w] < 0. || avoided.count(std::minmax(int(u), int(w))) > 0) continue;
      const double jump = phi[w] - phi[u];
      const int next_sheet = sheet + (jump < -M_PI ? 1 : jump > M_PI ? -1 : 0);
      if(next_sheet < 0 || next_sheet > 1) continue;
      const std::size_t next = 2 * w + std::size_t(next_sheet);
      const double through = dist + weight_[surface_.edge(h)];
      if(through < distance[next]) {
        distance[next] = through;
        previous[next] = node;
        queue.push({through, next});
      }
    }
  }
  // Kept off a cut, any loop found beats `s`, which may run along it.
  if(!(distance[target] < (avoided.empty() ? s.weighted : std::numeric_limits<double>::infinity()))) return s;
  Section r = s;
  r.loop.clear();
  for(std::size_t node = previous[target]; node != source; node = previous[node]) r.loop.push_back(int(node / 2));
  r.loop.push_back(v);
  std::reverse(r.loop.begin(), r.loop.end());
  // Where the axis passes close to the surface (a click at a knuckle, on
  // the palm's side), a loop around a few faces there also goes once
  // around it: too few vertices to be a section of the limb.
  if(std::set<int>(r.loop.begin(), r.loop.end()).size() < std::size_t(options_.minimum_section_vertices)) return s;
  r.centre = Vector::Zero();
  for(int u : r.loop) r.centre += point(u);
  r.centre /= double(r.loop.size());
  r.weighted = distance[target];
  return r;
}

// `direction` and directions tilted from it by each angle (degrees) towards
// eight directions around it.
std::vector<Joint_finder::Vector> Joint_finder::tilted(const Vector& direction, const std::vector<double>& angles)
{
  const Vector u = direction.unitOrthogonal(), w = direction.cross(u);
  std::vector<Vector> r{direction};
  for(double angle : angles)
    for(int k = 0; k < 8; ++k) {
      const Vector e = std::cos(k * M_PI / 4.) * u + std::sin(k * M_PI / 4.) * w;
      r.push_back((direction + std::tan(angle * M_PI / 180.) * e).normalized());
    }
  return r;
}

void Joint_finder::fail(int v, const std::string& problem) const
{
  throw Input_error(source_, vertex_name(v), problem);
}

void Joint_finder::check_closed_and_connected() const
{
  for(auto h : surface_.halfedges())
    if(surface_.is_border(h))
      throw Input_error(source_, vertex_name(int(surface_.target(h))),
                        "lies on a hole of the mesh: cutting at joints needs a closed surface (close the holes first)");
  int components = 0;
  vertex_component_labels(m_, &components);
  if(components > 1)
    throw Input_error(source_, "mesh",
                      "has " + std::to_string(components) +
                        " connected components: cutting at joints needs one closed surface");
}

// The limbs the vertex lies on: skeleton edges near its node at a
// distance from it within half their radius of that radius (a vertex at
// the base of a limb often contracts to a node of the body but lies on the
// limb's surface), best fitting first, each with its direction smoothed
// over about a limb radius along the branch.
std::vector<Limb_axis> Joint_finder::limb_axes(int v) const
{
  const int node = skeleton_.node_of_vertex[std::size_t(v)];
  if(node < 0) fail(v, "no skeleton node stands for it");
  const std::vector<char> near = nodes_within(node, 8);
  const Vector p = point(v);
  std::vector<std::pair<double, std::size_t>> fits;
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t e = 0; e < skeleton_edges_.size(); ++e) {
    const auto [a, b] = skeleton_edges_[e];
    if(!near[std::size_t(a)] || !near[std::size_t(b)] || !(edge_radius_[e] > 0)) continue;
    const double misfit = edge_misfit(e, p);
    best = std::min(best, misfit);
    if(misfit <= 0.5) fits.emplace_back(misfit, e);
  }
  if(fits.empty())
    fail(v, "is on the body: no limb of the curve skeleton passes under it (its distance to each nearby axis "
            "differs from that limb's radius by " + std::to_string(int(100. * best)) + "% or more)");
  std::sort(fits.begin(), fits.end());
  std::vector<Limb_axis> axes;
  for(std::size_t k = 0; k < std::min<std::size_t>(fits.size(), 8); ++k) {
    const Limb_axis axis = edge_axis(fits[k].second, p);
    if(axis.direction.allFinite()) axes.push_back(axis);
  }
  // At a limb's base the thick body's many edges can fill the list: the
  // best fitting edge of a limb much thinner than the best fit is tried too.
  for(const auto& [misfit, e] : fits)
    if(!axes.empty() && edge_radius_[e] < 0.6 * axes.front().radius) {
      const Limb_axis axis = edge_axis(e, p);
      if(axis.direction.allFinite()) axes.push_back(axis);
      break;
    }
  if(axes.empty()) fail(v, "the curve skeleton has no direction there");
  return axes;
}


// Per skeleton edge, the mean distance from its line of the mesh vertices
// that contracted to its two nodes: the limb's radius there.
void Joint_finder::measure_skeleton_edges()
{
  std::vector<std::vector<std::size_t>> edges_of_node(skeleton_.points.size());
  for(std::size_t a = 0; a < skeleton_.neighbours.size(); ++a)
    for(int b : skeleton_.neighbours[a])
      if(int(a) < b) {
        edges_of_node[a].push_back(skeleton_edges_.size());
        edges_of_node[std::size_t(b)].push_back(skeleton_edges_.size());
        skeleton_edges_.emplace_back(int(a), b);
      }
  std::vector<double> sum(skeleton_edges_.size(), 0.);
  std::vector<int> count(skeleton_edges_.size(), 0);
  for(std::size_t u = 0; u < skeleton_.node_of_vertex.size(); ++u) {
    const int n = skeleton_.node_of_vertex[u];
    if(n < 0) continue;
    for(std::size_t e : edges_of_node[std::size_t(n)]) {
      const Vector a = skeleton_.points[std::size_t(skeleton_edges_[e].first)];
      const Vector d = (skeleton_.points[std::size_t(skeleton_edges_[e].second)] - a).normalized();
      const Vector r = point(int(u)) - a;
      sum[e] += (r - r.dot(d) * d).norm();
      ++count[e];
    }
  }
  for(std::size_t e = 0; e < sum.size(); ++e) edge_radius_.push_back(count[e] > 0 ? sum[e] / count[e] : 0.);
}

// Nodes at most `hops` skeleton edges from `node`.
std::vector<char> Joint_finder::nodes_within(int node, int hops) const
{
  std::vector<char> reached(skeleton_.points.size(), 0);
  std::vector<int> front{node};
  reached[std::size_t(node)] = 1;
  for(int h = 0; h < hops; ++h) {
    std::vector<int> next;
    for(int n : front)
      for(int m : skeleton_.neighbours[std::size_t(n)])
        if(!reached[std::size_t(m)]) {
          reached[std::size_t(m)] = 1;
          next.push_back(m);
        }
    front = std::move(next);
  }
  return reached;
}

// Position reached walking from `from` away from `previous` along a chain
// of the skeleton for `length`, stopping at a branch or an end.
Joint_finder::Vector Joint_finder::walk(int from, int previous, double length) const
{
  double walked = 0.;
  while(walked < length && skeleton_.neighbours[std::size_t(from)].size() == 2) {
    const auto& nb = skeleton_.neighbours[std::size_t(from)];
    const int next = nb[0] == previous ? nb[1] : nb[0];
    walked += (skeleton_.points[std::size_t(next)] - skeleton_.points[std::size_t(from)]).norm();
    previous = from;
    from = next;
  }
  return skeleton_.points[std::size_t(from)];
}

// A small closed loop around its limb's axis, with enough vertices.
bool Joint_finder::acceptable(const Section& s) const
{
  return std::set<int>(s.loop.begin(), s.loop.end()).size() >= std::size_t(options_.minimum_section_vertices) &&
         s.spread <= 3. * s.axis.radius && s.off_axis <= s.axis.radius;
}

// The closed section by the plane through the clicked vertex moved by `t`
// along the axis, with the given normal: the loop through the vertex when
// `through_click` and there is one, else the loop centred nearest the axis.
Section Joint_finder::section(int v, const Limb_axis& axis, double t, const Vector& normal, bool through_click) const
{
  const Vector origin = point(v) + t * axis.direction, centre = axis.point + t * axis.direction;
  std::vector<char> positive(std::size_t(m_.number_of_vertices()));
  for(int u = 0; u < m_.number_of_vertices(); ++u)
    positive[std::size_t(u)] = normal.dot(point(u) - origin) >= 0;
  auto crossing = [&](Indexed_surface_mesh::Halfedge_index h) {
    return positive[std::size_t(surface_.source(h))] != positive[std::size_t(surface_.target(h))];
  };
  std::vector<char> visited(surface_.number_of_edges(), 0);
  Section best;
  double best_rank = std::numeric_limits<double>::infinity();
  for(auto e : surface_.edges()) {
    if(visited[e] || !crossing(surface_.halfedge(e))) continue;
    Section s = trace(surface_.halfedge(e), crossing, positive, visited);
    s.spread = 0.;
    for(int u : s.loop) s.spread = std::max(s.spread, (point(u) - centre).norm());
    s.off_axis = (s.centre - centre).norm();
    const bool has_click = through_click && std::find(s.loop.begin(), s.loop.end(), v) != s.loop.end();
    const double rank = has_click ? -1. : s.off_axis;
    if(rank < best_rank) {
      best_rank = rank;
      best = std::move(s);
    }
  }
  best.shift = t;
  best.axis = axis;
  best.normal = normal;
  return best;
}

// Follows the crossing edges from `start` face by face around the section.
template <class Crossing>
Section Joint_finder::trace(Indexed_surface_mesh::Halfedge_index start, const Crossing& crossing, const std::vector<char>& positive,
                            std::vector<char>& visited) const
{
  Section s;
  double weighted = 0.;
  Indexed_surface_mesh::Halfedge_index h = start;
  do {
    visited[surface_.edge(h)] = 1;
    const int u = int(positive[std::size_t(surface_.source(h))] ? surface_.source(h) : surface_.target(h));
    if(s.loop.empty() || s.loop.back() != u) {
      if(!s.loop.empty()) weighted += edge_weight(s.loop.back(), u);
      s.loop.push_back(u);
    }
    // The face on h's side has exactly one other crossing edge.
    const Indexed_surface_mesh::Halfedge_index n = surface_.next(h);
    h = surface_.opposite(crossing(n) ? n : surface_.prev(h));
  } while(h != start);
  if(s.loop.size() > 1 && s.loop.front() == s.loop.back()) s.loop.pop_back();
  if(s.loop.size() > 1) weighted += edge_weight(s.loop.back(), s.loop.front());
  for(int u : s.loop) s.centre += point(u);
  s.centre /= double(std::max<std::size_t>(s.loop.size(), 1));
  s.weighted = weighted;
  return s;
}

double Joint_finder::edge_weight(int a, int b) const
{
  const auto h = surface_.halfedge(Indexed_surface_mesh::Vertex_index(a), Indexed_surface_mesh::Vertex_index(b));
  return h == Indexed_surface_mesh::null_halfedge() ? 0. : weight_[surface_.edge(h)];
}

Limb_axis Joint_finder::edge_axis(std::size_t e, const Vector& p) const
{
  const auto [a, b] = skeleton_edges_[e];
  Limb_axis axis;
  axis.radius = edge_radius_[e];
  axis.direction = (walk(b, a, axis.radius) - walk(a, b, axis.radius)).normalized();
  const Vector pa = skeleton_.points[std::size_t(a)];
  axis.point = pa + (p - pa).dot(axis.direction) * axis.direction;
  return axis;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
