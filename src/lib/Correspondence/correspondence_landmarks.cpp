// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Correspondence_surface.h>

#include <CGAL/MPM/Input_error.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <limits>
#include <numeric>
#include <tuple>

namespace CGAL {
namespace MPM {
namespace internal {
namespace correspondence {

namespace {

bool tags_agree(const Surface& t, const Surface& s, const std::vector<int>& permutation)
{
  for(std::size_t l = 0; l < permutation.size(); ++l)
  {
    const int a = t.loop_tags[l], b = s.loop_tags[permutation[l]];
    if(a >= 0 && b >= 0 && a != b) return false;
  }
  return true;
}

// How far a loop's plane leans away from the segment's axis (towards
// `axis_point`): the component of its unit normal across the axis, about
// the sine of the lean angle.
Vec3 lean_of(const Loop& l, const Vec3& axis_point, int orientation)
{
  Vec3 normal = l.area_vector();
  const Vec3 axis = axis_point - l.centroid;
  if(!(normal.norm() > 0) || !(axis.norm() > 0)) return Vec3::Zero();
  normal.normalize();
  const Vec3 a = axis.normalized();
  return orientation * (normal - normal.dot(a) * a);
}

// Where a loop's plane leans away from the segment's axis, as a point at
// the loop's radius from its centroid: the mitred joint of a bent tube
// tilts its seam towards the bend, which fixes the twist that circular
// seams leave open. Leans under about 6 degrees count less, none (the
// centroid itself) says nothing.
Vec3 tilt_point(const Loop& l, const Vec3& axis_point, int orientation)
{
  const Vec3 lean = lean_of(l, axis_point, orientation);
  if(!(lean.norm() > 1e-6)) return l.centroid;
  return l.centroid + l.mean_radius() * std::min(1., lean.norm() / 0.1) * lean.normalized();
}

// Where the cap of a one-loop segment turns towards its tip: the line on
// which the surface normal makes the angle acos(cosine) with the axis (from
// the loop's centroid to the tip), in the half nearer the tip, traced
// across the triangles (linear in the vertex normals) so that it does not
// depend on the sampling. Its centre and mean radius; `found` is false
// when the surface has no such line there (a flat or pointed end).
struct Cap_ring
{
  bool found = false;
  Vec3 axis = Vec3::UnitZ(), centre = Vec3::Zero();
  double radius = 0.;
};

Cap_ring cap_ring(const Surface& x, double cosine)
{
  Cap_ring ring;
  const Vec3 c = x.loops[0].centroid;
  const double length = (x.tip - c).norm();
  if(!(length > 0)) return ring;
  ring.axis = (x.tip - c) / length;
  std::vector<double> value(x.vertex_normals.size());
  for(std::size_t v = 0; v < value.size(); ++v)
    value[v] = x.vertex_normals[v].norm() > 0 ? x.vertex_normals[v].dot(ring.axis) - cosine : -1.;
  double total = 0., height = 0., radius = 0.;
  for(const Triangle& f : x.mesh.triangles)
  {
    Vec3 ends[2];
    int found = 0;
    for(int k = 0; k < 3 && found < 2; ++k)
    {
      const int i = f[k], j = f[(k + 1) % 3];
      if((value[i] < 0) == (value[j] < 0)) continue;
      const double t = value[i] / (value[i] - value[j]);
      ends[found++] = (1. - t) * x.mesh.points.row(i).transpose() + t * x.mesh.points.row(j).transpose();
    }
    if(found < 2) continue;
    const Vec3 mid = 0.5 * (ends[0] + ends[1]) - c;
    const double h = mid.dot(ring.axis);
    if(h < 0.5 * length) continue;
    const double w = (ends[1] - ends[0]).norm();
    total += w;
    height += w * h;
    radius += w * (mid - h * ring.axis).norm();
  }
  if(!(total > 0)) return ring;
  ring.found = true;
  ring.centre = c + (height / total) * ring.axis;
  ring.radius = radius / total;
  return ring;
}

Point_matrix repeated(const Vec3& p, int count) { return p.transpose().replicate(count, 1); }

double rms(const Point_matrix& a, const Point_matrix& b)
{
  return a.rows() ? std::sqrt((a - b).squaredNorm() / a.rows()) : 0.;
}

bool tag_agrees(const Surface& t, int l, const Surface& s, int j)
{
  return t.loop_tags[std::size_t(l)] < 0 || s.loop_tags[std::size_t(j)] < 0 ||
         t.loop_tags[std::size_t(l)] == s.loop_tags[std::size_t(j)];
}

// A loop's centroid and the point at its mean radius along its normal
// (from the loop's direction, which follows the triangles): a motion that
// carries one loop onto another keeps the surface's orientation only if it
// carries both points.
Point_matrix oriented_loop_points(const Loop& l)
{
  const Vec3 normal = l.area_vector();
  Point_matrix p(2, 3);
  p.row(0) = l.centroid.transpose();
  const Vec3 lift = normal.norm() > 0 ? Vec3(l.mean_radius() * normal.normalized()) : Vec3::Zero();
  p.row(1) = (l.centroid + lift).transpose();
  return p;
}

// Loop orders worth trying on a part with too many loops to try them all
// (8! for an ant's thorax, its six legs alike in length and tag): each
// placement of the template's three longest loops on three segment loops
// whose tags agree gives a rigid motion (from their oriented points and
// the area centroids), under which every other loop takes the nearest
// free segment loop whose tag agrees. The `keep` orders whose loops then
// fit best; the identity (length order) when nothing agrees.
std::vector<std::vector<int>> likely_loop_orders(const Surface& t, const Surface& s, std::size_t keep)
{
  const int loops = static_cast<int>(t.loops.size());
  std::vector<std::pair<double, std::vector<int>>> found;
  const auto centroids = [](const Surface& x, const std::vector<int>& order) {
    Point_matrix p(2 * Eigen::Index(order.size()) + 1, 3);
    for(std::size_t k = 0; k < order.size(); ++k)
      p.middleRows(2 * Eigen::Index(k), 2) = oriented_loop_points(x.loops[std::size_t(order[k])]);
    p.row(2 * Eigen::Index(order.size())) = x.area_centroid.transpose();
    return p;
  };
  std::vector<int> identity(loops);
  std::iota(identity.begin(), identity.end(), 0);
  const Point_matrix all_t = centroids(t, identity);
  for(int a = 0; a < loops; ++a)
    for(int b = 0; b < loops; ++b)
      for(int c = 0; c < loops; ++c)
      {
        if(a == b || a == c || b == c || !tag_agrees(t, 0, s, a) || !tag_agrees(t, 1, s, b) || !tag_agrees(t, 2, s, c))
          continue;
        const Rigid_motion motion = fit_rigid_motion(centroids(t, {0, 1, 2}), centroids(s, {a, b, c}));
        std::vector<int> order(std::size_t(loops), -1);
        std::vector<bool> taken(std::size_t(loops), false);
        order[0] = a, order[1] = b, order[2] = c;
        taken[std::size_t(a)] = taken[std::size_t(b)] = taken[std::size_t(c)] = true;
        // Nearest pairs first, so that one loop does not take another's match.
        std::vector<std::tuple<double, int, int>> pairs;
        for(int l = 3; l < loops; ++l)
        {
          const Vec3 moved = motion.apply(t.loops[std::size_t(l)].centroid.transpose()).row(0).transpose();
          for(int j = 0; j < loops; ++j)
            if(!taken[std::size_t(j)] && tag_agrees(t, l, s, j))
              pairs.emplace_back((moved - s.loops[std::size_t(j)].centroid).norm(), l, j);
        }
        std::sort(pairs.begin(), pairs.end());
        for(const auto& [d, l, j] : pairs)
          if(order[std::size_t(l)] < 0 && !taken[std::size_t(j)]) order[std::size_t(l)] = j, taken[std::size_t(j)] = true;
        if(std::find(order.begin(), order.end(), -1) != order.end()) continue;
        const Point_matrix all_s = centroids(s, order);
        found.emplace_back(rms(fit_rigid_motion(all_t, all_s).apply(all_t), all_s), order);
      }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end(),
                          [](const auto& x, const auto& y) { return x.second == y.second; }),
              found.end());
  std::vector<std::vector<int>> orders;
  for(std::size_t k = 0; k < found.size() && k < keep; ++k) orders.push_back(found[k].second);
  if(orders.empty()) orders.push_back(identity);
  return orders;
}

} // namespace

// A tube's twist is left open by its geometry (the scores of all twists
// agree to a fraction of a percent); same-type parts of one model are mostly
// placed alike (fingers point the same way), so among near-equal scores the
// alignment rotating least wins: a score grows by this fraction per half turn.
constexpr double rotation_preference = 1.;

// Candidate alignments (loop matching with cyclic shift, or principal
// frames for closed segments), all proper (no reflection), scored by the landmark residual
// after rigid alignment plus the mean distance of template samples to the
// segment: the loops fix the twist of a tube only up to its symmetry, the
// surface decides the rest.
Landmarks match_landmarks(const Surface& t, const Surface& s, const std::vector<int>& user_t,
                          const std::vector<int>& user_s, int samples, bool use_tilt)
{
  const int loops = static_cast<int>(t.loops.size());
  const Point_matrix user_source = rows_of(t.mesh.points, user_t), user_target = rows_of(s.mesh.points, user_s);
  const int user_weight = std::max(1, samples / 2);
  std::vector<Point_matrix> user_src_w(user_weight, user_source), user_tgt_w(user_weight, user_target);

  std::vector<int> probe;
  const int step = std::max(1, t.mesh.number_of_vertices() / 150);
  for(int v = 0; v < t.mesh.number_of_vertices(); v += step) probe.push_back(v);
  const Point_matrix probe_points = rows_of(t.mesh.points, probe);
  const auto surface_distance = [&](const Rigid_motion& m) {
    const Point_matrix moved = m.apply(probe_points);
    double sum = 0.;
    for(Eigen::Index i = 0; i < moved.rows(); ++i)
      sum += (s.closest(moved.row(i).transpose()) - moved.row(i).transpose()).norm();
    return sum / moved.rows();
  };

  struct Candidate
  {
    std::vector<Loop_match> loops;
    Point_matrix source, target;
    Rigid_motion motion;
    double residual = 0.;
    double score = -1.;
    bool tilt = false;
  };
  std::vector<Candidate> candidates;

  const bool extremity = loops == 1;
  const Vec3 &extremity_t = t.tip, &extremity_s = s.tip;
  const int extremity_weight = std::max(1, samples / 4);

  std::vector<Point_matrix> template_samples;
  for(const Loop& l : t.loops) template_samples.push_back(l.samples(samples, 0., 1));
  const auto finish = [&](Candidate& c) {
    c.motion = fit_rigid_motion(c.source, c.target);
    c.residual = rms(c.motion.apply(c.source), c.target);
  };
  // Tilt landmarks of template loop l matched by m, about the axis to the
  // area centroid (one loop: more robust than the extremity) or to the
  // other loop (two loops).
  const int tilt_weight = std::max(1, samples / 2);
  const auto add_tilt = [&](const Loop_match& m, int l, const std::vector<int>& permutation,
                            std::vector<Point_matrix>& src, std::vector<Point_matrix>& tgt) {
    if(loops == 1)
    {
      src.push_back(repeated(tilt_point(t.loops[0], t.area_centroid, 1), tilt_weight));
      tgt.push_back(repeated(tilt_point(s.loops[m.target], s.area_centroid, m.orientation), tilt_weight));
    }
    else if(loops == 2)
    {
      src.push_back(repeated(tilt_point(t.loops[l], t.loops[1 - l].centroid, 1), tilt_weight));
      tgt.push_back(repeated(tilt_point(s.loops[m.target], s.loops[permutation[1 - l]].centroid, m.orientation), tilt_weight));
    }
  };
  // Loop 0 of the template on loop permutation[0] at `offset`: rigid motion
  // from it and the other loops' centroids, then the other loops' best
  // shifts (at `resolution` per turn) under that motion, then the motion of all.
  // With `tilt`, the seams' lean joins the fit; the residual that ranks
  // candidates leaves it out.
  const auto loop_candidate = [&](const std::vector<int>& permutation, int orientation, double offset, int resolution,
                                  bool tilt) {
    Candidate c;
    c.tilt = tilt;
    c.loops.assign(loops, Loop_match());
    c.loops[0] = {permutation[0], orientation, offset};
    std::vector<Point_matrix> src{template_samples[0]},
      tgt{s.loops[permutation[0]].samples(samples, offset, orientation)};
    for(int l = 1; l < loops; ++l)
    {
      src.push_back(repeated(t.loops[l].centroid, samples));
      tgt.push_back(repeated(s.loops[permutation[l]].centroid, samples));
    }
    std::vector<Point_matrix> extra_src, extra_tgt, tilt_src, tilt_tgt;
    if(tilt) add_tilt(c.loops[0], 0, permutation, tilt_src, tilt_tgt);
    if(extremity)
    {
      extra_src.push_back(repeated(extremity_t, extremity_weight));
      extra_tgt.push_back(repeated(extremity_s, extremity_weight));
    }
    extra_src.insert(extra_src.end(), user_src_w.begin(), user_src_w.end());
    extra_tgt.insert(extra_tgt.end(), user_tgt_w.begin(), user_tgt_w.end());
    src.insert(src.end(), extra_src.begin(), extra_src.end());
    tgt.insert(tgt.end(), extra_tgt.begin(), extra_tgt.end());
    src.insert(src.end(), tilt_src.begin(), tilt_src.end());
    tgt.insert(tgt.end(), tilt_tgt.begin(), tilt_tgt.end());
    const Rigid_motion first = fit_rigid_motion(stack(src), stack(tgt));
    for(int l = 1; l < loops; ++l)
    {
      const Point_matrix moved = first.apply(template_samples[l]);
      double best = std::numeric_limits<double>::infinity();
      for(int k = 0; k < resolution; ++k)
      {
        const double d = (moved - s.loops[permutation[l]].samples(samples, double(k) / resolution, 1)).squaredNorm();
        if(d < best)
        {
          best = d;
          c.loops[l] = {permutation[l], 1, double(k) / resolution};
        }
      }
    }
    std::vector<Point_matrix> all_src, all_tgt;
    for(int l = 0; l < loops; ++l)
    {
      all_src.push_back(template_samples[l]);
      all_tgt.push_back(s.loops[c.loops[l].target].samples(samples, c.loops[l].offset, c.loops[l].orientation));
    }
    all_src.insert(all_src.end(), extra_src.begin(), extra_src.end());
    all_tgt.insert(all_tgt.end(), extra_tgt.begin(), extra_tgt.end());
    const Eigen::Index ranked = stack(all_src).rows();
    if(tilt)
      for(int l = 1; l < loops; ++l) add_tilt(c.loops[l], l, permutation, tilt_src, tilt_tgt);
    all_src.insert(all_src.end(), tilt_src.begin(), tilt_src.end());
    all_tgt.insert(all_tgt.end(), tilt_tgt.begin(), tilt_tgt.end());
    c.source = stack(all_src);
    c.target = stack(all_tgt);
    finish(c);
    c.residual = rms(c.motion.apply(c.source.topRows(ranked)), c.target.topRows(ranked));
    return c;
  };
  const auto score = [&](Candidate& c) {
    if(c.score < 0)
      c.score = (c.residual + surface_distance(c.motion)) *
                (1. + rotation_preference * Eigen::AngleAxisd(c.motion.rotation).angle() / 3.141592653589793);
    return c.score;
  };

  if(loops == 0)
  {
    // Closed segments: centroid and principal axes, in the 4 proper sign choices.
    const auto frame = [](const Point_matrix& p, Vec3& c, Eigen::Matrix3d& axes) {
      c = p.colwise().mean().transpose();
      const Point_matrix centred = p.rowwise() - c.transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> e(centred.transpose() * centred / p.rows());
      axes = e.eigenvectors() * e.eigenvalues().cwiseMax(0.).cwiseSqrt().asDiagonal();
    };
    Vec3 ct, cs;
    Eigen::Matrix3d at, as;
    frame(t.mesh.points, ct, at);
    frame(s.mesh.points, cs, as);
    for(int signs = 0; signs < 4; ++signs)
    {
      Candidate c;
      const double s0 = (signs & 1) ? -1. : 1., s1 = (signs & 2) ? -1. : 1.;
      const Eigen::Vector3d flip(s0, s1, s0 * s1);
      c.source.resize(7, 3);
      c.target.resize(7, 3);
      c.source.row(0) = ct.transpose();
      c.target.row(0) = cs.transpose();
      for(int k = 0; k < 3; ++k)
      {
        c.source.row(1 + 2 * k) = (ct + at.col(k)).transpose();
        c.source.row(2 + 2 * k) = (ct - at.col(k)).transpose();
        c.target.row(1 + 2 * k) = (cs + flip[k] * as.col(k)).transpose();
        c.target.row(2 + 2 * k) = (cs - flip[k] * as.col(k)).transpose();
      }
      finish(c);
      candidates.push_back(std::move(c));
    }
  }
  else
  {
    std::vector<std::vector<int>> orders;
    if(loops <= 5)
    {
      std::vector<int> permutation(loops);
      std::iota(permutation.begin(), permutation.end(), 0);
      do
        orders.push_back(permutation);
      while(std::next_permutation(permutation.begin(), permutation.end()));
      const bool any_agrees = std::any_of(orders.begin(), orders.end(),
                                          [&](const std::vector<int>& o) { return tags_agree(t, s, o); });
      if(any_agrees)
        orders.erase(std::remove_if(orders.begin(), orders.end(),
                                    [&](const std::vector<int>& o) { return !tags_agree(t, s, o); }),
                     orders.end());
    }
    else
      orders = likely_loop_orders(t, s, 8);
    for(const std::vector<int>& order : orders)
      for(int shift = 0; shift < samples; ++shift)
        candidates.push_back(loop_candidate(order, 1, double(shift) / samples, samples, use_tilt));
  }

  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.residual < b.residual; });
  candidates.resize(std::min<std::size_t>(candidates.size(), 64));
  std::size_t best = 0;
  for(std::size_t i = 0; i < candidates.size(); ++i)
    if(score(candidates[i]) < score(candidates[best])) best = i;
  Candidate chosen = candidates[best];
  // The coarse search resolves the twist to 1/samples of a turn (15
  // degrees at 24 samples); search between the neighbouring shifts at
  // sixteen times that resolution.
  constexpr int fine = 16;
  if(loops > 0)
  {
    std::vector<int> matched;
    for(const Loop_match& m : chosen.loops) matched.push_back(m.target);
    const Loop_match first = chosen.loops[0];
    for(int k = 1 - fine; k < fine; ++k)
    {
      Candidate c = loop_candidate(matched, first.orientation, first.offset + k / double(fine * samples), fine * samples,
                                   chosen.tilt);
      if(score(c) < score(chosen)) chosen = c;
    }
  }

