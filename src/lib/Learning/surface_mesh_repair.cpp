// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Surface_mesh_repair.h>

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// Which polygons the orientation turned over.
struct Turned_polygons : Polygon_mesh_processing::Default_orientation_visitor
{
  std::vector<char>* turned;
  void polygon_orientation_reversed(std::size_t polygon) { (*turned)[polygon] ^= 1; }
};

// orient_polygon_soup() orients a component like the polygon it starts
// from, which may be the one face the user had flipped: keep instead the
// orientation most of the component's faces had, so that a closed surface
// stays outward. Returns the number of faces turned in the end.
int keep_most_faces_orientation(Indexed_mesh& mesh, std::vector<char>& turned, const std::string& source,
                                const std::string& user)
{
  const Indexed_surface_mesh held = to_surface_mesh(mesh, source, user);
  std::vector<std::size_t> component(mesh.triangles.size());
  const std::size_t count = Polygon_mesh_processing::connected_components(
    held, make_property_map(component), parameters::face_index_map(get(CGAL::face_index, held)));
  std::vector<std::size_t> faces(count, 0), turned_faces(count, 0);
  for(std::size_t f = 0; f < component.size(); ++f) {
    ++faces[component[f]];
    turned_faces[component[f]] += std::size_t(turned[f]);
  }
  int result = 0;
  for(std::size_t f = 0; f < component.size(); ++f) {
    if(2 * turned_faces[component[f]] > faces[component[f]]) {
      std::swap(mesh.triangles[f][1], mesh.triangles[f][2]);
      turned[f] ^= 1;
    }
    result += turned[f];
  }
  return result;
}

} // namespace

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
  const std::vector<std::array<std::size_t, 3>> original = polygons;
  std::vector<char> turned(polygons.size(), 0);
  Turned_polygons visitor;
  visitor.turned = &turned;
  Polygon_mesh_processing::orient_polygon_soup(points, polygons, parameters::visitor(visitor));

  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t c = 0; c < 3; ++c) mesh.triangles[f][c] = static_cast<int>(polygons[f][c]);
  mesh.points.conservativeResize(static_cast<Eigen::Index>(points.size()), 3);
  for(std::size_t v = before; v < points.size(); ++v)
    mesh.points.row(Eigen::Index(v)) << points[v].x(), points[v].y(), points[v].z();
  const int turned_faces = keep_most_faces_orientation(mesh, turned, source, user);
  // Turning a face twice rotates its corners: start it where it started.
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    Triangle& t = mesh.triangles[f];
    const auto first = std::find(t.begin(), t.end(), static_cast<int>(original[f][0]));
    if(first != t.end()) std::rotate(t.begin(), first, t.end());
  }
  return "non-manifold or inconsistently oriented: " + std::to_string(points.size() - before) +
         " vertices were copied to pull the faces apart at non-manifold edges and vertices, and " +
         std::to_string(turned_faces) + " faces turned to agree with their neighbours, so that the model can keep "
         "it as a surface mesh (its edits have the copied vertices too)";
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
