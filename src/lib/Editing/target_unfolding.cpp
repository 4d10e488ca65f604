// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Target_unfolding.h>

#include <CGAL/MPM/Editing/Arap_deformation.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Edge_faces.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// Per vertex, its neighbours along the triangles' edges, in increasing
// order (the patches, and so their ARAP solves, are numbered in it).
std::vector<std::vector<int>> neighbours_of(Eigen::Index n, const std::vector<Triangle>& triangles)
{
  std::vector<std::vector<int>> next{std::size_t(n)};
  for(const Cluster_edge& e : mesh_edges(triangles))
  {
    next[std::size_t(e.source)].push_back(e.target);
    next[std::size_t(e.target)].push_back(e.source);
  }
  for(std::vector<int>& v : next) std::sort(v.begin(), v.end());
  return next;
}

Eigen::Vector3d normal_of(const Point_matrix& p, const Triangle& t)
{
  return (p.row(t[1]) - p.row(t[0])).cross(p.row(t[2]) - p.row(t[0])).transpose();
}

// The angle between the normals of faces `f` and `g`.
double fold_angle(const Point_matrix& p, const std::vector<Triangle>& triangles, int f, int g)
{
  const Eigen::Vector3d m = normal_of(p, triangles[std::size_t(f)]), n = normal_of(p, triangles[std::size_t(g)]);
  return std::atan2(m.cross(n).norm(), m.dot(n));
}

// Per vertex, the best rotation from `rest` to `target` of the vertices two
// edges away: the vertex and its first ring are left out so that a vertex
// pushed through the surface does not sway the rotations its own faces are
// measured by.
std::vector<Eigen::Matrix3d> neighbourhood_rotations(const Point_matrix& target, const Point_matrix& rest,
                                                     const std::vector<std::vector<int>>& next)
{
  std::vector<Eigen::Matrix3d> rotations(next.size(), Eigen::Matrix3d::Identity());
  std::vector<int> stamp(next.size(), -1);
  std::vector<int> around;
  for(std::size_t v = 0; v < next.size(); ++v)
  {
    around.clear();
    stamp[v] = int(v);
    for(int a : next[v]) stamp[std::size_t(a)] = int(v);
    for(int a : next[v])
      for(int b : next[std::size_t(a)])
        if(stamp[std::size_t(b)] != int(v))
        {
          stamp[std::size_t(b)] = int(v);
          around.push_back(b);
        }
    if(around.size() < 3) around.insert(around.end(), next[v].begin(), next[v].end());
    if(around.size() < 3) continue;
    Eigen::Matrix3Xd from(3, around.size()), to(3, around.size());
    for(std::size_t i = 0; i < around.size(); ++i)
    {
      from.col(Eigen::Index(i)) = rest.row(around[i]).transpose();
      to.col(Eigen::Index(i)) = target.row(around[i]).transpose();
    }
    rotations[v] = Eigen::umeyama(from, to, false).topLeftCorner<3, 3>();
  }
  return rotations;
}

// Faces whose normal points against the rest's for each of their corners'
// neighbourhood rotations: a fold, not a turn. One rotation for a
// whole part would count the faces of a joint bent by more than 90 degrees,
// whose two sides turn apart.
std::vector<int> locally_inverted_faces(const Point_matrix& target, const Point_matrix& rest,
                                        const std::vector<Triangle>& triangles,
                                        const std::vector<std::vector<int>>& next)
{
  const std::vector<Eigen::Matrix3d> rotation = neighbourhood_rotations(target, rest, next);
  std::vector<int> inverted;
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    const Eigen::Vector3d now = normal_of(target, triangles[f]), before = normal_of(rest, triangles[f]);
    int against = 0;
    for(int v : triangles[f]) against += now.dot(rotation[std::size_t(v)] * before) < 0.;
    if(against == 3) inverted.push_back(int(f));
  }
  return inverted;
}

