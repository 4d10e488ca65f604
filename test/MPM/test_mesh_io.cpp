// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Io_test_support.h"

#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/internal/Atomic_file.h>

#include <unistd.h>

#include <cmath>
#include <limits>

using namespace CGAL::MPM;
using mpm_test::read_bytes;
using mpm_test::write_bytes;

namespace {

Indexed_mesh tetrahedron()
{
  Indexed_mesh m;
  m.points.resize(4, 3);
  m.points << 0, 0, 0, 1.25, 0, 0, 0, 1. / 3., 0, 0, 0, 0.1;
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

using mpm_test::triangle_vertices;

} // namespace

TEST(MeshIo, RoundTripsEveryWritableFormatExactly)
{
  mpm_test::Scratch_directory dir;
  const Indexed_mesh m = tetrahedron();
  for(const std::string ext : {".off", ".obj", ".ply", ".OFF"}) {
    const std::string path = dir.file("tetra" + ext);
    write_mesh_file(m, path);
    const Mesh_file r = read_mesh_file(path);
    EXPECT_EQ(r.mesh.points, m.points) << ext;
    EXPECT_EQ(r.mesh.triangles, m.triangles) << ext;
    EXPECT_EQ(r.file_face, (std::vector<int>{0, 1, 2, 3})) << ext;
    EXPECT_EQ(r.number_of_file_faces, 4);
    EXPECT_TRUE(r.warnings.empty()) << ext;
  }
}

// STL has no shared vertices: the reader merges equal corners back, so
// the tetrahedron returns with its 4 vertices (binary: in single precision).
TEST(MeshIo, WritesBinaryPlyAndAsciiAndBinaryStl)
{
  mpm_test::Scratch_directory dir;
  const Indexed_mesh m = tetrahedron();
  Mesh_write_options binary;
  binary.binary = true;
  write_mesh_file(m, dir.file("b.ply"), nullptr, binary);
  const Mesh_file ply = read_mesh_file(dir.file("b.ply"));
  EXPECT_EQ(ply.mesh.points, m.points);
  EXPECT_EQ(ply.mesh.triangles, m.triangles);
  EXPECT_EQ(read_bytes(dir.file("b.ply")).find("format binary_little_endian 1.0"), 4u);
  for(const bool b : {false, true})
  {
    const std::string path = dir.file(b ? "b.stl" : "a.stl");
    write_mesh_file(m, path, nullptr, Mesh_write_options{b});
    const Mesh_file stl = read_mesh_file(path);
    ASSERT_EQ(stl.mesh.number_of_vertices(), 4) << path;
    ASSERT_EQ(stl.mesh.number_of_faces(), 4) << path;
    for(int f = 0; f < 4; ++f)
      for(int c = 0; c < 3; ++c)
        EXPECT_LT((stl.mesh.points.row(stl.mesh.triangles[f][c]) - m.points.row(m.triangles[f][c])).norm(), b ? 1e-7 : 1e-15)
          << path << " face " << f;
  }
  EXPECT_EQ(mpm_test::fs::file_size(dir.file("b.stl")), 84u + 4u * 50u);
}

TEST(MeshIo, PlyCarriesFaceColours)
{
  mpm_test::Scratch_directory dir;
  const Indexed_mesh m = tetrahedron();
  Eigen::Matrix<unsigned char, Eigen::Dynamic, 3> colors(4, 3);
  colors << 255, 0, 0, 0, 255, 0, 0, 0, 255, 7, 8, 9;
  const std::string path = dir.file("colored.ply");
  write_mesh_file(m, path, &colors);
  const std::string text = read_bytes(path);
  EXPECT_NE(text.find("property uchar red\nproperty uchar green\nproperty uchar blue"), std::string::npos);
  EXPECT_NE(text.find("3 1 2 3 7 8 9\n"), std::string::npos);
  const Mesh_file r = read_mesh_file(path);
  EXPECT_EQ(r.mesh.points, m.points);
  EXPECT_EQ(r.mesh.triangles, m.triangles);
  MPM_EXPECT_INPUT_ERROR(write_mesh_file(m, dir.file("x.ply"), &(colors = Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>(colors.topRows(2))).eval()),
                         "x.ply", "2 face colours for 4 faces");
}

// CGAL reads the invalid OBJ index 0 as another vertex; the error named
// index 4 of a file that has no index 4.
TEST(MeshIo, ObjIndexZeroIsNamed)
{
  mpm_test::Scratch_directory dir;
  write_bytes(dir.file("z.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("z.obj")), "z.obj: face 0: line 4: vertex index 0 is not valid");
  write_bytes(dir.file("ok.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -1\n");
  EXPECT_EQ(read_mesh_file(dir.file("ok.obj")).mesh.triangles.size(), 1u);
}

// Both were accepted silently.
TEST(MeshIo, RepeatedFacesAndTextAfterTheLastFaceWarn)
{
  mpm_test::Scratch_directory dir;
  const std::string tetra = "OFF\n4 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  write_bytes(dir.file("d.off"), tetra + "3 2 1 0\njunk\n");
  const Mesh_file file = read_mesh_file(dir.file("d.off"));
  EXPECT_EQ(file.mesh.triangles.size(), 5u); // kept
  ASSERT_EQ(file.warnings.size(), 2u);
  EXPECT_EQ(file.warnings[0], dir.file("d.off") + ": 1 face repeats the vertices of another (first: face 4 repeats face 0); kept");
  EXPECT_EQ(file.warnings[1], dir.file("d.off") + ": line 12: text after the last of the 5 faces (\"junk\") is ignored");
}

TEST(MeshIo, MissingEmptyGarbageAndUnsupportedFilesAreRejected)
{
  mpm_test::Scratch_directory dir;
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("absent.off")), "absent.off", "file not found");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.path().string()), "is a directory");
  write_bytes(dir.file("empty.off"), "");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("empty.off")), "empty.off", "empty");
  std::string garbage;
  std::mt19937 random(7);
  for(int i = 0; i < 4096; ++i) garbage += char(random() & 0xff);
  for(const std::string ext : {".off", ".obj", ".ply", ".stl"}) {
    const std::string path = dir.file("garbage" + ext);
    write_bytes(path, garbage);
    MPM_EXPECT_INPUT_ERROR(read_mesh_file(path), "garbage" + ext);
    EXPECT_EQ(read_bytes(path), garbage) << "input modified";
  }
  write_bytes(dir.file("mesh.xyz"), "OFF\n3 1 0\n" + triangle_vertices + "3 0 1 2\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("mesh.xyz")), "mesh.xyz", "\".xyz\"",
                         "supported: .off, .obj, .ply, .stl");
  write_bytes(dir.file("comments.off"), "# nothing\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("comments.off")), "comments.off");
}

