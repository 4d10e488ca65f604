// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Io_test_support.h"

#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#ifdef MPM_HAS_OPENMESH
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#endif

#include <boost/property_map/function_property_map.hpp>

using namespace CGAL::MPM;

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
#ifdef MPM_HAS_OPENMESH
using Open_mesh = OpenMesh::TriMesh_ArrayKernelT<>;
#endif

// A 3 x 3 vertex grid (8 triangles) plus a tetrahedron as a second component.
const std::vector<std::array<double, 3>> points = {
  {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0.5}, {2, 1, 0}, {0, 2, 0}, {1, 2, 0}, {2, 2, 0},
  {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
const std::vector<std::array<int, 3>> triangles = {
  {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7}, {3, 7, 6}, {4, 5, 8}, {4, 8, 7},
  {9, 11, 10}, {9, 10, 12}, {9, 12, 11}, {10, 11, 12}};

Surface_mesh make_surface_mesh()
{
  Surface_mesh sm;
  std::vector<Surface_mesh::Vertex_index> v;
  for(const auto& p : points) v.push_back(sm.add_vertex(Kernel::Point_3(p[0], p[1], p[2])));
  for(const auto& t : triangles) sm.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return sm;
}

#ifdef MPM_HAS_OPENMESH
Open_mesh make_open_mesh()
{
  Open_mesh om;
  std::vector<Open_mesh::VertexHandle> v;
  for(const auto& p : points) v.push_back(om.add_vertex(Open_mesh::Point(float(p[0]), float(p[1]), float(p[2]))));
  for(const auto& t : triangles) om.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return om;
}
#endif

Indexed_mesh expected_mesh()
{
  Indexed_mesh m;
  m.points.resize(int(points.size()), 3);
  for(std::size_t i = 0; i < points.size(); ++i) m.points.row(int(i)) << points[i][0], points[i][1], points[i][2];
  for(const auto& t : triangles) m.triangles.push_back({t[0], t[1], t[2]});
  return m;
}

// Corner order may start anywhere on the face; compare up to rotation.
Triangle canonical(Triangle t)
{
  while(t[0] != std::min({t[0], t[1], t[2]})) t = {t[1], t[2], t[0]};
  return t;
}

void expect_equal_meshes(const Indexed_mesh& a, const Indexed_mesh& b)
{
  EXPECT_EQ(a.points, b.points);
  ASSERT_EQ(a.number_of_faces(), b.number_of_faces());
  for(int f = 0; f < a.number_of_faces(); ++f) EXPECT_EQ(canonical(a.triangles[f]), canonical(b.triangles[f])) << f;
}

} // namespace

TEST(FaceGraphConversion, SurfaceMeshAndOpenMeshGiveTheSameMesh)
{
  const Indexed_mesh expected = expected_mesh();
  const Surface_mesh sm = make_surface_mesh();
  const Indexed_mesh from_sm = to_indexed_mesh(sm);
  expect_equal_meshes(from_sm, expected);
#ifdef MPM_HAS_OPENMESH
  const Open_mesh om = make_open_mesh();
  const Indexed_mesh from_om = to_indexed_mesh(om);
  expect_equal_meshes(from_om, expected);
  EXPECT_EQ(from_sm.triangles, from_om.triangles);
#endif
}

TEST(FaceGraphConversion, VertexPointMapParameter)
{
  Surface_mesh sm = make_surface_mesh();
  auto moved = sm.add_property_map<Surface_mesh::Vertex_index, Kernel::Point_3>("v:moved").first;
  for(auto v : vertices(sm)) moved[v] = sm.point(v) + Kernel::Vector_3(0, 0, 10);
  const Indexed_mesh m = to_indexed_mesh(sm, CGAL::parameters::vertex_point_map(moved));
  Indexed_mesh expected = expected_mesh();
  expected.points.col(2).array() += 10;
  expect_equal_meshes(m, expected);
}

TEST(FaceGraphConversion, RemovedElementsAreSkipped)
{
  Surface_mesh sm = make_surface_mesh();
  // Removal only marks the face; the conversion must follow faces(g), not the storage.
  sm.remove_face(*faces(sm).begin());
  const Indexed_mesh m = to_indexed_mesh(sm);
  EXPECT_EQ(m.number_of_vertices(), int(points.size()));
  ASSERT_EQ(m.number_of_faces(), int(triangles.size()) - 1);
  EXPECT_EQ(canonical(m.triangles[0]), canonical({0, 4, 3}));
}

TEST(FaceGraphConversion, FaceLabelsFollowFaceOrder)
{
  Surface_mesh sm = make_surface_mesh();
  auto label = sm.add_property_map<Surface_mesh::Face_index, unsigned char>("f:label", 0).first;
  int i = 0;
  for(auto f : faces(sm)) label[f] = static_cast<unsigned char>(i++ < 8 ? 0 : 1);
  EXPECT_EQ(face_labels_from_map(sm, label), (std::vector<int>{0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1}));

#ifdef MPM_HAS_OPENMESH
  Open_mesh om = make_open_mesh();
  OpenMesh::FPropHandleT<int> part;
  om.add_property(part);
  for(auto f : om.faces()) om.property(part, f) = f.idx() * 2;
  const auto map = boost::make_function_property_map<Open_mesh::FaceHandle>(
    [&](Open_mesh::FaceHandle f) { return om.property(part, f); });
  const std::vector<int> labels = face_labels_from_map(om, map);
  ASSERT_EQ(labels.size(), triangles.size());
  for(std::size_t f = 0; f < labels.size(); ++f) EXPECT_EQ(labels[f], int(2 * f));
#endif
}

TEST(FaceGraphConversion, NonTriangleFacesAreRejected)
{
  Surface_mesh sm;
  std::vector<Surface_mesh::Vertex_index> v;
  for(const auto& p : points) v.push_back(sm.add_vertex(Kernel::Point_3(p[0], p[1], p[2])));
  sm.add_face(v[0], v[1], v[4]);
  sm.add_face(std::vector<Surface_mesh::Vertex_index>{v[1], v[2], v[5], v[4]});
  try {
    to_indexed_mesh(sm);
    ADD_FAILURE() << "no error";
  } catch(const Input_error& e) {
    EXPECT_EQ(e.element(), "face 1");
    EXPECT_TRUE(mpm_test::contains_all(e.what(), {"has 4 corners"}));
  }
}

// The learning API over FaceGraph gives the same model on Surface_mesh and
// on OpenMesh as on the plain indexed mesh.
namespace {

void set_point(Surface_mesh& g, Surface_mesh::Vertex_index v, double x, double y, double z)
{
  g.point(v) = Kernel::Point_3(x, y, z);
}

#ifdef MPM_HAS_OPENMESH
struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Open_mesh_d = OpenMesh::TriMesh_ArrayKernelT<Double_traits>;

// CGAL 5.5's OpenMesh point map writes through float, so set points natively.
void set_point(Open_mesh_d& g, Open_mesh_d::VertexHandle v, double x, double y, double z)
{
  g.set_point(v, Open_mesh_d::Point(x, y, z));
}
#endif

template <class Mesh>
Morphable_part_model learn_through_face_graph(const Synthetic_model& s, Mesh& g)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> v;
  for(int i = 0; i < s.mesh.mesh.number_of_vertices(); ++i)
  {
    const auto p = s.mesh.mesh.points.row(i);
    v.push_back(add_vertex(g));
    set_point(g, v.back(), p(0), p(1), p(2));
  }
  auto labels = get(CGAL::dynamic_face_property_t<int>(), g);
  for(int f = 0; f < s.mesh.mesh.number_of_faces(); ++f)
  {
    const Triangle& t = s.mesh.mesh.triangles[f];
    const auto face = CGAL::Euler::add_face(std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>{v[t[0]], v[t[1]], v[t[2]]}, g);
    put(labels, face, s.mesh.face_labels[f]);
  }
  return learn_morphable_part_model(g, labels, s.annotation);
}

void expect_same_model(const Morphable_part_model& a, const Morphable_part_model& b)
{
  ASSERT_EQ(a.types.size(), b.types.size());
  for(std::size_t t = 0; t < a.types.size(); ++t)
  {
    EXPECT_EQ(a.types[t].name, b.types[t].name);
    EXPECT_EQ(a.types[t].number_of_vertices, b.types[t].number_of_vertices);
    EXPECT_EQ(a.types[t].space.number_of_modes(), b.types[t].space.number_of_modes());
    EXPECT_LT((a.types[t].space.mean - b.types[t].space.mean).norm(), 1e-9 * a.types[t].space.mean.norm());
  }
  ASSERT_EQ(a.rules.size(), b.rules.size());
  for(std::size_t r = 0; r < a.rules.size(); ++r) EXPECT_EQ(a.rules[r].points.size(), b.rules[r].points.size());
  EXPECT_EQ(a.examples[0].graph.edges.size(), b.examples[0].graph.edges.size());
}

} // namespace

TEST(FaceGraphLearning, surface_mesh_and_open_mesh_match_the_indexed_mesh)
{
  Synthetic_options options;
  options.vertices = 2000;
  const Synthetic_model s = make_synthetic_model(Synthetic_family::hexa_grid, options);
  const Morphable_part_model reference = learn_morphable_part_model(s.mesh, s.annotation);

  Surface_mesh sm;
  expect_same_model(reference, learn_through_face_graph(s, sm));
#ifdef MPM_HAS_OPENMESH
  Open_mesh_d om;
  expect_same_model(reference, learn_through_face_graph(s, om));
#endif
}
