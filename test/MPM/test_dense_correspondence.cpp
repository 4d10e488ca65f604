// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Dense correspondence of same-type parts with different triangulations:
// errors against the synthetic ground truth after independent remeshing,
// learning from such parts, and bad input.
#include "Tube_mesh.h"
#include "Tool_test_support.h"

#include <CGAL/MPM/Baselines/Correspondence_evaluation.h>
#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <CGAL/MPM/IO/Mesh_io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MPM/IO/Face_graph_conversion.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include "Learned_models.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include <unistd.h>

namespace {

using namespace CGAL::MPM;
using mpm_test::small_hand;

const std::vector<Correspondence_type_report>& hand_reports()
{
  static const std::vector<Correspondence_type_report> reports = evaluate_correspondence_on_remeshed(small_hand());
  return reports;
}

// A tube: `rings` rings of `sides` vertices, open at both ends.
Indexed_mesh tube(int rings, int sides, double length)
{
  Indexed_mesh m;
  m.points.resize(rings * sides, 3);
  const double pi = std::acos(-1.);
  for(int r = 0; r < rings; ++r)
    for(int s = 0; s < sides; ++s)
      m.points.row(r * sides + s) << std::cos(2 * pi * s / sides), std::sin(2 * pi * s / sides), length * r / (rings - 1);
  m.triangles = mpm_test::tube_triangles(rings, sides);
  return m;
}

// A tube closed at the top by a fan: one boundary loop.
Indexed_mesh capped_tube(int rings, int sides, double length)
{
  Indexed_mesh m = tube(rings, sides, length);
  const int apex = m.number_of_vertices();
  m.points.conservativeResize(apex + 1, 3);
  m.points.row(apex) << 0., 0., length * 1.2;
  const int top = (rings - 1) * sides;
  for(int s = 0; s < sides; ++s) m.triangles.push_back({top + s, top + (s + 1) % sides, apex});
  return m;
}

// A thorax: a sphere (an icosahedron subdivided by CGAL's Loop
// subdivision, stretched along y by `stretch`) with eight round holes:
// a head at -y, an abdomen at +y and six legs, left and right at three
// heights, of radii `legs` (radians). Seam tags: head 1, abdomen 2, legs 3.
struct Thorax
{
  Indexed_mesh mesh;
  std::vector<int> seam_tags;
  std::vector<Eigen::Vector3d> hole_centres; // head, abdomen, then the legs
};

Thorax thorax(const std::array<double, 6>& legs, double stretch, const Eigen::Matrix3d& rotation)
{
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> sphere;
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  CGAL::make_icosahedron<decltype(sphere), Point>(sphere, Point(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(sphere, CGAL::parameters::number_of_iterations(4));
  Indexed_mesh round = to_indexed_mesh(sphere);
  std::vector<Eigen::Vector3d> directions{{0, -1, 0}, {0, 1, 0}};
  std::vector<double> radii{0.3, 0.35};
  for(int k = 0; k < 6; ++k)
  {
    directions.push_back(Eigen::Vector3d(k % 2 ? 0.8 : -0.8, 0.9 * (k / 2 - 1), -0.4).normalized());
    radii.push_back(legs[std::size_t(k)]);
  }
  Thorax t;
  std::vector<int> hole_of_face;
  std::vector<Triangle> kept;
  for(const Triangle& f : round.triangles)
  {
    const Eigen::Vector3d c =
      (round.points.row(f[0]) + round.points.row(f[1]) + round.points.row(f[2])).transpose().normalized();
    int hole = -1;
    for(std::size_t h = 0; h < directions.size(); ++h)
      if(std::acos(std::clamp(c.dot(directions[h]), -1., 1.)) < radii[h]) hole = int(h);
    if(hole < 0) kept.push_back(f);
  }
  std::map<int, int> local;
  for(Triangle& f : kept)
    for(int& v : f) v = local.insert({v, int(local.size())}).first->second;
  t.mesh.triangles = kept;
  t.mesh.points.resize(Eigen::Index(local.size()), 3);
  const Eigen::Vector3d scale(1., stretch, 1.);
  for(const auto& [old, v] : local)
    t.mesh.points.row(v) = (rotation * round.points.row(old).transpose().normalized().cwiseProduct(scale)).transpose();
  for(const Eigen::Vector3d& d : directions) t.hole_centres.push_back(rotation * d.cwiseProduct(scale));
  t.seam_tags.assign(local.size(), -1);
  for(const std::vector<int>& loop : boundary_loops(t.mesh))
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(int v : loop) c += t.mesh.points.row(v).transpose();
    c /= double(loop.size());
    std::size_t nearest = 0;
    for(std::size_t h = 1; h < t.hole_centres.size(); ++h)
      if((t.hole_centres[h] - c).norm() < (t.hole_centres[nearest] - c).norm()) nearest = h;
    for(int v : loop) t.seam_tags[std::size_t(v)] = nearest < 2 ? int(nearest) + 1 : 3;
  }
  return t;
}

// Too many seams to try every order (8! here): the legs, alike in tag and
// nearly in length, and longest in a different order on the two segments,
// must still each land on their own leg, not on the next one by length.
TEST(Dense_correspondence, eight_seams_each_land_on_their_own_hole)
{
  const Thorax a = thorax({0.20, 0.21, 0.22, 0.23, 0.24, 0.25}, 1., Eigen::Matrix3d::Identity());
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Thorax b = thorax({0.25, 0.24, 0.23, 0.22, 0.21, 0.20}, 1.25, turn);
  std::vector<Correspondence_segment> pair(2);
  pair[0].mesh = a.mesh;
  pair[0].seam_tags = a.seam_tags;
  pair[0].name = "thorax a";
  pair[1].mesh = b.mesh;
  pair[1].seam_tags = b.seam_tags;
  pair[1].name = "thorax b";
  ASSERT_EQ(boundary_loops(a.mesh).size(), 8u);
  ASSERT_EQ(boundary_loops(b.mesh).size(), 8u);
  const Dense_correspondence c = compute_dense_correspondence(pair, "thorax");
  const Point_matrix& on_b = c.segments[1].positions;
  for(const std::vector<int>& loop : boundary_loops(a.mesh))
  {
    Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
    for(int v : loop) from += a.mesh.points.row(v).transpose(), to += on_b.row(v).transpose();
    from /= double(loop.size()), to /= double(loop.size());
    std::size_t hole = 0, lands = 0;
    for(std::size_t h = 1; h < a.hole_centres.size(); ++h)
    {
      if((a.hole_centres[h] - from).norm() < (a.hole_centres[hole] - from).norm()) hole = h;
      if((b.hole_centres[h] - to).norm() < (b.hole_centres[lands] - to).norm()) lands = h;
    }
    EXPECT_EQ(lands, hole) << "hole " << hole << " of the template lands on hole " << lands;
  }
  EXPECT_LT(c.segments[1].residual, 0.01);
  EXPECT_LT(c.segments[1].flipped_faces, int(c.triangles.size() / 100));
}

// A capped tube of radius 1 and `length` curled about the y axis by
// `curl` radians over its length (the axis along an arc), its seam at z = 0.
Indexed_mesh curled_capped_tube(int rings, int sides, double length, double curl)
{
  Indexed_mesh m = capped_tube(rings, sides, length);
  if(curl == 0.) return m;
  const double radius = length / curl;
  for(Eigen::Index v = 0; v < m.points.rows(); ++v)
  {
    const double x = m.points(v, 0), z = m.points(v, 2), angle = z / radius;
    m.points(v, 0) = (radius - x) * -std::cos(angle) + radius;
    m.points(v, 2) = (radius - x) * std::sin(angle);
  }
  return m;
}

// An arm that curls through three quarters of a turn, put in correspondence
// with a straight one of another triangulation: each template vertex must
// land at its own height along the arm (the position along the tube is the
// curled arm's arc length), where a rigid start and a spline pulled the
// template across the curl.
TEST(Dense_correspondence, curled_arm_is_followed_along_its_length)
{
  const double length = 12., curl = 1.5 * 3.141592653589793;
  std::vector<Correspondence_segment> pair(2);
  pair[0].mesh = capped_tube(25, 16, length);
  pair[0].name = "straight arm";
  pair[1].mesh = curled_capped_tube(40, 12, length, curl);
  pair[1].name = "curled arm";
  const Dense_correspondence c = compute_dense_correspondence(pair, "arm");
  const Point_matrix& on_curl = c.segments[1].positions;
  const double radius = length / curl;
  double worst = 0., sum = 0.;
  int count = 0;
  for(Eigen::Index v = 0; v < pair[0].mesh.points.rows(); ++v)
  {
    const double height = pair[0].mesh.points(v, 2);
    if(height > length) continue; // the cap
    const Eigen::Vector3d p = on_curl.row(v).transpose();
    // Arc length of the curled point: the angle of (x - radius, z) about the centre of the curl.
    const double angle = std::atan2(p.z(), radius - p.x());
    const double arc = (angle < -0.5 ? angle + 2 * 3.141592653589793 : angle) * radius;
    worst = std::max(worst, std::abs(arc - height));
    sum += std::abs(arc - height);
    ++count;
  }
  std::cout << "  along the arm: worst " << worst << ", mean " << sum / count << " of " << length << "\n";
  // Measured: worst 3.0, mean 0.94 (positions along the tube come from
  // shortest paths, which run along the inside of the curl: the outside is
  // crowded towards the seam); 11.7 and 2.9 placed rigidly and bent by a
  // spline, with 149 triangles turned.
  EXPECT_LT(worst, 0.3 * length);
  EXPECT_LT(sum / count, 0.1 * length);
  EXPECT_LT(c.segments[1].residual, 0.015);
  EXPECT_LT(c.segments[1].flipped_faces, int(c.triangles.size() / 50));
}

TEST(Dense_correspondence, remeshed_parts_share_no_connectivity)
{
  const Labeled_mesh remeshed = remesh_parts_independently(small_hand());
  std::map<int, std::size_t> faces_of_label;
  for(int label : remeshed.face_labels) ++faces_of_label[label];
  for(const Synthetic_type& type : small_hand().types)
  {
    std::set<std::size_t> counts;
    int instances = 0;
    for(const Synthetic_instance& i : small_hand().instances)
      if(i.type == type.name)
      {
        counts.insert(faces_of_label.at(i.label));
        ++instances;
      }
    // Different face counts prove different connectivity; a coincidence
    // of counts would only weaken the test, not fake a result.
    EXPECT_GE(counts.size() + 1, static_cast<std::size_t>(instances)) << type.name;
  }
}

TEST(Dense_correspondence, proximal_phalanges_meet_the_ground_truth_targets)
{
  // Proximal phalanges (two seams) with automatic landmarks only: mean
  // <= 1% and 95th percentile <= 3% of the part's diameter, before and
  // after refinement.
  bool found = false;
  for(const Correspondence_type_report& r : hand_reports())
  {
    if(r.type != "proximal") continue;
    found = true;
    EXPECT_EQ(r.segments, 5);
    EXPECT_LE(r.mean_before, 0.01);
    EXPECT_LE(r.p95_before, 0.03);
    EXPECT_LE(r.mean_after, 0.01);
    EXPECT_LE(r.p95_after, 0.03);
  }
  EXPECT_TRUE(found);
}

// The one-seam types (a round tube closed by a cap: fingertip, spider
// tarsus) at the resolution of real parts (about 12,000 vertices, templates
// of 320-600 vertices): their twist and their stretch along the axis are
// fixed only by the seam's lean, the tip and the cap rings.
TEST(Dense_correspondence, capped_segments_meet_the_ground_truth_targets)
{
  for(const auto& [family, type] : {std::pair{Synthetic_family::hand, "distal"},
                                    std::pair{Synthetic_family::spider, "tarsus"}})
  {
    Synthetic_options o;
    o.vertices = 12000;
    bool found = false;
    for(const Correspondence_type_report& r : evaluate_correspondence_on_remeshed(make_synthetic_model(family, o)))
    {
      if(r.type != type) continue;
      found = true;
      EXPECT_LE(r.mean_before, 0.01) << type;
      EXPECT_LE(r.p95_before, 0.03) << type;
      EXPECT_LE(r.mean_after, 0.01) << type;
      EXPECT_LE(r.p95_after, 0.03) << type;
    }
    EXPECT_TRUE(found) << type;
  }
}

TEST(Dense_correspondence, refinement_lowers_the_trace_of_every_type)
{
  ASSERT_EQ(hand_reports().size(), 3u);
  for(const Correspondence_type_report& r : hand_reports())
  {
    EXPECT_LT(r.after.trace, r.before.trace) << r.type;
    EXPECT_LT(r.after.total(0.1, 10.), r.before.total(0.1, 10.)) << r.type;
    // Middle and distal phalanges are near-symmetric tubes whose twist the
    // geometry barely fixes (see doc/MPM/Correspondence.md): looser bounds.
    EXPECT_LT(r.mean_after, 0.05) << r.type;
  }
}

TEST(Dense_correspondence, template_connectivity_on_every_segment)
{
  std::vector<Correspondence_segment> segments(3);
  segments[0].mesh = tube(6, 12, 3.);
  segments[1].mesh = tube(9, 16, 3.6);
  segments[2].mesh = tube(5, 10, 2.5);
  for(std::size_t i = 0; i < segments.size(); ++i) segments[i].name = "tube " + std::to_string(i);
  const Dense_correspondence c = compute_dense_correspondence(segments, "tube");
  EXPECT_EQ(c.triangles, segments[0].mesh.triangles);
  ASSERT_EQ(c.segments.size(), 3u);
  for(std::size_t i = 0; i < 3; ++i)
  {
    const Point_matrix& p = c.segments[i].positions;
    ASSERT_EQ(p.rows(), segments[0].mesh.number_of_vertices());
    ASSERT_TRUE(p.allFinite());
    // On the cylinder of radius 1 (up to the chord error of the segment's
    // own polygonal sides) and within its length.
    const double length = segments[i].mesh.points.col(2).maxCoeff();
    for(Eigen::Index v = 0; v < p.rows(); ++v)
    {
      EXPECT_NEAR(p.row(v).head<2>().norm(), 1., 0.1) << i << " " << v;
      EXPECT_GE(p(v, 2), -1e-9);
      EXPECT_LE(p(v, 2), length + 1e-9);
    }
    EXPECT_LT(c.segments[i].residual, 0.05);
  }
  EXPECT_LE(c.after.trace, c.before.trace);
}

TEST(Dense_correspondence, learns_and_deforms_remeshed_parts)
{
  const Labeled_mesh remeshed = remesh_parts_independently(small_hand());
  std::vector<std::string> stages;
  Learning_options options;
  options.progress = [&](const std::string& stage, double) { stages.push_back(stage); };
  const Morphable_part_model model = learn_morphable_part_model(remeshed, small_hand().annotation, options);
  EXPECT_NE(std::find(stages.begin(), stages.end(), "correspondence of proximal"), stages.end());
  ASSERT_EQ(model.types.size(), 4u);
  for(const Part_type& t : model.types)
    if(t.name != "palm") EXPECT_GT(t.space.number_of_modes(), 0) << t.name;
  EXPECT_FALSE(model.rules.empty());

  const Indexed_mesh rest = to_labeled_mesh(model.examples[0]).mesh;
  Labeled_mesh example;
  example.mesh = rest;
  example.face_labels = to_labeled_mesh(model.examples[0]).face_labels;
  Point_matrix stretched = rest.points;
  stretched.col(1) *= 1.1;
  const Handle_set handles = handles_per_part(example, 1, stretched);
  Embedding_solver solver(make_deformation_problem(model));
  solver.set_handles(handles.vertices, handles.targets);
  solver.solve();
  const Point_matrix& result = solver.positions();
  ASSERT_TRUE(result.allFinite());
  // Every handle reached, and no vertex thrown far off.
  for(int h = 0; h < handles.size(); ++h)
    EXPECT_LT((result.row(handles.vertices[h]) - handles.targets.row(h)).norm(), 0.05 * (rest.points.colwise().maxCoeff() - rest.points.colwise().minCoeff()).norm());
  EXPECT_LT((result - stretched).rowwise().norm().maxCoeff(),
            0.3 * (rest.points.colwise().maxCoeff() - rest.points.colwise().minCoeff()).norm());
}

TEST(Dense_correspondence, command_writes_template_connectivity_and_summary)
{
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("mpm_correspond_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto in_dir = [&](const std::string& name) { return mpm_test::quote((dir / name).string()); };
  ASSERT_EQ(mpm_test::run_tool(dir, "synth hand --vertices 3000 -o " + in_dir("hand")).status, 0);
  const mpm_test::Run_result r =
    mpm_test::run_tool(dir, "correspond " + in_dir("hand.off") + " -o " + in_dir("corr/") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  ASSERT_EQ(summary["types"].size(), 3u);
  for(const auto& type : summary["types"])
  {
    ASSERT_EQ(type["segments"].size(), 5u);
    const Indexed_mesh first = read_mesh_file(type["segments"][0]["file"].get<std::string>()).mesh;
    for(const auto& segment : type["segments"])
    {
      const Indexed_mesh m = read_mesh_file(segment["file"].get<std::string>()).mesh;
      EXPECT_EQ(m.triangles, first.triangles);
      EXPECT_TRUE(m.points.allFinite());
      EXPECT_LT(segment["residual"].get<double>(), 0.05);
    }
    EXPECT_LE(type["after_refinement"]["trace"].get<double>(), type["before_refinement"]["trace"].get<double>());
  }
  EXPECT_TRUE(fs::is_regular_file(dir / "corr" / "correspondence.json"));
  // A missing annotation file: an input error; none at all: a usage error.
  EXPECT_EQ(mpm_test::run_tool(dir, "correspond " + in_dir("hand.off") + " --annotation " + in_dir("missing.json") +
                                      " -o " + in_dir("x")).status, 1);
  fs::rename(dir / "hand.json", dir / "other.json");
  EXPECT_EQ(mpm_test::run_tool(dir, "correspond " + in_dir("hand.off") + " -o " + in_dir("x")).status, 2);
  fs::remove_all(dir);
}

TEST(Dense_correspondence_bad_input, landmark_out_of_range_names_the_segment)
{
  std::vector<Correspondence_segment> segments(2);
  segments[0].mesh = tube(5, 10, 3.);
  segments[1].mesh = tube(6, 12, 3.);
  segments[0].name = "a.off label 1";
  segments[1].name = "b.off label 2";
  segments[0].landmarks = {0, 3};
  segments[1].landmarks = {0, 500};
  try
  {
    compute_dense_correspondence(segments, "leg");
    FAIL() << "no error";
  }
  catch(const Input_error& e)
  {
    EXPECT_EQ(e.source(), "b.off label 2");
    EXPECT_NE(e.element().find("landmark 1"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("out of range"), std::string::npos) << e.what();
  }
}

TEST(Dense_correspondence_bad_input, different_numbers_of_boundary_loops)
{
  std::vector<Correspondence_segment> segments(2);
  segments[0].mesh = tube(5, 10, 3.);
  segments[1].mesh = capped_tube(6, 12, 3.);
  segments[0].name = "a.off label 1";
  segments[1].name = "a.off label 5";
  try
  {
    compute_dense_correspondence(segments, "leg");
    FAIL() << "no error";
  }
  catch(const Input_error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("part type \"leg\""), std::string::npos) << what;
    EXPECT_NE(what.find("a.off label 5"), std::string::npos) << what;
    EXPECT_NE(what.find("a.off label 1"), std::string::npos) << what;
    EXPECT_NE(what.find("1 boundary loops but"), std::string::npos) << what;
  }
}

TEST(Dense_correspondence_bad_input, degenerate_segments)
{
  std::vector<Correspondence_segment> segments(2);
  segments[0].mesh = tube(5, 10, 3.);
  segments[0].name = "good";
  segments[1].name = "bad";
  // Collinear points.
  segments[1].mesh.points.resize(4, 3);
  for(int v = 0; v < 4; ++v) segments[1].mesh.points.row(v) << v, 2. * v, 0.;
  segments[1].mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  EXPECT_THROW(compute_dense_correspondence(segments, "leg"), Input_error);
  // No triangle at all.
  segments[1].mesh = Indexed_mesh();
  try
  {
    compute_dense_correspondence(segments, "leg");
    FAIL() << "no error";
  }
  catch(const Input_error& e)
  {
    EXPECT_EQ(e.source(), "bad");
    EXPECT_NE(e.problem().find("degenerate segment"), std::string::npos) << e.what();
  }
  // Non-finite coordinates.
  segments[1].mesh = tube(5, 10, 3.);
  segments[1].mesh.points(3, 1) = std::nan("");
  EXPECT_THROW(compute_dense_correspondence(segments, "leg"), Input_error);
  EXPECT_THROW(compute_dense_correspondence({}, "leg"), Input_error);
}

} // namespace