TEST(MeshIo, AbsurdCountsAreRejectedBeforeAllocating)
{
  mpm_test::Scratch_directory dir;
  write_bytes(dir.file("huge.off"), "OFF\n2000000000 2000000000 0\n" + triangle_vertices);
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("huge.off")), "huge.off", "header",
                         "2000000000 vertices");
  write_bytes(dir.file("corners.off"), "OFF\n3 1 0\n" + triangle_vertices + "4000000000 0 1 2\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("corners.off")), "corners.off");
}

TEST(MeshIo, TruncatedOffNamesWhereItEnds)
{
  mpm_test::Scratch_directory dir;
  write_bytes(dir.file("cut.off"), "OFF\n3 2 0\n" + triangle_vertices + "3 0 1 2\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("cut.off")), "cut.off", "truncated", "1 of 2 faces");
  write_bytes(dir.file("cut2.off"), "OFF\n4 1 0\n" + triangle_vertices);
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("cut2.off")), "cut2.off");
  write_bytes(dir.file("cut3.off"), "OFF\n3 1 0\n" + triangle_vertices + "3 0 1");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("cut3.off")), "cut3.off", "face 0");
}

TEST(MeshIo, PolygonsAreFanTriangulatedWithOneWarning)
{
  mpm_test::Scratch_directory dir;
  const std::string path = dir.file("quads.off");
  const std::string text = "OFF\n6 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n"
                           "3 0 1 3\n4 0 1 2 3\n4 1 4 5 2\n";
  write_bytes(path, text);
  const Mesh_file r = read_mesh_file(path);
  EXPECT_EQ(r.number_of_file_faces, 3);
  EXPECT_EQ(r.mesh.triangles, (std::vector<Triangle>{{0, 1, 3}, {0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}}));
  EXPECT_EQ(r.file_face, (std::vector<int>{0, 1, 1, 2, 2}));
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(mpm_test::contains_all(r.warnings[0], {"quads.off", "2 polygons with more than 3 corners were fan-triangulated (first: face 1)"}));
  EXPECT_EQ(read_bytes(path), text) << "input modified";
}

