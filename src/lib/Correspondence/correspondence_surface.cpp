// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Correspondence_surface.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Vertex_normals.h>

#include <Eigen/Eigenvalues>

#include <map>

namespace CGAL {
namespace MPM {
namespace internal {
namespace correspondence {

std::vector<std::vector<int>> loops_of(const Indexed_mesh& mesh)
{
  std::map<std::pair<int, int>, int> uses;
  for(const Triangle& t : mesh.triangles)
    for(int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::multimap<int, int> next;
  for(const Triangle& t : mesh.triangles)
    for(int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      if(uses[{std::min(a, b), std::max(a, b)}] == 1) next.insert({a, b});
    }
  std::vector<std::vector<int>> loops;
  while(!next.empty())
  {
    std::vector<int> loop{next.begin()->first};
    int current = next.begin()->second;
    next.erase(next.begin());
    while(current != loop.front())
    {
      loop.push_back(current);
      const auto it = next.find(current);
      if(it == next.end()) break; // an open chain (non-manifold border): keep what was walked
      current = it->second;
      next.erase(it);
    }
    if(loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

Loop make_loop(const Point_matrix& points, std::vector<int> vertices)
{
  Loop l;
  l.vertices = std::move(vertices);
  const int k = static_cast<int>(l.vertices.size());
  l.points.resize(k, 3);
  for(int i = 0; i < k; ++i) l.points.row(i) = points.row(l.vertices[i]);
  l.arc.assign(1, 0.);
  for(int i = 0; i < k; ++i) l.arc.push_back(l.arc.back() + (l.points.row((i + 1) % k) - l.points.row(i)).norm());
  // The centroid of the polyline, not of its vertices: a remeshed or
  // scanned seam is sampled unevenly, and the vertex mean then drifts
  // towards the dense side, which tilts the axis and turns the lean of a
  // slightly tilted seam by 10 degrees or more.
  l.centroid.setZero();
  for(int i = 0; i < k; ++i)
    l.centroid += 0.5 * (l.points.row(i) + l.points.row((i + 1) % k)).transpose() * (l.arc[i + 1] - l.arc[i]);
  if(l.arc.back() > 0) l.centroid /= l.arc.back();
  return l;
}

Surface::Surface(const Indexed_mesh& m, const std::string& type_name, const std::string& name) : mesh(m)
{
  const std::string element = "part type \"" + type_name + "\"";
  if(m.number_of_faces() == 0 || m.number_of_vertices() < 3)
    throw Input_error(name, element, "degenerate segment: no triangle");
  if(!m.points.allFinite()) throw Input_error(name, element, "degenerate segment: non-finite coordinates");
  const Point_matrix centred = m.points.rowwise() - m.points.colwise().mean();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(centred.transpose() * centred);
  if(!(pca.eigenvalues()(1) > 1e-12 * pca.eigenvalues()(2)))
    throw Input_error(name, element, "degenerate segment: its points are collinear");
  for(const Triangle& t : m.triangles)
  {
    for(int k = 0; k < 3; ++k)
      if(t[k] < 0 || t[k] >= m.number_of_vertices())
        throw Input_error(name, element, "degenerate segment: triangle corner out of range");
    triangles.emplace_back(to_point(m.points.row(t[0])), to_point(m.points.row(t[1])), to_point(m.points.row(t[2])));
    const Vec3 n = (m.points.row(t[1]) - m.points.row(t[0])).transpose().cross((m.points.row(t[2]) - m.points.row(t[0])).transpose());
    normals.push_back(n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero());
  }
  const Point_matrix unit_normals = area_weighted_vertex_normals(m.points, m.triangles);
  for(Eigen::Index v = 0; v < unit_normals.rows(); ++v) vertex_normals.push_back(unit_normals.row(v).transpose());
  tree.insert(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  for(std::vector<int>& vertices : loops_of(m)) loops.push_back(make_loop(m.points, std::move(vertices)));
  std::sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.length() > b.length(); });
  border.resize(loops.size());
  for(std::size_t l = 0; l < loops.size(); ++l)
  {
    const Loop& loop = loops[l];
    const int k = static_cast<int>(loop.vertices.size());
    for(int i = 0; i < k; ++i)
      border[l].segments.emplace_back(to_point(loop.points.row(i)), to_point(loop.points.row((i + 1) % k)));
    border[l].tree = std::make_unique<Segment_tree>(border[l].segments.begin(), border[l].segments.end());
    border[l].tree->accelerate_distance_queries();
  }
  diagonal = bounding_box_diagonal(m.points);
  double area = 0.;
  area_centroid.setZero();
  for(const Triangle& t : m.triangles)
  {
    const Vec3 a = m.points.row(t[0]), b = m.points.row(t[1]), c = m.points.row(t[2]);
    const double w = 0.5 * (b - a).cross(c - a).norm();
    area += w;
    area_centroid += w * (a + b + c) / 3.;
  }
  if(area > 0) area_centroid /= area;
  double total = 0.;
  for(const Triangle& t : m.triangles)
    for(int k = 0; k < 3; ++k) total += (m.points.row(t[k]) - m.points.row(t[(k + 1) % 3])).norm();
  edge_length = total / (3. * m.triangles.size());
  if(loops.size() == 1) tip = pole_of(*this);
}

void tag_loops(Surface& s, const std::vector<int>& seam_tags)
{
  for(const Loop& l : s.loops)
  {
    std::map<int, int> count;
    for(int v : l.vertices)
      if(v < int(seam_tags.size()) && seam_tags[v] >= 0) ++count[seam_tags[v]];
    int tag = -1, best = 0;
    for(const auto& [t, c] : count)
      if(c > best)
      {
        best = c;
        tag = t;
      }
    s.loop_tags.push_back(tag);
  }
}

// The tip of a segment with one loop (a fingertip): the surface point
// farthest along the axis from the loop's centroid towards the area
// centroid. On a round cap this is better defined than the vertex
// geodesically farthest from a tilted seam. The farthest vertex alone is
// off the tip by up to half an edge, which tilts a long tube; the centroid
// of the top slice (a fifth of the seam's radius deep), put back on the
// surface, is not.
Vec3 pole_of(const Surface& s)
{
  const Loop& loop = s.loops[0];
  const Vec3 c = loop.centroid;
  if(!((s.area_centroid - c).norm() > 0)) return s.closest(c); // a flat part: no axis
  const Vec3 axis = (s.area_centroid - c).normalized();
  const Eigen::VectorXd height = (s.mesh.points.rowwise() - c.transpose()) * axis;
  const double top = height.maxCoeff() - 0.2 * loop.mean_radius();
  Vec3 sum = Vec3::Zero();
  double area = 0.;
  for(const Triangle& t : s.mesh.triangles)
  {
    if(height(t[0]) + height(t[1]) + height(t[2]) < 3. * top) continue;
    const Vec3 a = s.mesh.points.row(t[0]), b = s.mesh.points.row(t[1]), d = s.mesh.points.row(t[2]);
    const double w = 0.5 * (b - a).cross(d - a).norm();
    sum += w * (a + b + d) / 3.;
    area += w;
  }
  if(!(area > 0))
  {
    Eigen::Index best;
    height.maxCoeff(&best);
    return s.mesh.points.row(best).transpose();
  }
  return s.closest(sum / area);
}

} // namespace correspondence
} // namespace internal
} // namespace MPM
} // namespace CGAL