// Faces along an edge whose fold (the angle between its two faces' normals)
// grew by more than 60 degrees against the rest: a crease pressed into the
// surface, as a caricature makes of a fold it doubles. A bend spreads
// over many edges; the two-ring rotations above take such a crease for
// one, as it turns a face by less than 180 degrees.
// `rest_folds` are the rest's (edge_folds()), measured once per unfolding.
std::vector<int> creased_faces(const Point_matrix& target, const std::vector<Triangle>& triangles,
                               const std::vector<Edge_fold>& rest_folds)
{
  const double limit = 60. * CGAL_PI / 180.;
  std::vector<int> creased;
  for(const Edge_fold& e : rest_folds)
    if(fold_angle(target, triangles, e.first, e.second) - e.angle > limit)
    {
      creased.push_back(e.first);
      creased.push_back(e.second);
    }
  std::sort(creased.begin(), creased.end());
  creased.erase(std::unique(creased.begin(), creased.end()), creased.end());
  return creased;
}

// What `unfold_target()` takes out: folds and creases.
std::vector<int> faulty_faces(const Point_matrix& target, const Point_matrix& rest,
                              const std::vector<Triangle>& triangles, const std::vector<std::vector<int>>& next,
                              const std::vector<Edge_fold>& rest_folds)
{
  const std::vector<int> folded = locally_inverted_faces(target, rest, triangles, next);
  const std::vector<int> creased = creased_faces(target, triangles, rest_folds);
  std::vector<int> all;
  std::set_union(folded.begin(), folded.end(), creased.begin(), creased.end(), std::back_inserter(all));
  return all;
}

// The region (a flag per vertex) grown by one ring.
void grow(std::vector<bool>& region, const std::vector<std::vector<int>>& next)
{
  const std::vector<bool> before = region;
  for(std::size_t v = 0; v < next.size(); ++v)
    if(before[v])
      for(int w : next[v]) region[std::size_t(w)] = true;
}

