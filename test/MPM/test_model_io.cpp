// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Io_test_support.h"

#include <CGAL/MPM/IO/Model_io.h>

#include <boost/crc.hpp>

#include <random>

using namespace CGAL::MPM;

namespace {

// Three faces around vertex 0 and two more closing the fan around vertex 1:
// a manifold surface with a border.
std::vector<Triangle> sample_triangles() { return {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 4, 3}, {1, 2, 4}}; }

std::string payload_of(const std::string& file);
std::string wrap_payload(const std::string& payload);

Rigid_motion motion(double angle, double shift)
{
  Rigid_motion m;
  m.rotation = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  m.translation = Eigen::Vector3d(shift, -shift, 0.5);
  return m;
}

Shape_space space(int points, int modes, int instances)
{
  Shape_space s;
  s.mean = Point_matrix::Random(points, 3);
  s.modes = Eigen::MatrixXd::Random(3 * points, modes);
  s.sigmas = Eigen::VectorXd::LinSpaced(modes, 1.5, 0.5);
  s.variances = Eigen::VectorXd::LinSpaced(modes + 2, 2.25, 0.);
  s.instance_coordinates = Eigen::MatrixXd::Random(modes, instances);
  for(int i = 0; i < instances; ++i) {
    s.instance_motions.push_back(motion(0.1 * i, i));
    s.instance_residuals.push_back(1e-3 * i);
  }
  return s;
}

// A small model that sets every field to something other than its default.
Morphable_part_model sample_model()
{
  Morphable_part_model m;
  m.parameters = {0.05, 0.1 / 3, 0.2, 2, 0.97};

  Part_type palm;
  palm.name = "palm";
  palm.number_of_vertices = 4;
  palm.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  palm.edges = {{0, 1, false}, {0, 2, false}, {0, 3, false}, {1, 2, false}, {1, 3, false}, {2, 3, false}};
  palm.sites = {{Docking_kind::boundary, {1, 2}}};
  palm.space = space(4, 1, 2);
  Part_type tip;
  tip.name = "finger tip";
  tip.number_of_vertices = 3;
  tip.triangles = {{0, 1, 2}};
  tip.edges = {{0, 1, false}, {1, 2, false}, {0, 2, true}};
  tip.sites = {{Docking_kind::generalized, {0}}, {Docking_kind::boundary, {0, 1}}};
  tip.space = space(3, 0, 1);
  m.types = {palm, tip};

  Docking_rule rule;
  rule.first = {0, 0};
  rule.second = {1, 1};
  rule.kind = Docking_kind::boundary;
  rule.seam = {{1, 0}, {2, 1}};
  rule.points = {{0, 1}, {0, 2}, {1, 2}};
  rule.edges = {{0, 1, false}, {1, 2, true}};
  rule.space = space(3, 2, 2);
  m.rules = {rule};

  Labeled_mesh surface;
  surface.mesh.points = Point_matrix::Random(5, 3);
  surface.mesh.triangles = sample_triangles();
  surface.face_labels = {0, 0, 0, 0, 3};
  Part_node a;
  a.type = 0;
  a.label = 0;
  a.vertices = {0, 1, 2, 3};
  a.coordinates = Eigen::VectorXd::Constant(1, 0.25);
  a.motion = motion(0.3, 1);
  Part_node b;
  b.type = 1;
  b.label = 3;
  b.vertices = {1, 2, 4};
  b.motion = motion(-0.2, 2);
  Part_edge g;
  g.first = 0;
  g.second = 1;
  g.rule = 0;
  g.coordinates = Eigen::Vector2d(0.5, -0.5);
  g.motion = motion(0.7, 3);
  Part_graph graph;
  graph.nodes = {a, b};
  graph.edges = {g};
  m.examples = {make_training_example("hand.off", surface, graph)};
  return m;
}

// `file` with the bytes `from` of its payload (found once) replaced by `to`,
// its checksum and length made right: a file whose damage only the model's
// consistency checks can find.
std::string with_payload_bytes_replaced(const std::string& file, const std::string& from, const std::string& to)
{
  std::string payload = payload_of(file);
  const std::size_t at = payload.find(from);
  EXPECT_NE(at, std::string::npos);
  EXPECT_EQ(payload.find(from, at + 1), std::string::npos);
  return wrap_payload(payload.replace(at, from.size(), to));
}

// Integers as the model file writes them, little-endian: a count (8 bytes)
// or an int (4).
std::string encoded(std::initializer_list<std::pair<std::uint64_t, int>> values)
{
  std::string r;
  for(const auto& [value, bytes] : values)
    for(int i = 0; i < bytes; ++i) r.push_back(char(value >> (8 * i)));
  return r;
}

