// Handle sets: the JSON file format (round trip, every error case) and the
// deterministic generators used by tests and benchmarks.
#include "Io_test_support.h"

#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace CGAL::MPM;
using mpm_test::Scratch_directory;

namespace {

// Four vertices at distinct, easily recognised places.
Point_matrix rest_positions()
{
  Point_matrix p(4, 3);
  p << 0, 0, 0,
       1, 0, 0,
       0, 2, 0,
       0, 0, 3;
  return p;
}

std::string handles_text(const std::string& entries)
{
  return R"({"format": "cgal-mpm-handles", "version": 1, "handles": [)" + entries + "]}";
}

Synthetic_model small_hexa_grid()
{
  Synthetic_options o;
  o.vertices = 2000;
  return make_synthetic_model(Synthetic_family::hexa_grid, o);
}

} // namespace

TEST(Handle_set, parses_targets_and_offsets)
{
  const Handle_set h = parse_handles(
      handles_text(R"({"vertex": 2, "target": [5, 6, 7]}, {"vertex": 3, "offset": [1, 1, -1]})"), "h.json",
      rest_positions());
  ASSERT_EQ(h.size(), 2);
  EXPECT_EQ(h.vertices, (std::vector<int>{2, 3}));
  EXPECT_EQ(h.targets.row(0), Eigen::RowVector3d(5, 6, 7));
  EXPECT_EQ(h.targets.row(1), Eigen::RowVector3d(1, 1, 2));
}

TEST(Handle_set, merges_identical_duplicates)
{
  const Handle_set h = parse_handles(
      handles_text(R"({"vertex": 1, "target": [2, 0, 0]}, {"vertex": 1, "offset": [1, 0, 0]})"), "h.json",
      rest_positions());
  ASSERT_EQ(h.size(), 1);
  EXPECT_EQ(h.targets.row(0), Eigen::RowVector3d(2, 0, 0));
}

TEST(Handle_set, file_round_trip_is_exact)
{
  const Synthetic_model model = small_hexa_grid();
  const Handle_set h = farthest_point_handles(model.mesh.mesh, 8, model.draw_pose(7));
  Scratch_directory dir;
  const std::string path = dir.file("handles.json");
  write_handles(h, path);
  const Handle_set back = read_handles(path, model.mesh.mesh.points);
  EXPECT_EQ(back.vertices, h.vertices);
  EXPECT_EQ(back.targets, h.targets);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"handles.json"});
}

TEST(Handle_set, each_error_names_the_file_and_the_handle)
{
  const Point_matrix rest = rest_positions();
  Scratch_directory dir;
  const auto error_of_file = [&](const std::string& entries) {
    const std::string path = dir.file("bad.json");
    mpm_test::write_bytes(path, handles_text(entries));
    return mpm_test::input_error_message([&] { read_handles(path, rest); });
  };
  const std::string ok = R"({"vertex": 0, "target": [0, 0, 0]}, )";
  const std::string file = dir.file("bad.json");

  EXPECT_TRUE(mpm_test::contains_all(error_of_file(ok + ok + ok + R"({"vertex": 4, "target": [0, 0, 0]})"),
                                     {file, "handles[3]", "out of range", "4 vertices"}));
  EXPECT_TRUE(mpm_test::contains_all(error_of_file(ok + R"({"vertex": 1, "target": [1e999, 0, 0]})"),
                                     {file, "malformed JSON", "1e999"}));
  EXPECT_TRUE(mpm_test::contains_all(
      error_of_file(ok + R"({"vertex": 1, "target": [0, 0, 0], "offset": [0, 0, 0]})"),
      {file, "handles[1]", "both"}));
  EXPECT_TRUE(mpm_test::contains_all(error_of_file(ok + R"({"vertex": 1})"), {file, "handles[1]", "neither"}));
  EXPECT_TRUE(mpm_test::contains_all(
      error_of_file(R"({"vertex": 2, "target": [0, 0, 0]}, {"vertex": 2, "target": [0, 0, 1]})"),
      {file, "handles[1]", "different target", "handles[0]"}));
  EXPECT_TRUE(mpm_test::contains_all(error_of_file(""), {file, "handles", "no handles"}));
  EXPECT_TRUE(mpm_test::contains_all(error_of_file(ok + R"({"vertex": 1, "traget": [0, 0, 0]})"),
                                     {file, "handles[1]", "unknown key \"traget\""}));
  EXPECT_TRUE(mpm_test::contains_all(error_of_file(ok + R"({"vertex": 1, "target": [0, 0]})"),
                                     {file, "handles[1].target", "3 numbers"}));
  EXPECT_TRUE(mpm_test::contains_all(error_of_file(ok + R"({"vertex": -1, "target": [0, 0, 0]})"),
                                     {file, "handles[1].vertex", "negative"}));

  Point_matrix huge = rest;
  huge(1, 1) = -1.7e308;
  MPM_EXPECT_INPUT_ERROR(parse_handles(handles_text(ok + R"({"vertex": 1, "offset": [0, -1.7e308, 0]})"), "h.json",
                                       huge),
                         "h.json", "handles[1]", "not finite");
  MPM_EXPECT_INPUT_ERROR(parse_handles(R"({"handles": [)", "h.json", rest), "h.json", "malformed JSON");
  MPM_EXPECT_INPUT_ERROR(parse_handles(R"({"handles": [], "extra": 1})", "h.json", rest), "h.json",
                         "unknown key \"extra\"");
  MPM_EXPECT_INPUT_ERROR(parse_handles(R"({"format": "cgal-mpm-annotation", "handles": []})", "h.json", rest),
                         "h.json", "format", "cgal-mpm-handles");
  MPM_EXPECT_INPUT_ERROR(parse_handles("{}", "h.json", rest), "h.json", "no handles");
  MPM_EXPECT_INPUT_ERROR(read_handles(dir.file("missing.json"), rest), dir.file("missing.json"));
}

