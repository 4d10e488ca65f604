// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Mesh_file_checks.h>
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/internal/Joint_finder.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

namespace CGAL {
namespace MPM {

namespace {

using internal::vertex_name;

// The length along the closed loop to each of its vertices, and to its
// first again (last entry: the loop's length).
std::vector<double> arc_lengths(const Indexed_mesh& m, const std::vector<int>& loop)
{
  std::vector<double> at{0.};
  for(std::size_t k = 0; k < loop.size(); ++k)
    at.push_back(at.back() + (m.points.row(loop[(k + 1) % loop.size()]) - m.points.row(loop[k])).norm());
  return at;
}

// `count` vertices of the loop spread evenly along its length.
std::vector<int> anchors(const Indexed_mesh& m, const std::vector<int>& loop, int count)
{
  const std::vector<double> at = arc_lengths(m, loop);
  std::vector<int> r;
  std::size_t k = 0;
  for(int i = 0; i < count; ++i) {
    const double target = at.back() * i / count;
    while(k + 1 < loop.size() && at[k + 1] <= target) ++k;
    if(std::find(r.begin(), r.end(), loop[k]) == r.end()) r.push_back(loop[k]);
  }
  return r;
}

// Every clicked vertex exists and lies on a face.
void check_vertices(const Indexed_mesh& mesh, const std::vector<int>& vertices, const std::string& source)
{
  std::vector<bool> in_face(std::size_t(mesh.number_of_vertices()), false);
  for(const Triangle& t : mesh.triangles)
    for(int v : t)
      if(v >= 0 && v < mesh.number_of_vertices()) in_face[std::size_t(v)] = true;
  for(int v : vertices) {
    if(v < 0 || v >= mesh.number_of_vertices())
      throw Input_error(source, vertex_name(v),
                        "is out of range (the mesh has " + std::to_string(mesh.number_of_vertices()) + " vertices)");
    if(!in_face[std::size_t(v)]) throw Input_error(source, vertex_name(v), "belongs to no face");
  }
}

bool on_cut(const std::vector<int>& path, int v) { return std::find(path.begin(), path.end(), v) != path.end(); }

// Sections around one limb: their axes within 20 degrees of each other and
// their radii within a factor 1.5 (not a limb's and the body's it leaves).
bool around_one_limb(const internal::Section& a, const internal::Section& b)
{
  return std::abs(a.axis.direction.normalized().dot(b.axis.direction.normalized())) > std::cos(20. * M_PI / 180.) &&
         std::abs(std::log(a.axis.radius / b.axis.radius)) < std::log(1.5);
}

// The edges both closed paths (first vertex repeated last) step along.
std::size_t shared_edges(const std::vector<int>& a, const std::vector<int>& b)
{
  std::set<std::pair<int, int>> edges;
  for(std::size_t k = 0; k + 1 < a.size(); ++k) edges.insert(std::minmax(a[k], a[k + 1]));
  std::size_t shared = 0;
  for(std::size_t k = 0; k + 1 < b.size(); ++k) shared += edges.count(std::minmax(b[k], b[k + 1]));
  return shared;
}

} // namespace

Joint_cutting_result cut_at_vertices(const Indexed_mesh& mesh, const std::vector<int>& vertices,
                                     const Joint_cutting_options& options, const std::string& mesh_source)
{
  // Checked before the skeleton is computed, so that a bad click fails at once.
  check_vertices(mesh, vertices, mesh_source);
  return Joint_cutter(mesh, options, mesh_source).cut(vertices);
}

Joint_cutter::Joint_cutter(const Indexed_mesh& mesh, const Joint_cutting_options& options,
                           const std::string& mesh_source)
  : finder_(std::make_unique<internal::Joint_finder>(mesh, options, mesh_source))
{
}

Joint_cutter::~Joint_cutter() = default;

Joint_cutting_result Joint_cutter::cut(const std::vector<int>& vertices) const
{
  check_vertices(finder_->mesh(), vertices, finder_->source());
  return internal::cut_at_vertices(*finder_, vertices);
}

namespace internal {

namespace {

// The cuts accepted so far, one per click, and what decides whether the next
// click is a joint of its own.
class Click_cuts
{
  // A click's cut: its section, the line through it, the path traced.
  struct Cut
  {
    Section section;
    Cut_line line;
    std::vector<int> path;
  };

public:
  explicit Click_cuts(const Joint_finder& finder) : finder_(finder), options_(finder.options())
  {
    cutting_.feature_weight = options_.feature_weight;
  }