// The connected pieces of a region.
std::vector<std::vector<int>> pieces_of(const std::vector<bool>& region, const std::vector<std::vector<int>>& next)
{
  std::vector<std::vector<int>> pieces;
  std::vector<bool> seen(region.size(), false);
  for(std::size_t v = 0; v < region.size(); ++v)
  {
    if(!region[v] || seen[v]) continue;
    seen[v] = true;
    std::vector<int> piece{int(v)};
    for(std::size_t i = 0; i < piece.size(); ++i)
      for(int w : next[std::size_t(piece[i])])
        if(region[std::size_t(w)] && !seen[std::size_t(w)])
        {
          seen[std::size_t(w)] = true;
          piece.push_back(w);
        }
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// Writes into `result` the rows of `piece` reshaped as rigidly as possible
// (CGAL's ARAP, rest shape as reference) between the target's positions
// on the ring of vertices around it (and at its held vertices). Only the
// piece and that ring are solved, with the rest aligned on the ring first:
// ARAP starts from identity rotations, and the ring's rotation is the
// piece's, not the part's (a fold sits on a joint the target may bend).
void reshape_piece(const std::vector<int>& piece, const Point_matrix& target, const Point_matrix& rest,
                   const std::vector<Triangle>& triangles, const std::vector<std::vector<int>>& next,
                   const std::vector<bool>& held, Point_matrix& result)
{
  std::map<int, int> local;
  std::vector<int> global;
  const auto add = [&](int v) {
    if(local.emplace(v, int(global.size())).second) global.push_back(v);
  };
  for(int v : piece) add(v);
  for(int v : piece)
    for(int w : next[std::size_t(v)]) add(w);
  std::vector<bool> free(global.size(), false);
  for(int v : piece) free[std::size_t(local[v])] = !held[std::size_t(v)];
  Indexed_mesh sub;
  for(const Triangle& t : triangles)
  {
    const auto a = local.find(t[0]), b = local.find(t[1]), c = local.find(t[2]);
    if(a != local.end() && b != local.end() && c != local.end()) sub.triangles.push_back({a->second, b->second, c->second});
  }
  Handle_set ring;
  for(std::size_t i = 0; i < global.size(); ++i)
    if(!free[i]) ring.vertices.push_back(int(i));
  if(ring.vertices.size() < 3) return; // the whole part folds: nothing to hold it by
  Eigen::Matrix3Xd from(3, ring.vertices.size()), to(3, ring.vertices.size());
  ring.targets.resize(Eigen::Index(ring.vertices.size()), 3);
  for(std::size_t k = 0; k < ring.vertices.size(); ++k)
  {
    from.col(Eigen::Index(k)) = rest.row(global[std::size_t(ring.vertices[k])]).transpose();
    to.col(Eigen::Index(k)) = target.row(global[std::size_t(ring.vertices[k])]).transpose();
    ring.targets.row(Eigen::Index(k)) = to.col(Eigen::Index(k)).transpose();
  }
  const Eigen::Matrix4d align = Eigen::umeyama(from, to, false);
  sub.points.resize(Eigen::Index(global.size()), 3);
  for(std::size_t i = 0; i < global.size(); ++i)
    sub.points.row(Eigen::Index(i)) =
      (align.topLeftCorner<3, 3>() * rest.row(global[i]).transpose() + align.topRightCorner<3, 1>()).transpose();
  Point_matrix solved;
  try
  {
    Arap_deformation arap(sub);
    arap.set_handles(ring);
    arap.deform(50, 1e-7);
    solved = arap.positions();
  }
  catch(const Input_error&)
  {
    return; // a piece of the patch without a ring vertex: it keeps the target
  }
  for(std::size_t i = 0; i < global.size(); ++i)
    if(free[i]) result.row(global[i]) = solved.row(Eigen::Index(i));
}

} // namespace

std::vector<Edge_fold> edge_folds(const Point_matrix& points, const std::vector<Triangle>& triangles)
{
  Indexed_mesh connectivity;
  connectivity.triangles = triangles;
  const std::map<Mesh_edge, std::vector<int>> faces_of_edge = faces_of_edges(connectivity);
  std::vector<Edge_fold> folds;
  for(const auto& [edge, faces] : faces_of_edge)
    if(faces.size() == 2) folds.push_back({faces[0], faces[1], fold_angle(points, triangles, faces[0], faces[1])});
  return folds;
}

std::vector<int> locally_inverted_faces(const Point_matrix& target, const Point_matrix& rest,
                                        const std::vector<Triangle>& triangles)
{
  return locally_inverted_faces(target, rest, triangles, neighbours_of(target.rows(), triangles));
}

Point_matrix unfold_target(const Point_matrix& target, const Point_matrix& rest, const std::vector<Triangle>& triangles,
                           const std::vector<int>& held)
{
  const std::vector<std::vector<int>> next = neighbours_of(target.rows(), triangles);
  const std::vector<Edge_fold> rest_folds = edge_folds(rest, triangles);
  const std::vector<int> inverted = faulty_faces(target, rest, triangles, next, rest_folds);
  if(inverted.empty()) return target;
  std::vector<bool> is_held(next.size(), false);
  for(int v : held) is_held[std::size_t(v)] = true;
  std::vector<bool> region(next.size(), false);
  for(int f : inverted)
    for(int v : triangles[std::size_t(f)]) region[std::size_t(v)] = true;
  Point_matrix best = target;
  std::size_t best_count = inverted.size();
  // A ring more each round: the fold's edge needs room to turn back.
  for(int round = 0; round < 10 && best_count > 0; ++round)
  {
    grow(region, next);
    Point_matrix candidate = target;
    for(const std::vector<int>& piece : pieces_of(region, next))
      reshape_piece(piece, target, rest, triangles, next, is_held, candidate);
    const std::size_t count = faulty_faces(candidate, rest, triangles, next, rest_folds).size();
    if(count < best_count)
    {
      best = candidate;
      best_count = count;
    }
  }
  return best;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
