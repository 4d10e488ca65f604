// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole pipeline over the user's own mesh type: cut -> learn -> deform
// -> assemble on Surface_mesh, Polyhedron_3 and OpenMesh, with labels and
// results in property maps, gives what the indexed-mesh path gives.
#include <CGAL/MPM/Cutting/Face_graph_cutting.h>
#include <CGAL/MPM/Editing/Face_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include "Hand_cuts.h"
#include "Learned_models.h"

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#ifdef MPM_HAS_OPENMESH
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#endif

#include <gtest/gtest.h>

#include <set>
#include <utility>
#include <vector>

namespace {

using namespace CGAL::MPM;
using mpm_test::small_hand;
using Kernel = CGAL::Simple_cartesian<double>;
using Surface_mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;

// Three tip vertices of the example pulled sideways, the wrist held.
Handle_set tip_handles(const Indexed_mesh& mesh)
{
  Handle_set h;
  const Eigen::Index n = mesh.points.rows();
  const double diagonal = (mesh.points.colwise().maxCoeff() - mesh.points.colwise().minCoeff()).norm();
  h.vertices = {0, int(n / 3), int(2 * n / 3)};
  h.targets.resize(3, 3);
  for(int k = 0; k < 3; ++k) h.targets.row(k) = mesh.points.row(h.vertices[std::size_t(k)]);
  h.targets.row(1) += Eigen::RowVector3d(0.05, 0.02, 0.) * diagonal;
  h.targets.row(2) += Eigen::RowVector3d(-0.03, 0.04, 0.01) * diagonal;
  return h;
}

// What the indexed-mesh path gives: the reference each mesh type is held to.
struct Pipeline_reference
{
  Cutting_result cut;
  Morphable_part_model model;
  internal::Solved_edit deformed;
  Assembly assembly;
};

const Pipeline_reference& reference()
{
  static const Pipeline_reference r = [] {
    Pipeline_reference ref;
    ref.cut = cut_mesh(small_hand().mesh.mesh, mpm_test::hand_cuts(small_hand()), Cutting_options(), "hand");
    ref.model = learn_morphable_part_model(ref.cut.mesh, small_hand().annotation);
    ref.deformed = internal::solve_edit(ref.model, make_deformation_problem(ref.model), tip_handles(to_labeled_mesh(ref.model.examples[0]).mesh));
    ref.assembly = assemble(ref.model, part_graph_of_example(ref.model));
    return ref;
  }();
  return r;
}

// Whether each vertex of `g` has faces of more than one part, read off the
// mesh's own adjacency: the reference for `vertex_is_seam_map`.
template <class Mesh, class PartMap, class SeamMap>
void expect_seams_where_parts_meet(const Mesh& g, PartMap parts, SeamMap seams)
{
  int seam_vertices = 0;
  for(auto v : vertices(g)) {
    std::set<int> around;
    for(auto f : CGAL::faces_around_target(halfedge(v, g), g))
      if(f != boost::graph_traits<Mesh>::null_face()) around.insert(get(parts, f));
    EXPECT_EQ(bool(get(seams, v)), around.size() > 1);
    seam_vertices += get(seams, v) ? 1 : 0;
  }
  EXPECT_GT(seam_vertices, 0);
}

double largest_difference(const Point_matrix& a, const Point_matrix& b)
{
  return a.rows() == b.rows() ? (a - b).rowwise().norm().maxCoeff() : HUGE_VAL;
}

template <class Mesh>
void run_pipeline(double tolerance)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using Point = typename boost::property_traits<typename CGAL::GetVertexPointMap<Mesh>::type>::value_type;
  const Pipeline_reference& ref = reference();
  const double diagonal = mpm_test::diagonal(small_hand().mesh.mesh.points);

  // Cut: labels land in a face property of the user's mesh.
  Mesh input;
  copy_to_face_graph(small_hand().mesh.mesh, input);
  auto labels = get(CGAL::dynamic_face_property_t<int>(), input);
  const auto cut = cut_mesh(input, mpm_test::hand_cuts(small_hand()), labels);
  EXPECT_EQ(face_labels_from_map(input, labels), ref.cut.mesh.face_labels);
  // The paths name the vertices of the user's mesh, in the order of vertices(input).
  const std::vector<vertex_descriptor> input_vertex(vertices(input).begin(), vertices(input).end());
  ASSERT_EQ(cut.paths.size(), ref.cut.paths.size());
  for(std::size_t k = 0; k < cut.paths.size(); ++k) {
    ASSERT_EQ(cut.paths[k].size(), ref.cut.paths[k].size());
    for(std::size_t i = 0; i < cut.paths[k].size(); ++i)
      EXPECT_EQ(cut.paths[k][i], input_vertex[std::size_t(ref.cut.paths[k][i])]);
  }
  EXPECT_EQ(cut.regions, ref.cut.regions);