TEST(MeshIo, BadIndicesAndPolygonsAreRejected)
{
  mpm_test::Scratch_directory dir;
  write_bytes(dir.file("range.off"), "OFF\n3 2 0\n" + triangle_vertices + "3 0 1 2\n3 0 1 7\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("range.off")), "range.off", "face 1",
                         "vertex index 7 is out of range (the file has 3 vertices)");
  write_bytes(dir.file("range.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("range.obj")), "range.obj", "face 1",
                         "vertex index 9 is out of range");
  write_bytes(dir.file("line.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("line.obj")), "line.obj", "face 1", "has 2 corners");
  write_bytes(dir.file("nofaces.off"), "OFF\n3 0 0\n" + triangle_vertices);
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("nofaces.off")), "nofaces.off", "no faces");
}

TEST(MeshIo, NonFiniteCoordinatesNameTheVertex)
{
  mpm_test::Scratch_directory dir;
  for(const std::string value : {"nan", "inf", "-inf"}) {
    write_bytes(dir.file("bad.off"), "OFF\n3 1 0\n0 0 0\n1 " + value + " 0\n0 1 0\n3 0 1 2\n");
    MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("bad.off")), "bad.off", "vertex 1", "non-finite");
    write_bytes(dir.file("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 " + value + " 0\nf 1 2 3\n");
    MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("bad.obj")), "bad.obj", "vertex 2", "non-finite");
  }
  write_bytes(dir.file("word.off"), "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("word.off")), "word.off", "vertex 1", "\"zero\" is not a number");

  // Binary STL stores raw floats, so a NaN reaches the geometric check.
  std::string stl(80, ' ');
  auto put = [&](const void* p, std::size_t n) { stl.append(static_cast<const char*>(p), n); };
  const std::uint32_t count = 1;
  put(&count, 4);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, nan, 1, 0};
  put(facet, sizeof facet);
  stl.append(2, '\0');
  write_bytes(dir.file("nan.stl"), stl);
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("nan.stl")), "nan.stl", "vertex 2", "non-finite coordinate (nan");
}