  // The cut for a click at `v`; throws Input_error naming `v`.
  void add(int v)
  {
    const std::size_t again = std::size_t(std::find(clicks_.begin(), clicks_.end(), v) - clicks_.begin());
    if(again < clicks_.size()) same_joint(v, again);
    Section through = finder_.find(v);
    Section s = finder_.snapped(v, through, options_.snap_band);
    // At a limb's flared base the body's section goes around the limb and
    // its neighbours; snapped, it often finds the limb's crease anyway. The
    // thinner limb's own section is taken when its snapped loop is cheaper.
    if(const Section thin = finder_.thinner_limb_section(v, through); !thin.loop.empty())
      if(Section t = finder_.snapped(v, thin, options_.snap_band); t.weighted < s.weighted) {
        through = thin;
        s = std::move(t);
      }
    Cut cut = traced_cut(v, std::move(s));
    if(const std::size_t met = conflicting(cut); met < cuts_.size()) {
      std::size_t blocking = met;
      // Two cuts a ring of faces apart bound a thin ring of a limb, as
      // people cut where an arm leaves the body; clicked there, both snap
      // to one crease. The second keeps the section through its click when
      // that goes around the same limb, or its loop snapped off the cut
      // made when that follows a crease of its own (the other side of the
      // ring). When the cut made runs through this click instead (it took
      // the crease clicked now), the first click's cut is snapped off this
      // one, so that either order of the two clicks can give both cuts.
      // Otherwise the click was on the joint of the cut made.
      if(around_one_limb(cuts_[met].section, through))
        if(Cut c = traced_cut(v, through); (blocking = conflicting(c)) == cuts_.size()) cut = std::move(c);
      if(blocking < cuts_.size())
        if(std::optional<Cut> c = off_the_cut(v, through, cuts_[met].path); c && conflicting(*c) == cuts_.size()) {
          cut = std::move(*c);
          blocking = cuts_.size();
        }
      if(blocking < cuts_.size() && !(on_cut(cuts_[met].path, v) && gives_back_its_crease(met, cut)))
        same_joint(v, blocking);
    }
    clicks_.push_back(v);
    throughs_.push_back(through);
    cuts_.push_back(std::move(cut));
  }

  // Every accepted cut made at once, with its click, limb and section.
  Joint_cutting_result result() const
  {
    const Indexed_mesh& mesh = finder_.mesh();
    Cut_specification all{{}, {}, source};
    for(const Cut& c : cuts_) all.cuts.push_back(c.line);
    Cutting_result cut = cut_mesh(mesh, all, cutting_, finder_.source());
    Joint_cutting_result r;
    r.mesh = std::move(cut.mesh);
    for(std::size_t i = 0; i < clicks_.size(); ++i) {
      Joint_cut c;
      c.vertex = clicks_[i];
      c.path = cut.paths[i];
      c.length = cut.lengths[i];
      const Section& section = cuts_[i].section;
      c.limb_radius = section.axis.radius;
      c.shift = std::abs(section.shift);
      c.axis = section.axis.direction;
      for(std::size_t k = 0; k + 1 < c.path.size(); ++k) c.centre += mesh.points.row(c.path[k]).transpose();
      c.centre /= double(std::max<std::size_t>(c.path.size() - 1, 1));
      r.cuts.push_back(std::move(c));
    }
    return r;
  }

private:
  static constexpr const char* source = "clicked vertices";

  // Through the click when its section passes there, so that cuts which
  // meet at a click are seen to meet.
  // Its anchors, or every vertex of the loop (`whole_loop`).
  Cut_line line_of(int v, const Section& s, bool whole_loop = false) const
  {
    std::vector<int> loop = s.loop;
    const auto at = std::find(loop.begin(), loop.end(), v);
    std::rotate(loop.begin(), at == loop.end() ? loop.begin() : at, loop.end());
    return Cut_line{whole_loop ? loop : anchors(finder_.mesh(), loop, options_.anchors), true,
                    "at vertex " + std::to_string(v)};
  }

