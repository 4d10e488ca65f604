// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Target_unfolding.h>

#include <CGAL/MPM/Arap_deformation.h>
#include <CGAL/MPM/Input_error.h>

#include <Eigen/Geometry>

#include <map>
#include <set>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// The region grown by one ring of triangles.
void grow(std::set<int>& region, const std::vector<Triangle>& triangles)
{
  std::set<int> grown = region;
  for(const Triangle& t : triangles)
    if(region.count(t[0]) || region.count(t[1]) || region.count(t[2])) grown.insert(t.begin(), t.end());
  region.swap(grown);
}

// The connected pieces of a vertex region (joined by the triangles'
// edges).
std::vector<std::set<int>> pieces_of(const std::set<int>& region, const std::vector<Triangle>& triangles)
{
  std::map<int, std::set<int>> next;
  for(const Triangle& t : triangles)
    for(int k = 0; k < 3; ++k)
      if(region.count(t[k]) && region.count(t[(k + 1) % 3])) next[t[k]].insert(t[(k + 1) % 3]), next[t[(k + 1) % 3]].insert(t[k]);
  std::vector<std::set<int>> pieces;
  std::set<int> seen;
  for(int v : region)
  {
    if(!seen.insert(v).second) continue;
    std::set<int> piece{v};
    std::vector<int> stack{v};
    while(!stack.empty())
    {
      const int x = stack.back();
      stack.pop_back();
      for(int y : next[x])
        if(seen.insert(y).second) piece.insert(y), stack.push_back(y);
    }
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// Writes into `result` the rows of `piece` reshaped as rigidly as possible
// (CGAL's ARAP, rest shape as reference) between the target's positions
// on the ring of vertices around it. Only the piece and that ring are
// solved, with the rest aligned on the ring first: ARAP starts from
// identity rotations, and the ring's rotation is the piece's, not the
// part's (a fold sits on a joint the target may bend).
void reshape_piece(const std::set<int>& piece, const Point_matrix& target, const Point_matrix& rest,
                   const std::vector<Triangle>& triangles, Point_matrix& result)
{
  std::set<int> patch = piece;
  grow(patch, triangles);
  std::map<int, int> local;
  std::vector<int> global;
  for(int v : patch)
  {
    local[v] = int(global.size());
    global.push_back(v);
  }
  Indexed_mesh sub;
  for(const Triangle& t : triangles)
    if(patch.count(t[0]) && patch.count(t[1]) && patch.count(t[2]))
      sub.triangles.push_back({local[t[0]], local[t[1]], local[t[2]]});
  Handle_set ring;
  for(int v : patch)
    if(!piece.count(v)) ring.vertices.push_back(local[v]);
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
  for(int v : piece) result.row(v) = solved.row(local[v]);
}

Eigen::Vector3d normal_of(const Point_matrix& p, const Triangle& t)
{
  return (p.row(t[1]) - p.row(t[0])).cross(p.row(t[2]) - p.row(t[0])).transpose();
}

// Faces whose normal points against the rest's once the best rotation of
// the neighbourhood (two rings around the corners, the corners left out so
// that a vertex pushed through the surface does not sway its own faces'
// rotation) is taken out: a fold, not a turn. One rotation for the whole cluster would count the
// faces of a joint bent by more than 90 degrees, whose two parts turn
// apart.
std::vector<int> locally_inverted_faces(const Point_matrix& target, const Point_matrix& rest,
                                        const std::vector<Triangle>& triangles)
{
  std::vector<std::set<int>> ring(std::size_t(rest.rows()));
  for(const Triangle& t : triangles)
    for(int k = 0; k < 3; ++k) ring[std::size_t(t[k])].insert(t.begin(), t.end());
  std::vector<int> inverted;
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    std::set<int> near, around;
    for(int v : triangles[f]) near.insert(ring[std::size_t(v)].begin(), ring[std::size_t(v)].end());
    for(int v : near) around.insert(ring[std::size_t(v)].begin(), ring[std::size_t(v)].end());
    for(int v : triangles[f]) around.erase(v);
    Eigen::Matrix3Xd from(3, around.size()), to(3, around.size());
    Eigen::Index i = 0;
    for(int v : around)
    {
      from.col(i) = rest.row(v).transpose();
      to.col(i++) = target.row(v).transpose();
    }
    const Eigen::Matrix3d rotation = Eigen::umeyama(from, to, false).topLeftCorner<3, 3>();
    if(normal_of(target, triangles[f]).dot(rotation * normal_of(rest, triangles[f])) < 0.) inverted.push_back(int(f));
  }
  return inverted;
}

} // namespace

Point_matrix unfold_target(const Point_matrix& target, const Point_matrix& rest, const std::vector<Triangle>& triangles)
{
  const std::vector<int> inverted = locally_inverted_faces(target, rest, triangles);
  if(inverted.empty()) return target;
  std::set<int> region;
  for(int f : inverted) region.insert(triangles[std::size_t(f)].begin(), triangles[std::size_t(f)].end());
  Point_matrix best = target;
  int best_count = static_cast<int>(inverted.size());
  // A ring more each round: the fold's edge needs room to turn back.
  for(int round = 0; round < 4 && best_count > 0; ++round)
  {
    grow(region, triangles);
    Point_matrix candidate = target;
    for(const std::set<int>& fold : pieces_of(region, triangles)) reshape_piece(fold, target, rest, triangles, candidate);
    const int count = static_cast<int>(locally_inverted_faces(candidate, rest, triangles).size());
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
