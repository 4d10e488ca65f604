// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The catalogue of bad inputs (doc/MPM/Bad_input.md): the kinds not covered
// by the tests of each reader. Every failing read checks that the message
// names the file (and the element when there is one) and that the input file
// is byte-for-byte unchanged.
#include "Io_test_support.h"

#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_problem.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>
#include <CGAL/MPM/internal/Surface_mesh_repair.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace CGAL::MPM;
using mpm_test::read_bytes;
using mpm_test::write_bytes;

namespace {

// Writes `bytes` to `path`, checks that `read` throws an Input_error whose
// message holds every piece (the file name is always required) and that the
// file is unchanged. Returns the message.
std::string expect_rejected(const std::string& path, const std::string& bytes,
                            const std::function<void(const std::string&)>& read,
                            std::initializer_list<std::string> pieces)
{
  write_bytes(path, bytes);
  const std::string message = mpm_test::input_error_message([&] { read(path); });
  EXPECT_TRUE(mpm_test::contains_all(message, {path})) << message;
  EXPECT_TRUE(mpm_test::contains_all(message, pieces)) << message;
  EXPECT_EQ(read_bytes(path), bytes) << path << ": input modified";
  std::cout << "  " << message << '\n';
  return message;
}

// Readers of every format, all taking a path.
void read_mesh(const std::string& p) { read_mesh_file(p); }
void read_seg(const std::string& p) { read_seg_file(p); }
void read_annot(const std::string& p) { read_annotation(p); }
void read_model(const std::string& p) { load_model(p); }
void read_graph(const std::string& p) { read_part_graph(p, Morphable_part_model()); }
void read_handle_file(const std::string& p) { read_handles(p, Point_matrix::Zero(4, 3)); }

struct Format
{
  std::string extension;
  std::function<void(const std::string&)> read;
};

std::vector<Format> all_formats()
{
  return {{".off", read_mesh},  {".obj", read_mesh},         {".ply", read_mesh},
          {".stl", read_mesh},  {".seg", read_seg},          {".annotation.json", read_annot},
          {".mpm", read_model}, {".graph.json", read_graph}, {".handles.json", read_handle_file}};
}

std::string garbage_bytes(unsigned seed, int n)
{
  std::string g;
  std::mt19937 random(seed);
  for(int i = 0; i < n; ++i) g += char(random() & 0xff);
  return g;
}

// Two square k x k grids side by side sharing the seam x = 1, labels 0 and 1.
Labeled_mesh two_tiles(int k = 4)
{
  Labeled_mesh lm;
  lm.source = "tiles";
  const int columns = 2 * k + 1;
  lm.mesh.points.resize(columns * (k + 1), 3);
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i < columns; ++i) {
      const double u = double(i) / k, v = double(j) / k;
      lm.mesh.points.row(j * columns + i) << u, v, 0.1 * std::sin(M_PI * u) * std::sin(M_PI * v);
    }
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < 2 * k; ++i) {
      const int a = j * columns + i, b = a + 1, c = a + columns, d = c + 1;
      lm.mesh.triangles.push_back({a, b, d});
      lm.mesh.triangles.push_back({a, d, c});
      lm.face_labels.push_back(i < k ? 0 : 1);
      lm.face_labels.push_back(i < k ? 0 : 1);
    }
  return lm;
}

Annotation two_types()
{
  Annotation a;
  a.part_type_of_label = {{0, "left"}, {1, "right"}};
  a.parameters.docking_radius = 0.3;
  a.source = "tiles.json";
  return a;
}

int add_point(Labeled_mesh& lm, double x, double y, double z)
{
  const Eigen::Index n = lm.mesh.points.rows();
  lm.mesh.points.conservativeResize(n + 1, 3);
  lm.mesh.points.row(n) << x, y, z;
  return int(n);
}

void add_face(Labeled_mesh& lm, Triangle t, int label)
{
  lm.mesh.triangles.push_back(t);
  lm.face_labels.push_back(label);
}