  // The cut along section `s` of a click at `v`, traced alone, so that a
  // section whose points cannot be joined in order is blamed on its click
  // (and skipped) rather than failing all.
  Cut traced_cut(int v, Section s, bool whole_loop = false) const
  {
    Cut c{std::move(s), {}, {}};
    c.line = line_of(v, c.section, whole_loop);
    try {
      c.path =
        cut_mesh(finder_.mesh(), Cut_specification{{c.line}, {}, source}, cutting_, finder_.source()).paths.front();
    } catch(const Input_error& e) {
      finder_.fail(v, "the section across the limb there cannot be traced as a cut: " + e.problem());
    }
    return c;
  }

  // The first cut already made (but `except`) that `c` runs along or
  // crosses: two closed cuts of a sphere that do neither make
  // three regions. Cuts may touch at a vertex: people cut an arm's base
  // ring pinched to a point. Cuts whose sections go around two limbs
  // (around_one_limb()) may also share a few edges, less than a quarter of
  // the shorter: two fingers' bases meet in the web between them, and the
  // cuts either side of a ring where an arm leaves the body meet where the
  // ring narrows (on the 12 PSB meshes, two human cuts more found, none lost).
  std::size_t conflicting(const Cut& c, std::size_t except = std::size_t(-1)) const
  {
    for(std::size_t i = 0; i < cuts_.size(); ++i) {
      const Cut& made = cuts_[i];
      if(i == except || std::none_of(c.path.begin(), c.path.end(), [&](int u) { return on_cut(made.path, u); }))
        continue;
      if(const std::size_t shared = shared_edges(made.path, c.path); shared > 0)
        if(around_one_limb(made.section, c.section) || 4 * shared >= std::min(made.path.size(), c.path.size()) - 1)
          return i;
      try {
        if(cut_mesh(finder_.mesh(), Cut_specification{{made.line, c.line}, {}, source}, cutting_, finder_.source())
             .regions == 3)
          continue;
      } catch(const Input_error&) {
      }
      return i;
    }
    return cuts_.size();
  }

  // The loop through `v` around the limb of `through`, snapped to a crease
  // beside the cut `path` and kept off its edges (traced through every
  // vertex: between a few anchors the crease-weighted geodesic would step
  // back onto it), if it follows a crease: its crease-weighted length below
  // `crease_ratio` of its length. One ring off a finger's joint, on the
  // smooth tube, that is its length: the click was on that joint. Where an
  // arm leaves the body, a thin ring lies between two concave creases.
  std::optional<Cut> off_the_cut(int v, const Section& through, const std::vector<int>& path) const
  {
    constexpr double crease_ratio = 0.8;
    Section s = finder_.snapped(v, through, options_.snap_band, path);
    if(!(s.weighted < crease_ratio * arc_lengths(finder_.mesh(), s.loop).back())) return std::nullopt;
    try {
      return traced_cut(v, std::move(s), true);
    } catch(const Input_error&) {
      return std::nullopt;
    }
  }

  // Cuts `made` again off the cut `c` of a click that lies on it; true if
  // both then run along or cross no other cut made; false, and nothing
  // changed, otherwise.
  bool gives_back_its_crease(std::size_t made, const Cut& c)
  {
    std::optional<Cut> own = off_the_cut(clicks_[made], throughs_[made], c.path);
    if(!own) return false;
    std::swap(cuts_[made], *own);
    if(conflicting(cuts_[made], made) == cuts_.size() && conflicting(c) == cuts_.size()) return true;
    std::swap(cuts_[made], *own);
    return false;
  }

  [[noreturn]] void same_joint(int v, std::size_t made) const
  {
    finder_.fail(v, "is on the same joint as " + vertex_name(clicks_[made]) +
                      " (its cut would run along or cross the cut made there): click each joint once");
  }

  const Joint_finder& finder_;
  const Joint_cutting_options& options_;
  Cutting_options cutting_;
  std::vector<int> clicks_;
  std::vector<Section> throughs_; // each click's section before snapping
  std::vector<Cut> cuts_;
};

} // namespace

Joint_cutting_result cut_at_vertices(const Joint_finder& finder, const std::vector<int>& vertices)
{
  Click_cuts cuts(finder);
  std::vector<Skipped_click> skipped;
  for(int v : vertices) {
    try {
      cuts.add(v);
    } catch(const Input_error& e) {
      if(!finder.options().skip_unfound) throw;
      skipped.push_back({v, e.what()});
    }
  }
  Joint_cutting_result result = cuts.result();
  result.skipped = std::move(skipped);
  return result;
}

} // namespace internal

} // namespace MPM
} // namespace CGAL