TEST(MeshIo, DegenerateTrianglesNameTheFace)
{
  mpm_test::Scratch_directory dir;
  write_bytes(dir.file("repeat.off"), "OFF\n3 2 0\n" + triangle_vertices + "3 0 1 2\n3 2 2 0\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("repeat.off")), "repeat.off: face 1: degenerate triangle (vertices 2, 2, 0)");
  write_bytes(dir.file("flat.off"), "OFF\n4 2 0\n" + triangle_vertices + "2 0 0\n3 0 1 2\n3 0 1 3\n");
  MPM_EXPECT_INPUT_ERROR(read_mesh_file(dir.file("flat.off")), "flat.off: face 1: degenerate triangle (zero area");
}

TEST(MeshIo, UnreferencedVerticesAreKeptWithAWarning)
{
  mpm_test::Scratch_directory dir;
  write_bytes(dir.file("extra.off"), "OFF\n5 1 0\n" + triangle_vertices + "5 5 5\n6 6 6\n3 0 1 2\n");
  const Mesh_file r = read_mesh_file(dir.file("extra.off"));
  EXPECT_EQ(r.mesh.number_of_vertices(), 5);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(mpm_test::contains_all(r.warnings[0], {"extra.off", "2 vertices are not used by any face (first: vertex 3)"}));
}

TEST(SegIo, ReadsWritesAndRejects)
{
  mpm_test::Scratch_directory dir;
  const std::vector<int> labels = {0, 3, 3, 1, 2147483647};
  write_seg_file(labels, dir.file("a.seg"));
  EXPECT_EQ(read_seg_file(dir.file("a.seg")), labels);
  write_bytes(dir.file("spaces.seg"), "  0 1\r\n\n2\t3\n");
  EXPECT_EQ(read_seg_file(dir.file("spaces.seg")), (std::vector<int>{0, 1, 2, 3}));

  write_bytes(dir.file("word.seg"), "0\n1\nfoot\n");
  MPM_EXPECT_INPUT_ERROR(read_seg_file(dir.file("word.seg")), "word.seg", "line 3", "\"foot\" is not an integer label");
  write_bytes(dir.file("float.seg"), "0\n1.5\n");
  MPM_EXPECT_INPUT_ERROR(read_seg_file(dir.file("float.seg")), "float.seg", "line 2", "not an integer");
  write_bytes(dir.file("neg.seg"), "0\n\n-4\n");
  MPM_EXPECT_INPUT_ERROR(read_seg_file(dir.file("neg.seg")), "neg.seg", "line 3", "negative label -4");
  write_bytes(dir.file("big.seg"), "99999999999999999999999\n");
  MPM_EXPECT_INPUT_ERROR(read_seg_file(dir.file("big.seg")), "big.seg", "line 1", "too large");
  write_bytes(dir.file("big2.seg"), "2147483648\n");
  MPM_EXPECT_INPUT_ERROR(read_seg_file(dir.file("big2.seg")), "big2.seg", "line 1", "too large");
  write_bytes(dir.file("empty.seg"), " \n\n");
  MPM_EXPECT_INPUT_ERROR(read_seg_file(dir.file("empty.seg")), "empty.seg", "empty");
  write_bytes(dir.file("binary.seg"), std::string("\x01\x02\xff\n", 4));
  MPM_EXPECT_INPUT_ERROR(read_seg_file(dir.file("binary.seg")), "binary.seg", "line 1");
  MPM_EXPECT_INPUT_ERROR(read_seg_file(dir.file("none.seg")), "none.seg", "file not found");
}

TEST(LabeledMesh, SegLabelsAreExpandedToTriangles)
{
  mpm_test::Scratch_directory dir;
  const std::string mesh = dir.file("quad.off");
  write_bytes(mesh, "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n4 0 1 2 3\n3 1 4 2\n");
  write_bytes(dir.file("quad.seg"), "7\n2\n");
  std::vector<std::string> warnings;
  const Labeled_mesh m = read_labeled_mesh(mesh, dir.file("quad.seg"), &warnings);
  EXPECT_EQ(m.face_labels, (std::vector<int>{7, 7, 2}));
  EXPECT_EQ(m.mesh.number_of_faces(), 3);
  EXPECT_EQ(m.source, mesh);
  EXPECT_EQ(warnings.size(), 1u);
  EXPECT_NO_THROW(validate_labeled_mesh(m));

  write_bytes(dir.file("short.seg"), "7\n");
  MPM_EXPECT_INPUT_ERROR(read_labeled_mesh(mesh, dir.file("short.seg")), "short.seg: has 1 labels but " + mesh + " has 2 faces");
  write_bytes(dir.file("long.seg"), "7\n1\n1\n");
  MPM_EXPECT_INPUT_ERROR(read_labeled_mesh(mesh, dir.file("long.seg")), "long.seg: has 3 labels but " + mesh + " has 2 faces");
}

TEST(LabeledMesh, ComponentsAreNumberedByFirstFace)
{
  mpm_test::Scratch_directory dir;
  Indexed_mesh m;
  m.points.resize(7, 3);
  m.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5, 6, 5, 5, 5, 6, 5, 1, 1, 0;
  // Faces 1 and 3 share only vertex 3 with nothing else: components need an edge.
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {1, 6, 2}, {3, 5, 4}};
  EXPECT_EQ(connected_component_labels(m), (std::vector<int>{0, 1, 0, 1}));
  Indexed_mesh touching = m;
  touching.triangles = {{3, 4, 5}, {0, 1, 2}, {2, 6, 5}};
  EXPECT_EQ(connected_component_labels(touching), (std::vector<int>{0, 1, 2}));

  write_mesh_file(m, dir.file("two.off"));
  EXPECT_EQ(read_labeled_mesh(dir.file("two.off"), "components").face_labels, (std::vector<int>{0, 1, 0, 1}));
}

TEST(LabeledMesh, PlyFaceProperty)
{
  mpm_test::Scratch_directory dir;
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 2\nproperty list uchar int vertex_indices\n";
  const std::string body = "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n";
  const std::string path = dir.file("parts.ply");
  write_bytes(path, header + "property int part\nproperty float weight\n" + body + "4 0 1 2 3 4 0.5\n3 1 4 2 9 1.5\n");
  EXPECT_EQ(read_labeled_mesh(path, "property:part").face_labels, (std::vector<int>{4, 4, 9}));
  MPM_EXPECT_INPUT_ERROR(read_labeled_mesh(path, "property:segment"), "parts.ply", "no face property \"segment\"", "part, weight");
  MPM_EXPECT_INPUT_ERROR(read_labeled_mesh(path, "property:weight"), "parts.ply", "floating-point");

  const std::string small = dir.file("small.ply");
  write_bytes(small, header + "property uchar part\n" + body + "4 0 1 2 3 4\n3 1 4 2 200\n");
  EXPECT_EQ(read_labeled_mesh(small, "property:part").face_labels, (std::vector<int>{4, 4, 200}));
  const std::string negative = dir.file("negative.ply");
  write_bytes(negative, header + "property int part\n" + body + "4 0 1 2 3 4\n3 1 4 2 -1\n");
  MPM_EXPECT_INPUT_ERROR(read_labeled_mesh(negative, "property:part"), "negative.ply", "face 1", "negative label -1");

  write_bytes(dir.file("t.off"), "OFF\n3 1 0\n" + triangle_vertices + "3 0 1 2\n");
  MPM_EXPECT_INPUT_ERROR(read_labeled_mesh(dir.file("t.off"), "property:part"), "t.off", "PLY");
}

