// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Editing/Surface_soundness.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>
#include <CGAL/MPM/internal/Nearest_surface.h>
#include <CGAL/MPM/internal/Target_unfolding.h>

#include <Eigen/Geometry>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <map>
#include <vector>

namespace CGAL {
namespace MPM {

namespace {

using Exact_mesh = internal::Exact_predicates_surface_mesh;
using Exact_kernel = CGAL::Kernel_traits<Exact_mesh::Point>::Kernel;
using Exact_point = Exact_mesh::Point;
namespace PMP = CGAL::Polygon_mesh_processing;

std::vector<Exact_point> points_of(const Indexed_mesh& mesh)
{
  std::vector<Exact_point> p;
  for(int i = 0; i < mesh.number_of_vertices(); ++i) p.emplace_back(mesh.points(i, 0), mesh.points(i, 1), mesh.points(i, 2));
  return p;
}

std::vector<std::vector<std::size_t>> faces_of(const Indexed_mesh& mesh)
{
  std::vector<std::vector<std::size_t>> f;
  for(const Triangle& t : mesh.triangles) f.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  return f;
}

Eigen::Vector3d normal_of(const Indexed_mesh& mesh, const Triangle& t)
{
  const Eigen::Vector3d a = mesh.points.row(t[0]).transpose(), b = mesh.points.row(t[1]).transpose(),
                        c = mesh.points.row(t[2]).transpose();
  return (b - a).cross(c - a);
}

// Only the surface counts: a soup that is no polygon mesh (a face turned
// the other way, a non-manifold edge) is oriented and split first.
Exact_mesh surface_mesh_of(const Indexed_mesh& m)
{
  std::vector<Exact_point> points = points_of(m);
  std::vector<std::vector<std::size_t>> faces = faces_of(m);
  if(!PMP::is_polygon_soup_a_polygon_mesh(faces)) PMP::orient_polygon_soup(points, faces);
  Exact_mesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, faces, sm);
  return sm;
}

} // namespace

bool self_intersecting_faces(const Indexed_mesh& mesh, std::vector<std::pair<int, int>>& pairs)
{
  pairs.clear();
  const std::vector<std::vector<std::size_t>> faces = faces_of(mesh);
  if(!PMP::is_polygon_soup_a_polygon_mesh(faces)) return false;
  Exact_mesh sm;
  PMP::polygon_soup_to_polygon_mesh(points_of(mesh), faces, sm); // faces keep their order
  std::vector<std::pair<Exact_mesh::Face_index, Exact_mesh::Face_index>> found;
  PMP::self_intersections(sm, std::back_inserter(found));
  for(const auto& [f, g] : found) pairs.emplace_back(int(f), int(g));
  return true;
}

Surface_soundness check_surface(const Indexed_mesh& mesh, const Indexed_mesh* reference,
                                const std::vector<int>* face_groups)
{
  Surface_soundness s;
  const std::vector<int> component = connected_component_labels(mesh);
  s.components = component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
  std::map<std::pair<int, int>, int> count;
  for(const Triangle& t : mesh.triangles)
    for(int k = 0; k < 3; ++k) ++count[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  for(const auto& [edge, c] : count)
  {
    s.border_edges += c == 1;
    s.non_manifold_edges += c > 2;
  }
  std::vector<std::pair<int, int>> pairs;
  s.self_intersections = self_intersecting_faces(mesh, pairs) ? static_cast<int>(pairs.size()) : -1;
  const std::vector<Exact_point> points = points_of(mesh);
  for(const Triangle& t : mesh.triangles)
    s.degenerate_faces += CGAL::collinear(points[t[0]], points[t[1]], points[t[2]]);
  if(reference && reference->triangles == mesh.triangles)
  {
    s.flipped_faces = 0;
    for(const Triangle& t : mesh.triangles) s.flipped_faces += normal_of(mesh, t).dot(normal_of(*reference, t)) < 0.;
    s.inverted_faces = static_cast<int>(inverted_faces(mesh, *reference, face_groups).size());
  }
  return s;
}

std::vector<int> locally_inverted_faces(const Indexed_mesh& mesh, const Indexed_mesh& reference)
{
  if(reference.triangles != mesh.triangles || reference.points.rows() != mesh.points.rows())
    throw Input_error("locally_inverted_faces", "reference", "does not have the mesh's vertices and triangles");
  return internal::locally_inverted_faces(mesh.points, reference.points, mesh.triangles);
}

std::vector<int> inverted_faces(const Indexed_mesh& mesh, const Indexed_mesh& reference,
                                const std::vector<int>* face_groups)
{
  if(reference.triangles != mesh.triangles)
    throw Input_error("inverted_faces", "reference", "does not have the mesh's triangles");
  if(face_groups && face_groups->size() != mesh.triangles.size())
    throw Input_error("inverted_faces", "face groups",
                      "has " + std::to_string(face_groups->size()) + " entries for " +
                        std::to_string(mesh.triangles.size()) + " faces");
  const std::vector<int> group = face_groups ? *face_groups : std::vector<int>(mesh.triangles.size(), 0);
  std::map<int, std::vector<int>> vertices_of_group;
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int v : mesh.triangles[f]) vertices_of_group[group[f]].push_back(v);
  std::map<int, Eigen::Matrix3d> rotation;
  for(auto& [g, v] : vertices_of_group)
  {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    Eigen::Matrix3Xd from(3, v.size()), to(3, v.size());
    for(std::size_t i = 0; i < v.size(); ++i)
    {
      from.col(i) = reference.points.row(v[i]).transpose();
      to.col(i) = mesh.points.row(v[i]).transpose();
    }
    rotation[g] = Eigen::umeyama(from, to, false).topLeftCorner<3, 3>();
  }
  std::vector<int> inverted;
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if(normal_of(mesh, mesh.triangles[f]).dot(rotation[group[f]] * normal_of(reference, mesh.triangles[f])) < 0.)
      inverted.push_back(int(f));
  return inverted;
}

namespace internal {

struct Nearest_surface::Impl
{
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Exact_mesh>;
  explicit Impl(const Indexed_mesh& surface)
    : target(surface_mesh_of(surface)), tree(faces(target).first, faces(target).second, target)
  {
    tree.accelerate_distance_queries();
  }
  Exact_mesh target;
  CGAL::AABB_tree<CGAL::AABB_traits<Exact_kernel, Primitive>> tree;
};

Nearest_surface::Nearest_surface(const Indexed_mesh& surface) : impl_(std::make_unique<Impl>(surface)) {}

Nearest_surface::~Nearest_surface() = default;

Eigen::Vector3d Nearest_surface::closest_point(const Eigen::Vector3d& p) const
{
  const Exact_point q = impl_->tree.closest_point(Exact_point(p[0], p[1], p[2]));
  return {q.x(), q.y(), q.z()};
}

bool Nearest_surface::folded(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) const
{
  const Eigen::Vector3d centroid = (a + b + c) / 3.;
  const Exact_mesh::Face_index nearest =
    impl_->tree.closest_point_and_primitive(Exact_point(centroid[0], centroid[1], centroid[2])).second;
  const Exact_kernel::Vector_3 n = PMP::compute_face_normal(nearest, impl_->target);
  return (b - a).cross(c - a).dot(Eigen::Vector3d(n.x(), n.y(), n.z())) < 0.;
}

} // namespace internal

std::vector<int> folded_faces(const Indexed_mesh& mesh, const Indexed_mesh& surface)
{
  const internal::Nearest_surface test(surface);
  std::vector<int> folded;
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const Triangle& t = mesh.triangles[f];
    if(test.folded(mesh.points.row(t[0]).transpose(), mesh.points.row(t[1]).transpose(),
                   mesh.points.row(t[2]).transpose()))
      folded.push_back(int(f));
  }
  return folded;
}

