// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Cutting the user's own mesh type: clicks given as vertex descriptors and
// joints proposed with no click write their labels into a face property map
// of a Surface_mesh or a Polyhedron_3, equal to the indexed-mesh path's; the
// part types proposed from that map are the indexed path's too, on
// OpenMesh as well when it is installed; so are the cuts of a
// Face_graph_joint_cutter, click after click. A click
// that is not a vertex of the mesh, or lies on the body, is an Input_error.
#include <CGAL/MPM/Cutting/Face_graph_cutting.h>
#include <CGAL/MPM/Cutting/Segmentation_measures.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>

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
#include <string>
#include <vector>

namespace {

using namespace CGAL::MPM;
using mpm_test::small_hand;
using Kernel = CGAL::Simple_cartesian<double>;

// What the indexed-mesh path gives on the same points: the reference each
// mesh type is held to.
struct Cut_reference
{
  explicit Cut_reference(const Indexed_mesh& mesh)
    : proposal(cut_at_proposed_joints(mesh)), clicks(cut_vertices(proposal)), clicked(cut_at_vertices(mesh, clicks)),
      types(propose_part_types(proposal.cutting.mesh))
  {}

  static std::vector<int> cut_vertices(const Joint_proposal& p)
  {
    std::vector<int> v;
    for(const Joint_cut& c : p.cutting.cuts) v.push_back(c.vertex);
    return v;
  }

  Joint_proposal proposal;
  std::vector<int> clicks;      // the proposal's cut vertices, clicked again
  Joint_cutting_result clicked; // cut_at_vertices() at them
  Part_type_proposal types;
};

template <class Mesh>
void expect_indexed_cuts()
{
  Mesh g;
  copy_to_face_graph(small_hand().mesh.mesh, g);
  const Cut_reference ref(to_indexed_mesh(g));
  // The reference is a real segmentation of the hand, not a trivial one.
  ASSERT_GE(ref.proposal.cutting.cuts.size(), 10u);
  const Labeled_mesh& hand = small_hand().mesh;
  EXPECT_LT(rand_index_error(hand.mesh, ref.proposal.cutting.mesh.face_labels, hand.face_labels), 0.15);

  // The results name the vertices of g: vertex i of the indexed mesh is the
  // i-th of vertices(g).
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  const std::vector<vertex_descriptor> vertex(vertices(g).begin(), vertices(g).end());
  const auto named = [&](const std::vector<int>& indices) {
    std::vector<vertex_descriptor> r;
    for(int i : indices) r.push_back(vertex[std::size_t(i)]);
    return r;
  };
  auto proposed = get(CGAL::dynamic_face_property_t<int>(), g);
  const auto p = cut_at_proposed_joints(g, proposed);
  EXPECT_EQ(p.limbs, ref.proposal.limbs);
  ASSERT_EQ(p.joints.size(), ref.proposal.joints.size());
  for(std::size_t j = 0; j < p.joints.size(); ++j)
    EXPECT_EQ(p.joints[j].vertex, vertex[std::size_t(ref.proposal.joints[j].vertex)]);
  ASSERT_EQ(p.cutting.cuts.size(), ref.proposal.cutting.cuts.size());
  for(std::size_t k = 0; k < p.cutting.cuts.size(); ++k)
    EXPECT_EQ(p.cutting.cuts[k].path, named(ref.proposal.cutting.cuts[k].path));
  EXPECT_EQ(face_labels_from_map(g, proposed), ref.proposal.cutting.mesh.face_labels);

  const std::vector<vertex_descriptor> clicks = named(ref.clicks);
  auto clicked = get(CGAL::dynamic_face_property_t<int>(), g);
  const auto c = cut_at_vertices(g, clicks, clicked);
  ASSERT_EQ(c.cuts.size(), ref.clicked.cuts.size());
  for(std::size_t k = 0; k < c.cuts.size(); ++k) {
    EXPECT_EQ(c.cuts[k].vertex, clicks[k]);
    EXPECT_EQ(c.cuts[k].path, named(ref.clicked.cuts[k].path));
    EXPECT_EQ(c.cuts[k].length, ref.clicked.cuts[k].length);
  }
  EXPECT_EQ(face_labels_from_map(g, clicked), ref.clicked.mesh.face_labels);

  // Click after click through one cutter (the skeleton computed once): the
  // clicks so far each give their cut, and all of them the cuts above.
  const Face_graph_joint_cutter<Mesh> cutter(g);
  auto step = get(CGAL::dynamic_face_property_t<int>(), g);
  const std::vector<vertex_descriptor> half(clicks.begin(), clicks.begin() + clicks.size() / 2);
  EXPECT_EQ(cutter.cut(half, step).cuts.size(), half.size());
  EXPECT_EQ(face_labels_from_map(g, step).size(), ref.clicked.mesh.face_labels.size());
  EXPECT_NE(face_labels_from_map(g, step), ref.clicked.mesh.face_labels);
  const auto all = cutter.cut(clicks, step);
  ASSERT_EQ(all.cuts.size(), ref.clicked.cuts.size());
  for(std::size_t k = 0; k < all.cuts.size(); ++k) EXPECT_EQ(all.cuts[k].path, named(ref.clicked.cuts[k].path));
  EXPECT_EQ(face_labels_from_map(g, step), ref.clicked.mesh.face_labels);

  const Part_type_proposal types = propose_part_types(g, proposed);
  EXPECT_EQ(types.annotation.part_type_of_label, ref.types.annotation.part_type_of_label);
  EXPECT_EQ(types.root, ref.types.root);
  std::set<std::string> names;
  for(const auto& [label, type] : types.annotation.part_type_of_label) names.insert(type);
  EXPECT_LT(names.size(), types.annotation.part_type_of_label.size()) << "some segments share a type";
}

TEST(FaceGraphCutting, SurfaceMeshGivesTheIndexedCuts) { expect_indexed_cuts<CGAL::Surface_mesh<Kernel::Point_3>>(); }

TEST(FaceGraphCutting, PolyhedronGivesTheIndexedCuts) { expect_indexed_cuts<CGAL::Polyhedron_3<Kernel>>(); }

#ifdef MPM_HAS_OPENMESH
// CGAL 5.5 writes OpenMesh points through float: the reference is the
// indexed path on those rounded points.
TEST(FaceGraphCutting, OpenMeshGivesTheIndexedCuts) { expect_indexed_cuts<OpenMesh::TriMesh_ArrayKernelT<>>(); }
#endif

TEST(FaceGraphCutting, BadClicksAreInputErrors)
{
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  Mesh g;
  copy_to_face_graph(small_hand().mesh.mesh, g);
  auto labels = get(CGAL::dynamic_face_property_t<int>(), g);
  const std::vector<Mesh::Vertex_index> outside = {Mesh::Vertex_index(Mesh::size_type(num_vertices(g) + 5))};
  try {
    cut_at_vertices(g, outside, labels);
    FAIL() << "a vertex not in the mesh was clicked";
  } catch(const Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("click 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is not a vertex of the mesh"), std::string::npos) << e.what();
  }
  // A click on the palm (vertex 0, no limb through it) names the vertex
  // by its index in vertices(g), as the indexed path does.
  try {
    cut_at_vertices(g, std::vector<Mesh::Vertex_index>{*vertices(g).begin()}, labels);
    FAIL() << "a click on the palm was cut";
  } catch(const Input_error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 0: is on the body"), std::string::npos) << e.what();
  }
}

} // namespace