TEST(Handle_set, writer_rejects_what_the_format_cannot_hold)
{
  Handle_set h;
  h.vertices = {0, 1};
  h.targets = Point_matrix::Zero(2, 3);
  h.targets(1, 2) = std::numeric_limits<double>::quiet_NaN();
  MPM_EXPECT_INPUT_ERROR(handles_to_json(h), "handles[1]", "not finite");
  h.vertices = {0, 0};
  h.targets.setZero();
  MPM_EXPECT_INPUT_ERROR(handles_to_json(h), "handles[1]", "handles[0]");
  h.vertices = {0};
  MPM_EXPECT_INPUT_ERROR(handles_to_json(h), "1 handle vertices but 2 targets");
}

TEST(Handle_set, farthest_point_sampling_is_deterministic_and_spread)
{
  const Point_matrix rest = rest_positions();
  Indexed_mesh mesh;
  mesh.points = rest;
  // Centroid (0.25, 0.5, 0.75): vertex 3 is farthest; then 2 (distance
  // sqrt(13) to vertex 3), then 1 (sqrt(5) to vertex 2 beats 0's 2).
  const Handle_set h = farthest_point_handles(mesh, 3, 2 * rest);
  EXPECT_EQ(h.vertices, (std::vector<int>{3, 2, 1}));
  EXPECT_EQ(h.targets.row(0), Eigen::RowVector3d(0, 0, 6));
  EXPECT_EQ(farthest_point_handles(mesh, 4, rest).vertices, (std::vector<int>{3, 2, 1, 0}));

  // Coincident vertices: ties go to the smallest index, none is chosen twice.
  mesh.points = Point_matrix::Zero(3, 3);
  EXPECT_EQ(farthest_point_handles(mesh, 3, mesh.points).vertices, (std::vector<int>{0, 1, 2}));

  MPM_EXPECT_INPUT_ERROR(farthest_point_handles(mesh, 4, mesh.points), "handle count", "[1, 3]");
  MPM_EXPECT_INPUT_ERROR(farthest_point_handles(mesh, 0, mesh.points), "handle count");
  MPM_EXPECT_INPUT_ERROR(farthest_point_handles(mesh, 1, rest), "4 rows", "3 vertices");

  const Synthetic_model model = small_hexa_grid();
  const Handle_set many = farthest_point_handles(model.mesh.mesh, 16, model.mesh.mesh.points);
  EXPECT_EQ(std::set<int>(many.vertices.begin(), many.vertices.end()).size(), 16u);
  EXPECT_EQ(many.vertices, farthest_point_handles(model.mesh.mesh, 16, model.mesh.mesh.points).vertices);
}

TEST(Handle_set, handles_per_part_gives_one_or_two_per_part)
{
  const Synthetic_model model = small_hexa_grid();
  const Labeled_mesh& m = model.mesh;
  const std::set<int> labels(m.face_labels.begin(), m.face_labels.end());
  const Point_matrix pose = model.draw_pose(3);

  const Handle_set one = handles_per_part(m, 1, pose);
  const Handle_set two = handles_per_part(m, 2, pose);
  EXPECT_EQ(one.size(), int(labels.size()));
  EXPECT_GT(two.size(), one.size());
  EXPECT_LE(two.size(), 2 * int(labels.size()));
  EXPECT_NO_THROW(validate_handles(two, m.mesh.number_of_vertices(), "two per part"));
  for(int i = 0; i < two.size(); ++i) EXPECT_EQ(two.targets.row(i), pose.row(two.vertices[std::size_t(i)]));

  MPM_EXPECT_INPUT_ERROR(handles_per_part(m, 3, pose), "handles per part", "1 or 2");
}