  // Learn from the mesh and its label map.
  const Morphable_part_model model = learn_morphable_part_model(input, labels, small_hand().annotation);
  ASSERT_EQ(model.types.size(), ref.model.types.size());
  ASSERT_EQ(model.rules.size(), ref.model.rules.size());

  // Deform: the result is written into the mesh, handles are its vertices.
  Mesh edited;
  auto parts = get(CGAL::dynamic_face_property_t<int>(), edited);
  auto types = get(CGAL::dynamic_face_property_t<int>(), edited);
  auto seams = get(CGAL::dynamic_vertex_property_t<int>(), edited);
  copy_training_example(model, 0, edited, parts, parameters::face_part_type_map(types).vertex_is_seam_map(seams));
  EXPECT_EQ(face_labels_from_map(edited, parts), to_labeled_mesh(ref.model.examples[0]).face_labels);
  for(auto f : faces(edited))
    for(const Part_node& node : ref.model.examples[0].graph.nodes)
      if(node.label == get(parts, f)) EXPECT_EQ(get(types, f), node.type);
  expect_seams_where_parts_meet(edited, parts, seams);
  const Handle_set h = tip_handles(to_labeled_mesh(ref.model.examples[0]).mesh);
  std::vector<vertex_descriptor> vertex(vertices(edited).begin(), vertices(edited).end());
  std::vector<std::pair<vertex_descriptor, Point>> handles;
  for(int k = 0; k < h.size(); ++k)
    handles.emplace_back(vertex[std::size_t(h.vertices[std::size_t(k)])],
                         Point(h.targets(k, 0), h.targets(k, 1), h.targets(k, 2)));
  const Edit_result deformed = deform(model, edited, handles);
  EXPECT_EQ(deformed.report.iterations, ref.deformed.result.report.iterations);
  EXPECT_LT(largest_difference(to_indexed_mesh(edited).points, ref.deformed.mesh.points), tolerance * diagonal);
  // The edit moved the mesh: the comparison is not of two rest states.
  EXPECT_GT(largest_difference(to_indexed_mesh(edited).points, to_labeled_mesh(ref.model.examples[0]).mesh.points), 0.01 * diagonal);

  // Symmetrize in place.
  Mesh symmetric;
  copy_training_example(model, 0, symmetric, get(CGAL::dynamic_face_property_t<int>(), symmetric));
  symmetrize(model, symmetric);
  const internal::Solved_edit ref_symmetric = internal::solve_edit(ref.model, make_symmetrization_problem(ref.model));
  EXPECT_LT(largest_difference(to_indexed_mesh(symmetric).points, ref_symmetric.mesh.points), tolerance * diagonal);

  // Assemble into a new mesh with the node of each face.
  Mesh assembled;
  auto nodes = get(CGAL::dynamic_face_property_t<int>(), assembled);
  auto node_types = get(CGAL::dynamic_face_property_t<int>(), assembled);
  auto node_seams = get(CGAL::dynamic_vertex_property_t<int>(), assembled);
  const Assembly_result a = assemble(model, part_graph_of_example(model), assembled, nodes, Assembly_options(),
                              parameters::vertex_is_seam_map(node_seams).face_part_type_map(node_types));
  EXPECT_EQ(face_labels_from_map(assembled, nodes), ref.assembly.face_nodes);
  for(auto f : faces(assembled)) EXPECT_EQ(get(node_types, f), a.graph.nodes[std::size_t(get(nodes, f))].type);
  expect_seams_where_parts_meet(assembled, nodes, node_seams);
  const Indexed_mesh assembled_mesh = to_indexed_mesh(assembled);
  EXPECT_EQ(assembled_mesh.triangles, ref.assembly.mesh.triangles);
  EXPECT_LT(largest_difference(assembled_mesh.points, ref.assembly.mesh.points), tolerance * diagonal);
  EXPECT_NEAR(a.residual_energy, ref.assembly.residual_energy, 1e-6 + tolerance * ref.assembly.residual_energy * 1e3);
}

} // namespace