TEST(LabeledMesh, ValidationNamesSourceAndElement)
{
  Labeled_mesh m;
  m.mesh = tetrahedron();
  m.face_labels = {0, 0, 1, 1};
  m.source = "memory tetra";
  EXPECT_NO_THROW(validate_labeled_mesh(m));
  Labeled_mesh bad = m;
  bad.face_labels.pop_back();
  MPM_EXPECT_INPUT_ERROR(validate_labeled_mesh(bad), "memory tetra", "3 face labels for 4 faces");
  bad = m;
  bad.face_labels[2] = -1;
  MPM_EXPECT_INPUT_ERROR(validate_labeled_mesh(bad), "memory tetra: face 2: negative label -1");
  bad = m;
  bad.mesh.points(3, 1) = std::numeric_limits<double>::infinity();
  MPM_EXPECT_INPUT_ERROR(validate_labeled_mesh(bad), "memory tetra: vertex 3: non-finite");
  bad = m;
  bad.mesh.triangles[1] = {0, 1, 4};
  MPM_EXPECT_INPUT_ERROR(validate_labeled_mesh(bad), "memory tetra: face 1: vertex index 4 is out of range");
  bad = m;
  bad.mesh.triangles[3] = {1, 2, 1};
  MPM_EXPECT_INPUT_ERROR(validate_labeled_mesh(bad), "memory tetra: face 3: degenerate");
  bad = m;
  bad.mesh.points.row(3) = 0.5 * (bad.mesh.points.row(1) + bad.mesh.points.row(0));
  MPM_EXPECT_INPUT_ERROR(validate_labeled_mesh(bad), "memory tetra: face 1: degenerate triangle (zero area");
}

TEST(AtomicFile, ReplacesWholeFilesAndLeavesNoTemporaries)
{
  mpm_test::Scratch_directory dir;
  const std::string path = dir.file("out.off");
  write_bytes(path, "old");
  write_mesh_file(tetrahedron(), path);
  EXPECT_EQ(read_mesh_file(path).mesh.points, tetrahedron().points);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.off"}));

  // A writer that fails midway leaves the old file and no temporary.
  const std::string before = read_bytes(path);
  EXPECT_THROW(internal::write_file_atomically(path, [](std::ostream& out) {
                 out << "partial";
                 throw std::runtime_error("interrupted");
               }),
               std::runtime_error);
  EXPECT_EQ(read_bytes(path), before);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.off"}));

  // A directory in the way is not replaced.
  mpm_test::fs::create_directory(dir.file("taken.off"));
  MPM_EXPECT_INPUT_ERROR(write_mesh_file(tetrahedron(), dir.file("taken.off")), "taken.off", "directory");
  EXPECT_TRUE(mpm_test::fs::is_directory(dir.file("taken.off")));
  MPM_EXPECT_INPUT_ERROR(write_seg_file({1}, dir.file("missing_dir/a.seg")), "a.seg", "cannot write");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.off", "taken.off"}));
  MPM_EXPECT_INPUT_ERROR(write_mesh_file(tetrahedron(), dir.file("out.xyz")), "out.xyz", "supported: .off, .obj, .ply, .stl");
}

TEST(AtomicFile, UnwritableDirectoryKeepsTheOldFile)
{
  if(geteuid() == 0) GTEST_SKIP() << "permissions do not restrict root";
  mpm_test::Scratch_directory dir;
  const std::string path = dir.file("keep.seg");
  write_seg_file({1, 2}, path);
  mpm_test::fs::permissions(dir.path(), mpm_test::fs::perms::owner_read | mpm_test::fs::perms::owner_exec);
  MPM_EXPECT_INPUT_ERROR(write_seg_file({3}, path), "keep.seg", "cannot write");
  mpm_test::fs::permissions(dir.path(), mpm_test::fs::perms::owner_all);
  EXPECT_EQ(read_seg_file(path), (std::vector<int>{1, 2}));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"keep.seg"}));
}

TEST(AtomicFile, ReadFileRejectsMissingFilesAndDirectories)
{
  mpm_test::Scratch_directory dir;
  MPM_EXPECT_INPUT_ERROR(internal::read_file(dir.file("nope")), "nope: file not found");
  MPM_EXPECT_INPUT_ERROR(internal::read_file(dir.path().string()), "is a directory");
  write_bytes(dir.file("bytes"), std::string("a\0b\r\n", 5));
  EXPECT_EQ(internal::read_file(dir.file("bytes")), std::string("a\0b\r\n", 5));
}