  // A lone seam that leans (over about 3 degrees, both ways) fixes the
  // twist more finely than the scores above, which barely change with it:
  // the shift, within two coarse steps, whose rigid fit (seam samples and
  // tip, as in the final landmarks) carries the template's lean onto the
  // segment's.
  constexpr double usable_lean = 0.05;
  if(loops == 1 && chosen.tilt && lean_of(t.loops[0], t.area_centroid, 1).norm() > usable_lean
     && lean_of(s.loops[chosen.loops[0].target], s.area_centroid, 1).norm() > usable_lean)
  {
    const Loop_match m = chosen.loops[0];
    const Point_matrix lean_t = tilt_point(t.loops[0], t.area_centroid, 1).transpose();
    const Point_matrix lean_s = tilt_point(s.loops[m.target], s.area_centroid, m.orientation).transpose();
    const auto misfit = [&](double offset) {
      const Rigid_motion motion =
        fit_rigid_motion(stack({template_samples[0], extremity_t.transpose()}),
                         stack({s.loops[m.target].samples(samples, offset, m.orientation), extremity_s.transpose()}));
      return (motion.apply(lean_t) - lean_s).norm();
    };
    double lowest = misfit(m.offset);
    for(int k = -2 * fine; k <= 2 * fine; ++k)
    {
      const double offset = m.offset + k / double(fine * samples), d = misfit(offset);
      if(d < lowest)
      {
        lowest = d;
        chosen.loops[0].offset = offset;
      }
    }
  }