// A file around `payload` with a correct header and checksum, to reach the
// payload parser with corrupt contents.
std::string wrap_payload(const std::string& payload)
{
  boost::crc_32_type crc;
  crc.process_bytes(payload.data(), payload.size());
  return std::string("CGALMPM\n", 8) + encoded({{model_file_version, 4}, {payload.size(), 8}}) + payload +
         encoded({{crc.checksum(), 4}});
}

std::string payload_of(const std::string& file) { return file.substr(20, file.size() - 24); }

} // namespace

TEST(ModelIo, HeaderLayout)
{
  const std::string bytes = serialize_model(sample_model());
  EXPECT_EQ(bytes.substr(0, 8), "CGALMPM\n");
  EXPECT_EQ(bytes.substr(8, 4), std::string("\x03\x00\x00\x00", 4)); // format version 3
  std::uint64_t length = 0;
  for(int i = 0; i < 8; ++i) length |= std::uint64_t(static_cast<unsigned char>(bytes[12 + i])) << (8 * i);
  EXPECT_EQ(length + 24, bytes.size());
  EXPECT_TRUE(wrap_payload(payload_of(bytes)) == bytes);
}

TEST(ModelIo, RoundTripIsByteIdenticalAndKeepsEveryField)
{
  const Morphable_part_model m = sample_model();
  const std::string bytes = serialize_model(m);
  const Morphable_part_model r = deserialize_model(bytes, "memory");
  EXPECT_TRUE(serialize_model(r) == bytes);

  EXPECT_EQ(r.parameters.sigma_bound, m.parameters.sigma_bound);
  EXPECT_EQ(r.parameters.modes, 2);
  ASSERT_EQ(r.types.size(), 2u);
  EXPECT_EQ(r.types[1].name, "finger tip");
  EXPECT_EQ(r.types[1].edges[2].is_virtual, true);
  EXPECT_EQ(r.types[1].sites[0].kind, Docking_kind::generalized);
  EXPECT_EQ(r.types[0].space.mean, m.types[0].space.mean);
  EXPECT_EQ(r.types[0].space.modes, m.types[0].space.modes);
  EXPECT_EQ(r.types[0].space.variances, m.types[0].space.variances);
  EXPECT_EQ(r.types[0].space.instance_coordinates, m.types[0].space.instance_coordinates);
  EXPECT_EQ(r.types[0].space.instance_motions[1].rotation, m.types[0].space.instance_motions[1].rotation);
  EXPECT_EQ(r.types[0].space.instance_residuals, m.types[0].space.instance_residuals);
  EXPECT_EQ(r.types[1].space.modes.rows(), 9);
  EXPECT_EQ(r.types[1].space.modes.cols(), 0);
  EXPECT_EQ(r.rules[0].second.site, 1);
  EXPECT_EQ(r.rules[0].seam, m.rules[0].seam);
  EXPECT_EQ(r.rules[0].points[2].side, 1);
  EXPECT_EQ(r.examples[0].name, "hand.off");
  EXPECT_EQ(to_labeled_mesh(r.examples[0]).mesh.points, to_labeled_mesh(m.examples[0]).mesh.points);
  EXPECT_EQ(to_labeled_mesh(r.examples[0]).face_labels, to_labeled_mesh(m.examples[0]).face_labels);
  EXPECT_EQ(r.examples[0].graph.nodes[1].label, 3);
  EXPECT_EQ(r.examples[0].graph.edges[0].coordinates, m.examples[0].graph.edges[0].coordinates);
  EXPECT_EQ(r.examples[0].graph.edges[0].motion.translation, m.examples[0].graph.edges[0].motion.translation);

  const Morphable_part_model empty;
  EXPECT_EQ(serialize_model(deserialize_model(serialize_model(empty), "empty")), serialize_model(empty));
}

TEST(ModelIo, SaveAndLoadFiles)
{
  mpm_test::Scratch_directory dir;
  const std::string path = dir.file("hand.mpm");
  const Morphable_part_model m = sample_model();
  save_model(m, path);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"hand.mpm"}));
  const std::string bytes = mpm_test::read_bytes(path);
  EXPECT_TRUE(bytes == serialize_model(m));
  EXPECT_TRUE(serialize_model(load_model(path)) == bytes);
  EXPECT_TRUE(mpm_test::read_bytes(path) == bytes) << "input modified";
  MPM_EXPECT_INPUT_ERROR(load_model(dir.file("none.mpm")), "none.mpm", "file not found");
  mpm_test::fs::create_directory(dir.file("hand2.mpm"));
  MPM_EXPECT_INPUT_ERROR(save_model(sample_model(), dir.file("hand2.mpm")), "hand2.mpm", "directory");
}