std::vector<int> spike_faces(const Indexed_mesh& mesh, double angle, int sharp_edges)
{
  std::vector<int> sharp(mesh.triangles.size(), 0);
  for(const internal::Edge_fold& e : internal::edge_folds(mesh.points, mesh.triangles))
    if(e.angle > angle)
    {
      ++sharp[std::size_t(e.first)];
      ++sharp[std::size_t(e.second)];
    }
  std::vector<int> spikes;
  for(std::size_t f = 0; f < sharp.size(); ++f)
    if(sharp[f] >= sharp_edges) spikes.push_back(int(f));
  return spikes;
}

double relative_hausdorff_distance(const Indexed_mesh& a, const Indexed_mesh& b)
{
  const Exact_mesh ma = surface_mesh_of(a), mb = surface_mesh_of(b);
  const double diagonal = internal::bounding_box_diagonal(b.points);
  // A fixed seed: the sampling is otherwise seeded by the clock, and the
  // real-mesh table varied from run to run (0.29-0.33% on ant_97).
  const auto sampling = CGAL::parameters::number_of_points_per_area_unit(4000. / (diagonal * diagonal)).random_seed(1);
  const double d = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(ma, mb, sampling, sampling);
  return d / diagonal;
}

} // namespace MPM
} // namespace CGAL