TEST(FaceGraphPipeline, surface_mesh_gives_the_indexed_result)
{
  run_pipeline<Surface_mesh>(1e-9);
}

TEST(FaceGraphPipeline, polyhedron_gives_the_indexed_result)
{
  run_pipeline<Polyhedron>(1e-9);
}

#ifdef MPM_HAS_OPENMESH
// CGAL 5.5 writes OpenMesh points through float: agreement to float precision.
TEST(FaceGraphPipeline, open_mesh_gives_the_indexed_result)
{
  run_pipeline<OpenMesh::TriMesh_ArrayKernelT<>>(1e-4);
}
#endif

TEST(FaceGraphPipeline, results_need_the_example_mesh)
{
  const Pipeline_reference& ref = reference();
  Surface_mesh other;
  Indexed_mesh small;
  small.points = Point_matrix::Random(4, 3);
  small.triangles = {{0, 1, 2}, {0, 2, 3}};
  copy_to_face_graph(small, other);
  try {
    symmetrize(ref.model, other);
    ADD_FAILURE() << "no error";
  } catch(const Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("has 4 vertices"), std::string::npos) << e.what();
  }
}

// A learned part as the user's mesh: the type's triangles at the shape the
// coordinates give, its boundary docking sites marked as seams.
TEST(FaceGraphPipeline, a_part_shape_is_its_space_at_the_coordinates)
{
  const Morphable_part_model& model = reference().model;
  int type = 0;
  while(type < int(model.types.size()) && model.types[std::size_t(type)].space.number_of_modes() == 0) ++type;
  ASSERT_LT(type, int(model.types.size())) << "no part type with modes";
  const Part_type& t = model.types[std::size_t(type)];
  Eigen::VectorXd coordinates = Eigen::VectorXd::Zero(t.space.number_of_modes());
  coordinates[0] = 2. * std::sqrt(t.space.variances[0]);

  Surface_mesh part;
  auto types = get(CGAL::dynamic_face_property_t<int>(), part);
  auto seams = get(CGAL::dynamic_vertex_property_t<bool>(), part);
  copy_part_shape(model, type, coordinates, part, parameters::face_part_type_map(types).vertex_is_seam_map(seams));
  const Indexed_mesh copied = to_indexed_mesh(part);
  EXPECT_EQ(copied.triangles, t.triangles);
  EXPECT_LT(largest_difference(copied.points, t.space.mean + (t.space.modes.col(0) * coordinates[0])
                                                               .reshaped<Eigen::RowMajor>(t.number_of_vertices, 3)),
            1e-12);
  EXPECT_GT(largest_difference(copied.points, t.space.mean), 0.);
  for(auto f : faces(part)) EXPECT_EQ(get(types, f), type);
  std::set<int> seam_vertices;
  for(const Docking_site& site : t.sites)
    if(site.kind == Docking_kind::boundary) seam_vertices.insert(site.vertices.begin(), site.vertices.end());
  ASSERT_FALSE(seam_vertices.empty());
  int i = 0;
  for(auto v : vertices(part)) EXPECT_EQ(get(seams, v), seam_vertices.count(i++) > 0);

  Surface_mesh mean;
  copy_part_shape(model, type, Eigen::VectorXd(), mean);
  EXPECT_LT(largest_difference(to_indexed_mesh(mean).points, t.space.mean), 1e-15);
}

TEST(FaceGraphPipeline, a_part_shape_needs_a_type_and_its_coordinates)
{
  const Morphable_part_model& model = reference().model;
  const auto error_of = [&](int type, const Eigen::VectorXd& coordinates) {
    Surface_mesh part;
    try {
      copy_part_shape(model, type, coordinates, part);
    } catch(const Input_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of(int(model.types.size()), Eigen::VectorXd()).find("does not exist"), std::string::npos);
  EXPECT_NE(error_of(-1, Eigen::VectorXd()).find("part type -1"), std::string::npos);
  const int modes = model.types[0].space.number_of_modes();
  EXPECT_NE(error_of(0, Eigen::VectorXd::Zero(modes + 1)).find(std::to_string(modes + 1) + " coordinates were given"),
            std::string::npos);
}