  Landmarks r;
  r.loops = chosen.loops;
  std::vector<Point_matrix> src, tgt;
  for(int l = 0; l < loops; ++l)
  {
    src.push_back(t.loops[l].samples(samples, 0., 1));
    tgt.push_back(s.loops[r.loops[l].target].samples(samples, r.loops[l].offset, r.loops[l].orientation));
  }
  if(loops == 0)
  {
    src.push_back(chosen.source);
    tgt.push_back(chosen.target);
  }
  r.automatic = loops * samples + (loops == 0 ? 7 : 0);
  if(extremity)
  {
    src.push_back(extremity_t.transpose());
    tgt.push_back(extremity_s.transpose());
    ++r.automatic;
  }
  // The seam and the tip leave the stretch along a capped segment to the
  // regularizer, which spreads it over the cap; caps alike in shape are
  // matched alike here: the rings where the cap turns 70 and 45 degrees
  // from the axis, at directions carried over by the rigid fit so far.
  if(extremity)
  {
    const Rigid_motion aligned = fit_rigid_motion(stack(src), stack(tgt));
    const int n = std::max(4, samples / 2);
    for(double cosine : {0.342, 0.707})
    {
      const Cap_ring rt = cap_ring(t, cosine), rs = cap_ring(s, cosine);
      if(!rt.found || !rs.found) continue;
      const Vec3 u = rt.axis.unitOrthogonal(), w = rt.axis.cross(u);
      Point_matrix ring_t(n, 3), ring_s(n, 3);
      for(int j = 0; j < n; ++j)
      {
        const double phi = 2. * 3.141592653589793 * j / n;
        const Vec3 d = std::cos(phi) * u + std::sin(phi) * w;
        Vec3 e = aligned.rotation * d;
        e = (e - e.dot(rs.axis) * rs.axis).normalized();
        ring_t.row(j) = t.closest(rt.centre + rt.radius * d).transpose();
        ring_s.row(j) = s.closest(rs.centre + rs.radius * e).transpose();
      }
      src.push_back(ring_t);
      tgt.push_back(ring_s);
      r.automatic += n;
    }
  }
  src.push_back(user_source);
  tgt.push_back(user_target);
  for(std::size_t k = 0; k < user_t.size(); ++k) r.vertex_targets.push_back({user_t[k], user_target.row(k).transpose()});
  r.source = stack(src);
  r.target = stack(tgt);
  r.motion = fit_rigid_motion(r.source, r.target);
  return r;
}


} // namespace correspondence
} // namespace internal
} // namespace MPM
} // namespace CGAL
