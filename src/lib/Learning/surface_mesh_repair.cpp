// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Surface_mesh_repair.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <array>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

std::string make_surface_mesh_compatible(Indexed_mesh& mesh, const std::string& source)
{
  const std::string user = "a training example";
  try {
    to_surface_mesh(mesh, source, user);
    return "";
  } catch(const Input_error&) {
    // Repaired below; a mesh the repair cannot mend throws again.
  }
  using Point = Indexed_surface_mesh::Point;
  std::vector<Point> points;
  points.reserve(std::size_t(mesh.number_of_vertices()));
  for(Eigen::Index v = 0; v < mesh.points.rows(); ++v)
    points.emplace_back(mesh.points(v, 0), mesh.points(v, 1), mesh.points(v, 2));
  std::vector<std::array<std::size_t, 3>> polygons;
  polygons.reserve(mesh.triangles.size());
  for(const Triangle& t : mesh.triangles) polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  const std::size_t before = points.size();
  Polygon_mesh_processing::orient_polygon_soup(points, polygons);

  int turned = 0;
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    Triangle& t = mesh.triangles[f];
    const Triangle was = t;
    for(int c = 0; c < 3; ++c) t[std::size_t(c)] = static_cast<int>(polygons[f][std::size_t(c)]);
    // The same corners in another cyclic order: the face turned over.
    turned += (t[0] == was[0] && t[1] == was[2]) || (t[0] == was[1] && t[1] == was[0]) ||
              (t[0] == was[2] && t[1] == was[1]);
  }
  mesh.points.conservativeResize(static_cast<Eigen::Index>(points.size()), 3);
  for(std::size_t v = before; v < points.size(); ++v)
    mesh.points.row(Eigen::Index(v)) << points[v].x(), points[v].y(), points[v].z();
  to_surface_mesh(mesh, source, user);
  return "non-manifold or inconsistently oriented: " + std::to_string(points.size() - before) +
         " vertices were copied to pull the faces apart at non-manifold edges and vertices, and " +
         std::to_string(turned) + " faces turned to agree with their neighbours, so that the model can keep it "
         "as a surface mesh (its edits have the copied vertices too)";
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