// Learns the mesh, drags two vertices and checks that every position and
// the energy stay finite; returns the learning warnings.
std::vector<std::string> learn_and_drag(const Labeled_mesh& lm, std::vector<int> handles = {0, 8})
{
  std::vector<std::string> warnings;
  Learning_options lo;
  lo.warning = [&](const std::string& w) { warnings.push_back(w); };
  const Morphable_part_model model = learn_morphable_part_model({Training_input{lm, two_types()}}, lo);
  const Embedding_problem problem = make_deformation_problem(model);
  for(const Global_step step : {Global_step::reduced, Global_step::direct}) {
    Embedding_options eo;
    eo.global_step = step;
    eo.max_iterations = 20;
    Embedding_solver solver(problem, eo);
    const Point_matrix& rest = problem.mesh.points;
    Point_matrix targets(2, 3);
    targets.row(0) = rest.row(handles[0]) + Eigen::RowVector3d(0., 0., 0.2);
    targets.row(1) = rest.row(handles[1]) + Eigen::RowVector3d(0.1, 0., -0.1);
    solver.set_handles(handles, targets);
    const Solve_report r = solver.solve();
    EXPECT_TRUE(solver.positions().allFinite()) << lm.source;
    EXPECT_TRUE(std::isfinite(r.energy())) << lm.source;
    EXPECT_LT((solver.positions().row(handles[0]) - targets.row(0)).norm(), 0.1) << lm.source;
  }
  return warnings;
}

using mpm_test::triangle_vertices;

} // namespace

// ---------------------------------------------------------------------------
// Missing, empty, truncated and garbage files of every format.

TEST(BadInput, MissingFileOfEveryFormat)
{
  mpm_test::Scratch_directory dir;
  for(const Format& f : all_formats()) {
    const std::string path = dir.file("absent" + f.extension);
    MPM_EXPECT_INPUT_ERROR(f.read(path), path + ": file not found");
  }
}

TEST(BadInput, DirectoryInsteadOfAFile)
{
  mpm_test::Scratch_directory dir;
  for(const Format& f : all_formats()) {
    const std::string path = dir.file("folder" + f.extension);
    mpm_test::fs::create_directory(path);
    MPM_EXPECT_INPUT_ERROR(f.read(path), path + ": is a directory, not a file");
  }
}

TEST(BadInput, EmptyFileOfEveryFormat)
{
  mpm_test::Scratch_directory dir;
  for(const std::string ext : {".off", ".obj", ".ply", ".stl"})
    expect_rejected(dir.file("empty" + ext), "", read_mesh, {"file is empty"});
  expect_rejected(dir.file("empty.seg"), "", read_seg, {"is empty (expected one label per face)"});
  expect_rejected(dir.file("empty.mpm"), "", read_model, {"not a CGAL-MPM model file"});
  expect_rejected(dir.file("empty.annotation.json"), "", read_annot, {"malformed JSON"});
  expect_rejected(dir.file("empty.graph.json"), "", read_graph, {"malformed JSON"});
  expect_rejected(dir.file("empty.handles.json"), "", read_handle_file, {"malformed JSON"});
  // White space only is as empty.
  expect_rejected(dir.file("blank.annotation.json"), " \n\t\n", read_annot, {"malformed JSON"});
}

TEST(BadInput, BinaryGarbageOfEveryFormat)
{
  mpm_test::Scratch_directory dir;
  unsigned seed = 11;
  for(const Format& f : all_formats())
    for(const int size : {1, 7, 100, 5000})
      expect_rejected(dir.file("garbage" + std::to_string(size) + f.extension), garbage_bytes(seed++, size), f.read,
                      {});
}

