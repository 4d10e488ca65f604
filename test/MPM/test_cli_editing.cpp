// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Runs the editing commands of the built `mpm` tool (deform, symmetrize,
// caricature) on a model learned from the synthetic hand, and checks the
// meshes they write, their JSON summaries and their errors.
#include <CGAL/MPM/IO/Mesh_io.h>

#include "Tool_test_support.h"

#include "Point_distances.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using CGAL::MPM::Point_matrix;

using mpm_test::quote;
using mpm_test::Run_result;
using mpm_test::slurp;
using mpm_test::diagonal;
using mpm_test::max_distance;

// One hand model learned once for the whole suite (synth and learn dominate
// the run time).
class Cli_editing : public ::testing::Test
{
protected:
  static fs::path shared;
  fs::path dir;

  static Run_result run_in(const fs::path& where, const std::string& arguments)
  {
    return mpm_test::run_tool(where, arguments);
  }

  static void SetUpTestSuite()
  {
    shared = fs::temp_directory_path() / ("mpm_cli_editing_" + std::to_string(::getpid()));
    fs::remove_all(shared);
    fs::create_directories(shared);
    const std::string prefix = (shared / "hand").string();
    const Run_result synth = run_in(shared, "synth hand --vertices 2500 -o " + quote(prefix));
    ASSERT_EQ(synth.status, 0) << synth.err;
    const Run_result learn = run_in(shared, "learn " + quote(prefix + ".off") + " -o " + quote(prefix + ".mpm"));
    ASSERT_EQ(learn.status, 0) << learn.err;
  }
  static void TearDownTestSuite() { fs::remove_all(shared); }

  void SetUp() override
  {
    ASSERT_TRUE(fs::is_regular_file(model())) << "the suite's model was not learned";
    dir = shared / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir);
  }

  Run_result run(const std::string& arguments) const { return run_in(dir, arguments); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  static std::string model() { return (shared / "hand.mpm").string(); }
  static std::string input_mesh() { return (shared / "hand.off").string(); }
  static Point_matrix rest() { return CGAL::MPM::read_mesh_file(input_mesh()).mesh.points; }

  // Writes a handle file pulling `vertex` by `offset` for each entry.
  std::string handles(const std::string& name, const std::map<int, std::array<double, 3>>& offsets) const
  {
    json h = {{"format", "cgal-mpm-handles"}, {"version", 1}, {"handles", json::array()}};
    for(const auto& [vertex, offset] : offsets) h["handles"].push_back({{"vertex", vertex}, {"offset", offset}});
    const std::string p = path(name);
    std::ofstream(p) << h.dump(2);
    return p;
  }

  static json one_object(const Run_result& r)
  {
    json j;
    EXPECT_NO_THROW(j = json::parse(r.out)) << "stdout:\n" << r.out;
    EXPECT_TRUE(j.is_object()) << r.out;
    return j;
  }

  // A failure with exit code `code` and exactly one `mpm: error:` line.
  static void expect_error(const Run_result& r, int code, const std::vector<std::string>& mentions)
  {
    EXPECT_EQ(r.status, code) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_EQ(r.err.rfind("mpm: error: ", 0), 0u) << r.err;
    for(const std::string& m : mentions) EXPECT_NE(r.err.find(m), std::string::npos) << r.err;
  }

  // The summary's energies: one per iteration, the last one the residual.
  static std::vector<double> energy_history(const json& s)
  {
    const std::vector<double> e = s["energies"].get<std::vector<double>>();
    EXPECT_EQ(static_cast<int>(e.size()), s["iterations"].get<int>());
    EXPECT_FALSE(e.empty());
    if(!e.empty()) EXPECT_EQ(s["residual_energy"].get<double>(), e.back());
    return e;
  }

  // ... and never increasing. The relative slack is round-off of the last
  // steps (4e-9 relative has been seen); the absolute one is the rounding of
  // reduced energies, differences of large sums, at a minimum of energy 0
  // (caricature factor 1 gives energies of +-6e-9).
  static void expect_decreasing_energies(const json& s)
  {
    const std::vector<double> e = energy_history(s);
    for(std::size_t i = 1; i < e.size(); ++i) EXPECT_LE(e[i], e[i - 1] * (1 + 1e-8) + 1e-7) << "iteration " << i;
  }
};