TEST(ModelIo, ForeignAndOtherVersionFiles)
{
  mpm_test::Scratch_directory dir;
  mpm_test::write_bytes(dir.file("mesh.mpm"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  MPM_EXPECT_INPUT_ERROR(load_model(dir.file("mesh.mpm")), "mesh.mpm: not a CGAL-MPM model file");
  mpm_test::write_bytes(dir.file("empty.mpm"), "");
  MPM_EXPECT_INPUT_ERROR(load_model(dir.file("empty.mpm")), "empty.mpm: not a CGAL-MPM model file");

  std::string bytes = serialize_model(sample_model());
  bytes[8] = 7;
  MPM_EXPECT_INPUT_ERROR(deserialize_model(bytes, "old.mpm"), "old.mpm: model format version 7, this build reads version 3");
}

TEST(ModelIo, DamagedFiles)
{
  const std::string bytes = serialize_model(sample_model());
  MPM_EXPECT_INPUT_ERROR(deserialize_model(bytes.substr(0, 5), "a.mpm"), "a.mpm: damaged model file (truncated");
  MPM_EXPECT_INPUT_ERROR(deserialize_model(bytes.substr(0, 30), "a.mpm"), "a.mpm: damaged model file (truncated");
  MPM_EXPECT_INPUT_ERROR(deserialize_model(bytes.substr(0, bytes.size() - 1), "a.mpm"), "a.mpm: damaged model file (truncated");
  MPM_EXPECT_INPUT_ERROR(deserialize_model(bytes + "x", "a.mpm"), "a.mpm: damaged model file (length mismatch");
  for(std::size_t at : {std::size_t(20), bytes.size() / 2, bytes.size() - 5, bytes.size() - 1}) {
    std::string flipped = bytes;
    flipped[at] = char(flipped[at] ^ 0x10);
    MPM_EXPECT_INPUT_ERROR(deserialize_model(flipped, "a.mpm"), "a.mpm: damaged model file (checksum mismatch)");
  }
}

TEST(ModelIo, CorruptPayloadsWithValidChecksumsAreRejected)
{
  // A count of 2^60 part types must not be allocated.
  std::string payload = payload_of(serialize_model(Morphable_part_model()));
  payload[8 * 3 + 4 + 8 + 7] = 0x10;
  MPM_EXPECT_INPUT_ERROR(deserialize_model(wrap_payload(payload), "big.mpm"), "big.mpm: damaged model file (a count of");

  // Truncated or bit-flipped payloads behind a valid checksum fail cleanly.
  const std::string good = payload_of(serialize_model(sample_model()));
  for(std::size_t n = 0; n < good.size(); n += 7)
    MPM_EXPECT_INPUT_ERROR(deserialize_model(wrap_payload(good.substr(0, n)), "cut.mpm"), "cut.mpm: ");
  std::mt19937 random(3);
  for(int trial = 0; trial < 2000; ++trial) {
    std::string p = good;
    for(int k = 0; k < 3; ++k) p[random() % p.size()] ^= char(1 << (random() % 8));
    try {
      deserialize_model(wrap_payload(p), "fuzz.mpm");
    } catch(const Input_error& e) {
      EXPECT_EQ(e.source(), "fuzz.mpm");
    }
  }
}

TEST(ModelIo, InconsistentIndicesNameTheElement)
{
  auto expect_file = [](const std::string& file, const std::string& element, const std::string& problem) {
    try {
      deserialize_model(file, "bad.mpm");
      ADD_FAILURE() << "no error for " << element;
    } catch(const Input_error& e) {
      EXPECT_EQ(e.element(), element);
      EXPECT_TRUE(mpm_test::contains_all(e.what(), {"bad.mpm", problem}));
    }
  };
  auto expect = [&](const Morphable_part_model& m, const std::string& element, const std::string& problem) {
    expect_file(serialize_model(m), element, problem);
  };
  Morphable_part_model m = sample_model();
  m.types[0].triangles[3][1] = 4;
  expect(m, "part type 0 (\"palm\") triangle 3", "vertex 4 is out of range (4)");
  m = sample_model();
  m.types[1].edges[0].target = -1;
  expect(m, "part type 1 (\"finger tip\") edge 0", "target -1 is out of range");
  m = sample_model();
  m.types[0].sites[0].vertices.push_back(9);
  expect(m, "part type 0 (\"palm\") site 0", "vertex 9");
  m = sample_model();
  m.types[0].space.mean.conservativeResize(3, 3);
  expect(m, "part type 0 (\"palm\") shape space", "mean of 3 points for 4");
  m = sample_model();
  m.types[0].space.sigmas.resize(2);
  expect(m, "part type 0 (\"palm\") shape space", "2 standard deviations for 1 modes");
  m = sample_model();
  m.rules[0].first.site = 5;
  expect(m, "rule 0 first site", "site 5 is out of range (1)");
  m = sample_model();
  m.rules[0].second.type = 2;
  expect(m, "rule 0 second site", "part type 2 is out of range");
  m = sample_model();
  m.rules[0].seam[1].second = 3;
  expect(m, "rule 0 seam pair 1", "second vertex 3");
  m = sample_model();
  m.rules[0].points[0].side = 2;
  expect(m, "rule 0 point 0", "side 2");
  m = sample_model();
  m.rules[0].edges[1].target = 3;
  expect(m, "rule 0 edge 1", "target 3");
  m = sample_model();
  // A face label less: labels {0, 0, 0, 0, 3} become {0, 0, 0, 0}.
  expect_file(with_payload_bytes_replaced(serialize_model(m), encoded({{5, 8}, {0, 4}, {0, 4}, {0, 4}, {0, 4}, {3, 4}}),
                                          encoded({{4, 8}, {0, 4}, {0, 4}, {0, 4}, {0, 4}})),
              "example 0 (\"hand.off\")", "4 face labels for 5 faces");
  // A triangle a surface mesh cannot hold: the last one repeats the first.
  expect_file(with_payload_bytes_replaced(serialize_model(m), encoded({{1, 4}, {2, 4}, {4, 4}, {5, 8}}),
                                          encoded({{0, 4}, {2, 4}, {1, 4}, {5, 8}})),
              "example 0 (\"hand.off\") face 4", "non-manifold edge or vertex");
  m = sample_model();
  m.examples[0].graph.nodes[1].type = 7;
  expect(m, "example 0 (\"hand.off\") node 1", "part type 7");
  m = sample_model();
  m.examples[0].graph.nodes[0].vertices[2] = 5;
  expect(m, "example 0 (\"hand.off\") node 0", "mesh vertex 5");
  m = sample_model();
  m.examples[0].graph.edges[0].rule = 1;
  expect(m, "example 0 (\"hand.off\") edge 0", "rule 1 is out of range");
  m = sample_model();
  std::swap(m.examples[0].graph.edges[0].first, m.examples[0].graph.edges[0].second);
  expect(m, "example 0 (\"hand.off\") edge 0", "not of the part types rule 0 docks");
}

// A docking of a stitched training example carries its own merged seam;
// the part it inserts a vertex into lists that vertex after its own.
TEST(ModelIo, EdgeMergedSeamsRoundTripAndAreChecked)
{
  Morphable_part_model m = sample_model();
  Seam_vertex v;
  v.parameter = 0.25;
  v.local = {{1, -1}};
  v.from = {{-1, 0}};
  v.to = {{-1, 1}};
  v.weight = {{0., 0.5}};
  m.examples[0].graph.edges[0].merged_seam = {v};
  m.examples[0].graph.nodes[1].vertices.push_back(1);
  const std::string bytes = serialize_model(m);
  const Morphable_part_model r = deserialize_model(bytes, "memory");
  EXPECT_TRUE(serialize_model(r) == bytes);
  ASSERT_EQ(r.examples[0].graph.edges[0].merged_seam.size(), 1u);
  EXPECT_EQ(r.examples[0].graph.edges[0].merged_seam[0].weight[1], 0.5);
  EXPECT_EQ(r.examples[0].graph.edges[0].merged_seam[0].from[1], 0);

  Morphable_part_model bad = m;
  bad.examples[0].graph.nodes[1].vertices.pop_back();
  MPM_EXPECT_INPUT_ERROR(deserialize_model(serialize_model(bad), "bad.mpm"),
                         "bad.mpm: example 0 (\"hand.off\") node 1", "3 vertices", "1 inserted seam vertices");
  bad = m;
  bad.examples[0].graph.edges[0].merged_seam[0].to[1] = 3;
  MPM_EXPECT_INPUT_ERROR(deserialize_model(serialize_model(bad), "bad.mpm"),
                         "example 0 (\"hand.off\") edge 0 merged seam vertex 0", "split edge end 3");
  bad = m;
  bad.examples[0].graph.edges[0].merged_seam[0].to[1] = 2; // 0 -> 2 is not a border half-edge of the tip
  MPM_EXPECT_INPUT_ERROR(deserialize_model(serialize_model(bad), "bad.mpm"), "bad.mpm", "not a border edge");
}