TEST(BadInput, TruncatedMeshFiles)
{
  mpm_test::Scratch_directory dir;
  // OBJ cut inside a vertex line and inside a face line.
  expect_rejected(dir.file("cut_vertex.obj"), "v 0 0 0\nv 1 0 0\nv 0 1", read_mesh, {"vertex 2", "fewer than 3"});
  expect_rejected(dir.file("cut_face.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2", read_mesh,
                  {"face 0", "has 2 corners"});
  // PLY whose body ends before the announced elements (ASCII and binary).
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  expect_rejected(dir.file("cut.ply"), header + triangle_vertices + "3 0 1 2\n", read_mesh,
                  {"element \"face\" 1", "truncated: the file ends in its property \"vertex_indices\""});
  expect_rejected(dir.file("cut_header.ply"), header.substr(0, 40), read_mesh,
                  {"header: has no end_header line (truncated, or not a PLY file)"});
  std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float coordinates[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  binary.append(reinterpret_cast<const char*>(coordinates), 20); // 5 of 9 floats
  expect_rejected(dir.file("cut_binary.ply"), binary, read_mesh,
                  {"element \"vertex\" 1", "truncated: the file ends in its property \"z\""});
  // ASCII STL ending inside a facet.
  expect_rejected(dir.file("cut_ascii.stl"),
                  "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n", read_mesh,
                  {"contains no faces (an empty, truncated or non-STL file)"});
  // Binary STL announcing 2 facets, holding 1.
  std::string stl(80, ' ');
  const std::uint32_t count = 2;
  stl.append(reinterpret_cast<const char*>(&count), 4);
  const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  stl.append(reinterpret_cast<const char*>(facet), sizeof facet);
  stl.append(2, '\0');
  expect_rejected(dir.file("cut_binary.stl"), stl, read_mesh, {"cannot be read as stl (malformed or truncated file)"});
  // Binary STL cut inside its 84-byte header.
  expect_rejected(dir.file("cut_header.stl"), stl.substr(0, 60), read_mesh, {"truncated or non-STL file"});
}

TEST(BadInput, TruncatedJsonAndModelFiles)
{
  mpm_test::Scratch_directory dir;
  expect_rejected(dir.file("cut.annotation.json"), R"({"parts": [{"label": 0, "type": "pa)", read_annot,
                  {"malformed JSON"});
  expect_rejected(dir.file("cut.graph.json"), R"({"format": "cgal-mpm-part-graph", "nodes": [)", read_graph,
                  {"malformed JSON"});
  expect_rejected(dir.file("cut.handles.json"), R"({"handles": [{"vertex": 0, "target": [0, 0)", read_handle_file,
                  {"malformed JSON"});
  const std::string model = serialize_model(Morphable_part_model());
  for(const std::size_t n : {std::size_t(3), std::size_t(12), model.size() - 1})
    expect_rejected(dir.file("cut" + std::to_string(n) + ".mpm"), model.substr(0, n), read_model, {});
  expect_rejected(dir.file("cut.mpm"), model.substr(0, model.size() - 1), read_model,
                  {"damaged model file (truncated"});
}

TEST(BadInput, ForeignFilesOfAnotherFormat)
{
  mpm_test::Scratch_directory dir;
  const std::string off = "OFF\n3 1 0\n" + triangle_vertices + "3 0 1 2\n";
  expect_rejected(dir.file("mesh.mpm"), off, read_model, {"not a CGAL-MPM model file"});
  expect_rejected(dir.file("mesh.annotation.json"), off, read_annot, {"malformed JSON"});
  // A handle file given as annotation, an annotation given as handles or part graph.
  expect_rejected(dir.file("h.annotation.json"), R"({"format": "cgal-mpm-handles", "handles": []})", read_annot,
                  {"format"});
  expect_rejected(dir.file("a.handles.json"), R"({"format": "cgal-mpm-annotation", "parts": []})",
                  read_handle_file, {"format"});
  expect_rejected(dir.file("a.graph.json"), R"({"format": "cgal-mpm-annotation", "parts": []})", read_graph,
                  {"format"});
  // A model file is not a mesh.
  expect_rejected(dir.file("model.off"), serialize_model(Morphable_part_model()), read_mesh, {});
}

// ---------------------------------------------------------------------------
// Geometry.

TEST(BadInput, HugeCoordinatesAreRefusedBeforeTheyOverflow)
{
  mpm_test::Scratch_directory dir;
  for(const std::string value : {"1e300", "-1e200", "1.7e308"}) {
    const std::string text = "OFF\n3 1 0\n0 0 0\n" + value + " 0 0\n0 1 0\n3 0 1 2\n";
    expect_rejected(dir.file("huge.off"), text, read_mesh, {"vertex 1", "is too large", "1e150"});
    expect_rejected(dir.file("huge.obj"), "v 0 0 0\nv 0 1 0\nv 0 0 " + value + "\nf 1 2 3\n", read_mesh,
                    {"vertex 2", "is too large"});
  }
  // Beyond the double range the text is read as infinity.
  expect_rejected(dir.file("overflow.off"), "OFF\n3 1 0\n0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n", read_mesh,
                  {"vertex 1", "non-finite coordinate \"1e999\""});
  // Large (and tiny) coordinates are fine, at any scale: the zero-area test
  // is relative to the bounding box and neither overflows nor underflows.
  for(const double scale : {1e-300, 1e-200, 1e-150, 1e100, 1e149}) {
    Indexed_mesh m;
    m.points.resize(3, 3);
    m.points << 0, 0, 0, scale, 0, 0, 0, scale, 0;
    m.triangles = {{0, 1, 2}};
    write_mesh_file(m, dir.file("scaled.off"));
    EXPECT_NO_THROW(read_mesh_file(dir.file("scaled.off"))) << scale;
  }
  // ... and a flat triangle is still flat at tiny scales.
  expect_rejected(dir.file("tiny_flat.off"), "OFF\n4 2 0\n0 0 0\n1e-200 0 0\n0 1e-200 0\n2e-200 0 0\n3 0 1 2\n3 0 1 3\n",
                  read_mesh, {"face 1", "degenerate triangle (zero area"});
  // In memory, and so before learning.
  Labeled_mesh lm = two_tiles();
  lm.mesh.points(5, 1) = -3e250;
  MPM_EXPECT_INPUT_ERROR(validate_labeled_mesh(lm), "tiles: vertex 5: coordinate -3e+250 is too large");
  MPM_EXPECT_INPUT_ERROR(learn_morphable_part_model(lm, two_types()), "tiles: vertex 5", "too large");
}

TEST(BadInput, SliverFacesAreAcceptedAndStayFinite)
{
  // A needle: height 1e-6 of its base, far above the zero-area threshold.
  mpm_test::Scratch_directory dir;
  const std::string text = "OFF\n4 2 0\n" + triangle_vertices + "0.5 -1e-6 0\n3 0 1 2\n3 1 0 3\n";
  write_bytes(dir.file("sliver.off"), text);
  const Mesh_file f = read_mesh_file(dir.file("sliver.off"));
  EXPECT_EQ(f.mesh.number_of_faces(), 2);
  EXPECT_TRUE(f.warnings.empty());

  Labeled_mesh lm = two_tiles();
  const int v = add_point(lm, 0.125, -1e-6, 0.);
  add_face(lm, {1, 0, v}, 0);
  lm.source = "sliver";
  learn_and_drag(lm);
}

TEST(BadInput, DuplicateVerticesAreKeptApart)
{
  // Vertex 3 repeats vertex 1: the reader keeps both (no merging), so the
  // two triangles are separate components.
  mpm_test::Scratch_directory dir;
  const std::string path = dir.file("dup.off");
  const std::string text = "OFF\n5 2 0\n" + triangle_vertices + "1 0 0\n1 1 0\n3 0 1 2\n3 3 4 2\n";
  write_bytes(path, text);
  const Mesh_file f = read_mesh_file(path);
  EXPECT_EQ(f.mesh.number_of_vertices(), 5);
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_EQ(connected_component_labels(f.mesh), (std::vector<int>{0, 1}));
  EXPECT_EQ(read_bytes(path), text);

  // Through learning: a flap of part 0 hanging on a copy of a corner.
  Labeled_mesh lm = two_tiles();
  const int copy = add_point(lm, 0., 0., 0.);
  const int a = add_point(lm, -0.2, -0.05, 0.), b = add_point(lm, -0.05, -0.2, 0.);
  add_face(lm, {copy, b, a}, 0);
  lm.source = "duplicate";
  learn_and_drag(lm);
}

TEST(BadInput, UnreferencedVerticesSurviveLearningAndSolving)
{
  Labeled_mesh lm = two_tiles();
  add_point(lm, 3., 3., 3.);
  lm.source = "unreferenced";
  learn_and_drag(lm);
}

TEST(BadInput, BowtieVerticesAreAcceptedAndStayFinite)
{
  mpm_test::Scratch_directory dir;
  const std::string text = "OFF\n5 2 0\n" + triangle_vertices + "-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n";
  write_bytes(dir.file("bowtie.off"), text);
  const Mesh_file f = read_mesh_file(dir.file("bowtie.off"));
  EXPECT_EQ(connected_component_labels(f.mesh), (std::vector<int>{0, 1}));

  Labeled_mesh lm = two_tiles();
  const int a = add_point(lm, -0.2, -0.05, 0.), b = add_point(lm, -0.05, -0.2, 0.);
  add_face(lm, {0, b, a}, 0); // touches part 0 at vertex 0 only
  lm.source = "bowtie";
  learn_and_drag(lm);
}

TEST(BadInput, NonManifoldEdgesAreAcceptedAndStayFinite)
{
  mpm_test::Scratch_directory dir;
  const std::string text = "OFF\n5 3 0\n" + triangle_vertices + "0.3 0.3 1\n0.3 0.3 -1\n3 0 1 2\n3 0 1 3\n3 1 0 4\n";
  write_bytes(dir.file("fin.off"), text);
  EXPECT_EQ(read_mesh_file(dir.file("fin.off")).mesh.number_of_faces(), 3);
  // Labels from a PLY face property as well (once read by CGAL's
  // Surface_mesh reader, which refused such a mesh).
  write_bytes(dir.file("fin.ply"), "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\n"
                                   "property double z\nelement face 3\nproperty list uchar int vertex_indices\n"
                                   "property int part\nend_header\n0 0 0\n1 0 0\n0 1 0\n0.3 0.3 1\n0.3 0.3 -1\n"
                                   "3 0 1 2 5\n3 0 1 3 6\n3 1 0 4 7\n");
  EXPECT_EQ(read_labeled_mesh(dir.file("fin.ply"), "property:part").face_labels, (std::vector<int>{5, 6, 7}));

  // A fin on an interior edge of part 0: three triangles share edge 1-11.
  Labeled_mesh lm = two_tiles();
  const Eigen::RowVector3d mid = 0.5 * (lm.mesh.points.row(1) + lm.mesh.points.row(11));
  const int fin = add_point(lm, mid(0), mid(1), mid(2) + 0.2);
  add_face(lm, {1, 11, fin}, 0);
  lm.source = "fin";
  // The model keeps its example as a surface mesh: the faces at edge 1-11
  // are pulled apart by copies of vertices (3, measured).
  const std::vector<std::string> warnings = learn_and_drag(lm);
  EXPECT_EQ(std::count_if(warnings.begin(), warnings.end(), [](const std::string& w) {
              return mpm_test::contains_all(w, {"fin: non-manifold", "3 vertices were copied"});
            }),
            1) << (warnings.empty() ? "" : warnings.front());
}

// A face turned against its neighbours is turned back, not the rest of the
// surface after it: a closed surface stays outward however the faces were
// visited. The model keeps its examples as surface meshes, which need one
// orientation.
TEST(BadInput, AFaceFlippedAgainstItsNeighboursIsTurnedBack)
{
  Indexed_mesh octahedron;
  octahedron.points.resize(6, 3);
  octahedron.points << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  octahedron.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for(int first : {0, 5}) {
    Indexed_mesh flipped = octahedron;
    std::swap(flipped.triangles[std::size_t(first)][1], flipped.triangles[std::size_t(first)][2]);
    const std::string said = internal::make_surface_mesh_compatible(flipped, "flipped");
    EXPECT_TRUE(mpm_test::contains_all(said, {"0 vertices were copied", "1 faces turned"})) << said;
    EXPECT_EQ(flipped.triangles, octahedron.triangles) << "face " << first << " flipped";
    EXPECT_EQ(flipped.points, octahedron.points);
  }
  EXPECT_EQ(internal::make_surface_mesh_compatible(octahedron, "octahedron"), "");

  Labeled_mesh lm = two_tiles();
  std::swap(lm.mesh.triangles[3][1], lm.mesh.triangles[3][2]);
  lm.source = "flipped";
  const std::vector<std::string> warnings = learn_and_drag(lm);
  EXPECT_EQ(std::count_if(warnings.begin(), warnings.end(), [](const std::string& w) {
              return mpm_test::contains_all(w, {"flipped: non-manifold or inconsistently oriented", "1 faces turned"});
            }),
            1);
}

TEST(BadInput, HolesAreAccepted)
{
  Labeled_mesh lm = two_tiles();
  // Remove the two triangles of an interior square of part 0 (row 1, column 1).
  const int k = 4, square = 1 * 2 * k + 1;
  lm.mesh.triangles.erase(lm.mesh.triangles.begin() + 2 * square, lm.mesh.triangles.begin() + 2 * square + 2);
  lm.face_labels.erase(lm.face_labels.begin() + 2 * square, lm.face_labels.begin() + 2 * square + 2);
  lm.source = "hole";
  learn_and_drag(lm);
}

TEST(BadInput, DisconnectedPartWarnsThatItDocksToNothing)
{
  Labeled_mesh lm = two_tiles();
  // Part 1 moved far away: no shared seam, nothing within the docking radius.
  const int copy_base = int(lm.mesh.points.rows());
  lm.mesh.points.conservativeResize(2 * copy_base, 3);
  for(int v = 0; v < copy_base; ++v)
    lm.mesh.points.row(copy_base + v) = lm.mesh.points.row(v) + Eigen::RowVector3d(5., 0., 0.);
  for(std::size_t f = 0; f < lm.mesh.triangles.size(); ++f)
    if(lm.face_labels[f] == 1)
      for(int& c : lm.mesh.triangles[f]) c += copy_base;
  lm.source = "apart";
  // (The original vertices of part 1 are now unreferenced: kept.)
  const std::vector<std::string> warnings = learn_and_drag(lm, {0, copy_base + 8});
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_TRUE(mpm_test::contains_all(warnings[0], {"apart: label 0", "docks to no other part"})) << warnings[0];
  EXPECT_TRUE(mpm_test::contains_all(warnings[1], {"apart: label 1", "docks to no other part"})) << warnings[1];
}

// ---------------------------------------------------------------------------
// Labels and annotations that do not fit the mesh.

TEST(BadInput, LabelFileForAnotherMesh)
{
  mpm_test::Scratch_directory dir;
  const std::string mesh = dir.file("t.off");
  write_bytes(mesh, "OFF\n3 1 0\n" + triangle_vertices + "3 0 1 2\n");
  const std::string seg = dir.file("t.seg");
  const std::string labels = "0\n0\n0\n";
  write_bytes(seg, labels);
  MPM_EXPECT_INPUT_ERROR(read_labeled_mesh(mesh, seg), seg + ": has 3 labels but " + mesh + " has 1 faces");
  EXPECT_EQ(read_bytes(seg), labels);
  // Labels as a mesh file's face property of a non-PLY mesh.
  MPM_EXPECT_INPUT_ERROR(read_labeled_mesh(mesh, "property:part"), mesh, "need a PLY file");
}

TEST(BadInput, AnnotationWithWrongValueTypes)
{
  mpm_test::Scratch_directory dir;
  expect_rejected(dir.file("a.annotation.json"), R"({"parts": [{"label": "zero", "type": "palm"}]})", read_annot,
                  {"parts[0].label", "must be an integer"});
  expect_rejected(dir.file("b.annotation.json"), R"({"parts": [{"label": 0, "type": "palm", "landmarks": [1, -2]}]})",
                  read_annot, {"parts[0].landmarks", "negative"});
  expect_rejected(dir.file("c.annotation.json"), R"({"parameters": {"sigma_sub": -1}})", read_annot,
                  {"parameters.sigma_sub", "must be positive"});
  expect_rejected(dir.file("d.annotation.json"), R"([1, 2, 3])", read_annot, {"must be a JSON object"});
}