fs::path Cli_editing::shared;

TEST_F(Cli_editing, DeformWithRestTargetsGivesTheInputBack)
{
  const std::string h = handles("rest.json", {{0, {0., 0., 0.}}, {700, {0., 0., 0.}}, {1900, {0., 0., 0.}}});
  const Run_result r = run("deform " + quote(model()) + " --handles " + quote(h) + " -o " + quote(path("d.off")) +
                           " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json s = one_object(r);
  const Point_matrix before = rest(), after = CGAL::MPM::read_mesh_file(path("d.off")).mesh.points;
  ASSERT_EQ(after.rows(), before.rows());
  EXPECT_LT(max_distance(before, after), 1e-8 * diagonal(before));
  EXPECT_LT(s["residual_energy"].get<double>(), 1e-12);
  EXPECT_LT(s["rms_displacement"].get<double>(), 1e-8);
  EXPECT_EQ(s["command"], "deform");
  EXPECT_EQ(s["model"], model());
  EXPECT_EQ(s["example"], 0);
  EXPECT_EQ(s["vertices"].get<long>(), before.rows());
  EXPECT_EQ(s["handles"], 3);
  EXPECT_EQ(s["handles_file"], h);
  EXPECT_EQ(s["output"], path("d.off"));
  EXPECT_TRUE(s["converged"].get<bool>());
  EXPECT_GE(s["setup_ms"].get<double>(), 0.);
  EXPECT_GE(s["solve_ms"].get<double>(), 0.);
  // Already at the minimum: every energy is round-off (the reduced energy
  // formula has given -1e-7 in the first iteration).
  for(double e : energy_history(s)) EXPECT_LT(std::abs(e), 1e-6);
}

TEST_F(Cli_editing, DeformMovesHandlesTowardTheirTargets)
{
  const Point_matrix before = rest();
  const double offset = 0.05 * diagonal(before);
  // Pull one vertex, hold two others.
  const std::map<int, std::array<double, 3>> offsets = {
    {0, {0., 0., 0.}}, {1250, {offset, 0., 0.}}, {2400, {0., 0., 0.}}};
  const Run_result r = run("deform " + quote(model()) + " --handles " + quote(handles("pull.json", offsets)) +
                           " -o " + quote(path("d.obj")) + " --json --iterations 200");
  ASSERT_EQ(r.status, 0) << r.err;
  const json s = one_object(r);
  const Point_matrix after = CGAL::MPM::read_mesh_file(path("d.obj")).mesh.points;
  ASSERT_EQ(after.rows(), before.rows());
  for(const auto& [vertex, o] : offsets)
  {
    const Eigen::RowVector3d target = before.row(vertex) + Eigen::RowVector3d(o[0], o[1], o[2]);
    EXPECT_LT((after.row(vertex) - target).norm(), 0.1 * offset) << "vertex " << vertex;
  }
  EXPECT_GT(s["rms_displacement"].get<double>(), 0.);
  expect_decreasing_energies(s);
}

// STL and binary PLY outputs (--binary), read back as the same surface.
TEST_F(Cli_editing, StlAndBinaryPlyOutputs)
{
  const Point_matrix before = rest();
  for(const std::string& name : {"c.stl", "b.stl", "b.ply"})
  {
    const bool binary = name[0] == 'b';
    const Run_result r = run("caricature " + quote(model()) + " --factor 1 -o " + quote(path(name)) + (binary ? " --binary" : ""));
    ASSERT_EQ(r.status, 0) << name << ": " << r.err;
    const CGAL::MPM::Mesh_file file = CGAL::MPM::read_mesh_file(path(name));
    EXPECT_EQ(file.mesh.number_of_faces(), CGAL::MPM::read_mesh_file(input_mesh()).mesh.number_of_faces()) << name;
    EXPECT_NEAR(diagonal(file.mesh.points), diagonal(before), 1e-6 * diagonal(before)) << name;
    const std::string head = slurp(path(name)).substr(0, 40);
    EXPECT_EQ(head.find("binary") != std::string::npos, binary) << name << ": " << head;
  }
}

TEST_F(Cli_editing, CaricatureWithFactorOneGivesTheInputBack)
{
  const Run_result r = run("caricature " + quote(model()) + " --factor 1 -o " + quote(path("c.off")) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json s = one_object(r);
  const Point_matrix before = rest(), after = CGAL::MPM::read_mesh_file(path("c.off")).mesh.points;
  ASSERT_EQ(after.rows(), before.rows());
  EXPECT_LT(max_distance(before, after), 1e-8 * diagonal(before));
  EXPECT_EQ(s["handles"], 0);
  EXPECT_TRUE(s["handles_file"].is_null());
  EXPECT_EQ(s["options"]["factor"], 1.);

  // A real caricature and the anti-shape move the mesh.
  for(const std::string factor : {"2", "-1", "0"})
  {
    const Run_result c = run("caricature " + quote(model()) + " --factor " + factor + " -o " +
                             quote(path("c" + factor + ".off")) + " --json");
    ASSERT_EQ(c.status, 0) << "factor " << factor << ": " << c.err;
    const json cs = one_object(c);
    EXPECT_GT(cs["rms_displacement"].get<double>(), 1e-6) << "factor " << factor;
    expect_decreasing_energies(cs);
  }
}

TEST_F(Cli_editing, SymmetrizeChangesTheShapeNotTheConnectivity)
{
  const Run_result r = run("symmetrize " + quote(model()) + " -o " + quote(path("s.off")) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json s = one_object(r);
  const CGAL::MPM::Mesh_file before = CGAL::MPM::read_mesh_file(input_mesh()),
                             after = CGAL::MPM::read_mesh_file(path("s.off"));
  ASSERT_EQ(after.mesh.number_of_vertices(), before.mesh.number_of_vertices());
  ASSERT_EQ(after.mesh.number_of_faces(), before.mesh.number_of_faces());
  EXPECT_EQ(after.mesh.triangles, before.mesh.triangles);
  EXPECT_GT(max_distance(before.mesh.points, after.mesh.points), 1e-4 * diagonal(before.mesh.points));
  EXPECT_GT(s["rms_displacement"].get<double>(), 0.);
  EXPECT_EQ(s["options"]["relative_sigma"], 0.01);
  expect_decreasing_energies(s);

  // The solver options reach the solver and the summary.
  const Run_result o = run("symmetrize " + quote(model()) + " --relative-sigma 0.1 --coupling 0.5 --handle-weight 10"
                           " --tolerance 1e-6 --iterations 7 -o " + quote(path("o.off")) + " --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const json os = one_object(o);
  EXPECT_EQ(os["options"], json::parse(R"({"relative_sigma": 0.1, "max_iterations": 7, "tolerance": 1e-6,
                                           "handle_weight": 10.0, "coupling_weight": 0.5, "keep_folds": false})"));
  EXPECT_LE(os["iterations"].get<int>(), 7);
  expect_decreasing_energies(os);
}

TEST_F(Cli_editing, TextSummaryNamesEveryQuantity)
{
  const std::string h = handles("h.json", {{10, {0., 0.01, 0.}}});
  const Run_result r = run("deform " + quote(model()) + " --handles " + quote(h) + " -o " + quote(path("t.off")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("Deformed example 0", 0), 0u) << r.out;
  for(const std::string& key : std::vector<std::string>{"options", "handles           1 (" + h + ")", "iterations", "energy            first",
                                "residual energy", "ms per iteration", "inverted faces", "rms displacement", "Wrote " + path("t.off")})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in\n" << r.out;
}

TEST_F(Cli_editing, PlyFacesAreColouredByPartType)
{
  const Run_result r = run("caricature " + quote(model()) + " --factor 2 -o " + quote(path("c.ply")));
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(path("c.ply"));
  std::string header, line;
  long faces = -1, vertices = -1;
  while(std::getline(in, line) && line != "end_header")
  {
    header += line + "\n";
    std::istringstream words(line);
    std::string w, element;
    if(words >> w >> element && w == "element") (element == "face" ? faces : vertices) = std::stol(line.substr(line.rfind(' ')));
  }
  for(const char* p : {"property uchar red\n", "property uchar green\n", "property uchar blue\n"})
    EXPECT_NE(header.find(p), std::string::npos) << header;
  for(long v = 0; v < vertices; ++v) std::getline(in, line);

  // Part type of every face, from the synthetic hand's labels and annotation.
  std::vector<long> labels;
  std::ifstream seg(shared / "hand.seg");
  for(long l; seg >> l;) labels.push_back(l);
  ASSERT_EQ(static_cast<long>(labels.size()), faces);
  std::map<long, std::string> type_of_label;
  const json annotation = json::parse(slurp(shared / "hand.json"));
  for(const json& p : annotation["parts"]) type_of_label[p["label"].get<long>()] = p["type"].get<std::string>();

  std::map<std::string, std::set<std::array<int, 3>>> colors_of_type;
  for(long f = 0; f < faces; ++f)
  {
    int n = 0, a = 0, b = 0, c = 0;
    std::array<int, 3> rgb{};
    ASSERT_TRUE(in >> n >> a >> b >> c >> rgb[0] >> rgb[1] >> rgb[2]) << "face " << f;
    ASSERT_EQ(n, 3);
    colors_of_type[type_of_label.at(labels[f])].insert(rgb);
  }
  ASSERT_GE(colors_of_type.size(), 2u);
  std::set<std::array<int, 3>> used;
  for(const auto& [type, colors] : colors_of_type)
  {
    EXPECT_EQ(colors.size(), 1u) << "type " << type << " has faces of several colours";
    used.insert(*colors.begin());
  }
  EXPECT_EQ(used.size(), colors_of_type.size()) << "two part types share a colour";
}

TEST_F(Cli_editing, InputErrorsExitWithStatusOne)
{
  const std::string bad = handles("bad.json", {{0, {0., 0., 0.}}, {99999999, {0., 0., 0.}}});
  expect_error(run("deform " + quote(model()) + " --handles " + quote(bad) + " -o " + quote(path("x.off"))), 1,
               {"bad.json", "handles[1]", "out of range"});
  EXPECT_FALSE(fs::exists(path("x.off")));

  const std::string empty = path("empty.json");
  std::ofstream(empty) << R"({"handles": []})";
  expect_error(run("deform " + quote(model()) + " --handles " + quote(empty) + " -o " + quote(path("x.off"))), 1,
               {"empty.json", "no handles"});
  expect_error(run("deform " + quote(model()) + " --handles " + quote(path("missing.json")) + " -o " +
                   quote(path("x.off"))), 1, {"missing.json"});
  expect_error(run("caricature " + quote(model()) + " --factor 2 --example 3 -o " + quote(path("x.off"))), 1,
               {model(), "example 3"});
  expect_error(run("symmetrize " + quote(path("nope.mpm")) + " -o " + quote(path("x.off"))), 1, {"nope.mpm"});
  // A target 1e150 away gave displacements of 1e148 with exit 0.
  const std::string far = handles("far.json", {{0, {1e150, 0., 0.}}, {5, {0., 0., 0.}}});
  expect_error(run("deform " + quote(model()) + " --handles " + quote(far) + " -o " + quote(path("x.off"))), 1,
               {"far.json", "handle 0 (vertex 0)", "bounding-box diagonals away", "nothing written"});
  // One of 1e308 overflowed the solve, and the error named no handle.
  const std::string overflow = handles("overflow.json", {{5, {0., 0., 0.}}, {0, {1e308, 0., 0.}}});
  expect_error(run("deform " + quote(model()) + " --handles " + quote(overflow) + " -o " + quote(path("x.off"))), 1,
               {"overflow.json", "handle 0 (vertex 0)", "bounding-box diagonals away"});
  EXPECT_FALSE(fs::exists(path("x.off")));
}

TEST_F(Cli_editing, UsageErrorsExitWithStatusTwo)
{
  const std::string m = quote(model()), out = " -o " + quote(path("x.off"));
  expect_error(run("deform " + m + out), 2, {"--handles"});
  expect_error(run("caricature " + m + out), 2, {"--factor"});
  expect_error(run("deform " + m + " --handles h.json"), 2, {"-o"});
  expect_error(run("caricature " + m + " --factor nan" + out), 2, {"--factor"});
  expect_error(run("caricature " + m + " --factor inf" + out), 2, {"--factor"});
  expect_error(run("caricature " + m + " --factor two" + out), 2, {"--factor"});
  expect_error(run("symmetrize " + m + " --relative-sigma 0" + out), 2, {"--relative-sigma"});
  expect_error(run("symmetrize " + m + " --iterations 0" + out), 2, {"--iterations"});
  expect_error(run("symmetrize " + m + " --tolerance -1" + out), 2, {"--tolerance"});
  expect_error(run("symmetrize " + m + " --handle-weight 0" + out), 2, {"--handle-weight"});
  expect_error(run("symmetrize " + m + " --coupling -1" + out), 2, {"--coupling"});
  expect_error(run("symmetrize " + m + " --example -1" + out), 2, {"--example"});
  expect_error(run("symmetrize " + m + " -o " + quote(path("x.xyz"))), 2, {"x.xyz", ".stl"});
  expect_error(run("symmetrize" + out), 2, {"MODEL"});
  EXPECT_FALSE(fs::exists(path("x.off")));
}

TEST_F(Cli_editing, HelpListsTheSharedOptions)
{
  for(const char* command : {"deform", "symmetrize", "caricature"})
  {
    const Run_result r = run(std::string(command) + " --help");
    ASSERT_EQ(r.status, 0) << r.err;
    for(const char* option : {"--output OUT", "--example N", "--handles H.json", "--iterations N", "--tolerance T",
                              "--handle-weight W", "--coupling W"})
      EXPECT_NE(r.out.find(option), std::string::npos) << command << ": " << option;
  }
  const Run_result list = run("--help");
  for(const char* command : {"deform ", "symmetrize ", "caricature "})
    EXPECT_NE(list.out.find(std::string("  ") + command), std::string::npos) << command;
}

} // namespace

// --mesh starts the edit from another pose of the example's mesh: with no
// handle displacement (caricature factor 1) that pose comes back unchanged;
// a mesh of another connectivity is refused naming the file.
TEST_F(Cli_editing, MeshOptionStartsFromAnotherPoseAndRefusesOtherMeshes)
{
  const std::string pose = path("pose");
  ASSERT_EQ(run("synth hand --vertices 2500 --pose-seed 4 -o " + quote(pose)).status, 0);
  const Run_result r = run("caricature " + quote(model()) + " --factor 1 --mesh " + quote(pose + ".off") + " -o " +
                           quote(path("p.off")));
  ASSERT_EQ(r.status, 0) << r.err;
  const Point_matrix expected = CGAL::MPM::read_mesh_file(pose + ".off").mesh.points;
  const Point_matrix got = CGAL::MPM::read_mesh_file(path("p.off")).mesh.points;
  EXPECT_LT(max_distance(got, expected), 1e-8 * diagonal(expected));
  EXPECT_GT(max_distance(expected, rest()), 1e-3 * diagonal(expected));

  const std::string other = path("other");
  ASSERT_EQ(run("synth hand --vertices 1500 -o " + quote(other)).status, 0);
  expect_error(run("caricature " + quote(model()) + " --factor 1 --mesh " + quote(other + ".off") + " -o " +
                   quote(path("x.off"))),
               1, {"other.off", "vertices"});
}

// `mpm handles` picks handles per part with targets from a held-out pose;
// deforming with them moves the example toward that pose.
TEST_F(Cli_editing, HandlesPerPartFromAPoseDriveADeformationTowardIt)
{
  const std::string pose = path("pose");
  ASSERT_EQ(run("synth hand --vertices 2500 --pose-seed 9 -o " + quote(pose)).status, 0);
  const Run_result h = run("handles " + quote(model()) + " --per-part 2 --targets " + quote(pose + ".off") + " -o " +
                           quote(path("h.json")) + " --json");
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_GE(json::parse(h.out)["handles"].get<int>(), 16);
  const Run_result d = run("deform " + quote(model()) + " --handles " + quote(path("h.json")) + " -o " +
                           quote(path("d.off")));
  ASSERT_EQ(d.status, 0) << d.err;
  const Point_matrix truth = CGAL::MPM::read_mesh_file(pose + ".off").mesh.points;
  const Point_matrix got = CGAL::MPM::read_mesh_file(path("d.off")).mesh.points;
  EXPECT_LT((got - truth).norm(), 0.5 * (rest() - truth).norm());
  expect_error(run("handles " + quote(model()) + " --per-part 1 --farthest 3 -o " + quote(path("x.json"))), 2,
               {"--per-part"});
}

// `mpm handles --bend-limbs` turns every finger tip about its attachment to
// the palm and holds the palm; deforming with them moves each tip by the
// asked fraction of the diagonal (to within the soft handles' give) and
// leaves the palm where it was.
TEST_F(Cli_editing, BentLimbHandlesMoveEveryTipAndHoldThePalm)
{
  const Run_result h = run("handles " + quote(model()) + " --bend-limbs 0.1 -o " + quote(path("bend.json")) + " --json");
  ASSERT_EQ(h.status, 0) << h.err;
  const int count = json::parse(h.out)["handles"].get<int>();
  const Run_result d = run("deform " + quote(model()) + " --handles " + quote(path("bend.json")) + " -o " +
                           quote(path("bent.off")));
  ASSERT_EQ(d.status, 0) << d.err;
  const Point_matrix got = CGAL::MPM::read_mesh_file(path("bent.off")).mesh.points;
  const double diagonal = (rest().colwise().maxCoeff() - rest().colwise().minCoeff()).norm();
  const Eigen::VectorXd moved = (got - rest()).rowwise().norm() / diagonal;
  int tips = 0, held = 0;
  for(Eigen::Index v = 0; v < moved.size(); ++v)
  {
    tips += moved[v] > 0.09;
    held += moved[v] < 1e-3;
  }
  EXPECT_GE(tips, 5);                // at least the five tips moved by about 10%
  EXPECT_LE(moved.maxCoeff(), 0.12); // and nothing much further
  EXPECT_GE(held, count - 5);        // the palm stayed
  expect_error(run("handles " + quote(model()) + " --bend-limbs 0.1 --targets " + quote(path("bent.off")) + " -o " +
                   quote(path("x.json"))),
               2, {"--targets"});
  expect_error(run("handles " + quote(model()) + " --bend-limbs 0 -o " + quote(path("x.json"))), 2, {"--bend-limbs"});
}

namespace {

// `-` stands for one input file (standard input) and one output file
// (standard output); the result is the same bytes as with named files, and
// messages name `-`, never the temporary copies.
TEST_F(Cli_editing, DashReadsStandardInputAndWritesStandardOutput)
{
  const std::string h = handles("pull.json", {{0, {0., 0., 0.}}, {1900, {0.2, 0., 0.}}});
  const std::string tmp = path("tmp");
  fs::create_directories(tmp);
  const std::string env = "TMPDIR=" + quote(tmp);
  const auto run_piped = [&](const std::string& arguments, const std::string& input) {
    return mpm_test::run_tool(dir, arguments, input, env);
  };

  ASSERT_EQ(run("deform " + quote(model()) + " --handles " + quote(h) + " -o " + quote(path("named.off"))).status, 0);
  const Run_result piped = run_piped("deform " + quote(model()) + " --handles - -o -", h);
  ASSERT_EQ(piped.status, 0) << piped.err;
  EXPECT_EQ(piped.out, slurp(path("named.off")));
  EXPECT_NE(piped.err.find("handles           2 (-)"), std::string::npos) << piped.err;
  EXPECT_NE(piped.err.find("Wrote -"), std::string::npos) << piped.err;

  // A mesh on standard input is recognized by its content.
  const Run_result learned = run_piped("learn - -o " + quote(path("again.mpm")) + " --json", input_mesh());
  ASSERT_EQ(learned.status, 0) << learned.err;
  EXPECT_EQ(one_object(learned)["examples"][0]["name"], "-");
  const Run_result info = run_piped("info - --json", model());
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_EQ(one_object(info)["model"], "-");
  const Run_result graph = run_piped("graph " + quote(model()) + " -o -", "/dev/null");
  ASSERT_EQ(graph.status, 0) << graph.err;
  EXPECT_EQ(json::parse(graph.out)["format"], "cgal-mpm-part-graph");

  // A reader that stops early (SIGPIPE) leaves no temporary copy either.
  run_piped("deform " + quote(model()) + " --handles " + quote(h) + " -o - | head -c 10", "/dev/null");
  expect_error(run_piped("info -", h), 1, {"mpm: error: -: "});
  expect_error(run_piped("deform " + quote(model()) + " --handles " + quote(h) + " -o - --json", "/dev/null"), 2,
               {"--json both write to standard output"});
  expect_error(run_piped("synth hand -o -", "/dev/null"), 2, {"cannot stand for the several files"});
  expect_error(run_piped("deform - --handles - -o " + quote(path("x.off")), h), 2,
               {"only one input can be read from standard input"});
  EXPECT_TRUE(fs::is_empty(tmp)) << "temporary copies were left in " << tmp;
}

// compare's progress advances through ARAP's iterations (it sat at one
// percentage for the whole run) and ends at 100%.
TEST_F(Cli_editing, CompareProgressAdvancesThroughArapIterations)
{
  const std::string h = handles("pull.json", {{0, {0., 0., 0.}}, {1900, {0.3, 0., 0.}}});
  const Run_result r = run("compare " + quote(model()) + " --handles " + quote(h) +
                           " --methods arap --arap-iterations 200 --progress");
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<int> arap;
  for(const std::string& l : r.err_lines())
    if(l.rfind("mpm compare: running arap ", 0) == 0) arap.push_back(std::stoi(l.substr(l.rfind(' ') + 1)));
  EXPECT_GE(std::set<int>(arap.begin(), arap.end()).size(), 3u) << r.err;
  EXPECT_TRUE(std::is_sorted(arap.begin(), arap.end())) << r.err;
  ASSERT_FALSE(arap.empty());
  EXPECT_EQ(arap.back(), 100) << r.err;
}

TEST_F(Cli_editing, FitWritesBinaryMeshes)
{
  const std::string fit = "fit " + quote(model()) + " " + quote(input_mesh());
  const Run_result binary = run(fit + " --binary -o " + quote(path("fitted.ply")));
  ASSERT_EQ(binary.status, 0) << binary.err;
  ASSERT_EQ(run(fit + " -o " + quote(path("fitted.off"))).status, 0);
  const std::string ply = slurp(path("fitted.ply"));
  EXPECT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << ply.substr(0, 80);
  const Point_matrix text = CGAL::MPM::read_mesh_file(path("fitted.off")).mesh.points;
  const Point_matrix read = CGAL::MPM::read_mesh_file(path("fitted.ply")).mesh.points;
  ASSERT_EQ(read.rows(), text.rows());
  EXPECT_LT(max_distance(read, text), 1e-5 * diagonal(text)); // the OFF text rounds
}

} // namespace
