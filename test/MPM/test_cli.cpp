// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Runs the built `mpm` tool (MPM_TOOL_PATH) in a temporary directory and
// checks its files, JSON summaries, messages and exit codes.
#include "Tool_test_support.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
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

using mpm_test::quote;
using mpm_test::Run_result;
using mpm_test::slurp;

class Cli : public ::testing::Test
{
protected:
  fs::path dir;

  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() /
          ("mpm_cli_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override
  {
    if(!HasFailure()) fs::remove_all(dir);
  }

  // Runs `mpm ARGS` (ARGS already shell-quoted where needed).
  Run_result run(const std::string& arguments) const { return mpm_test::run_tool(dir, arguments); }

  std::string path(const std::string& name) const { return (dir / name).string(); }

  // Parses stdout as exactly one JSON object (trailing text is an error).
  static json one_object(const Run_result& r)
  {
    json j;
    EXPECT_NO_THROW(j = json::parse(r.out)) << "stdout:\n" << r.out;
    EXPECT_TRUE(j.is_object()) << r.out;
    return j;
  }

  // Expects a failure with exit code `code` and one `mpm: error:` line on stderr.
  static void expect_error(const Run_result& r, int code, const std::string& mentions = "")
  {
    EXPECT_EQ(r.status, code) << r.err;
    const auto lines = r.err_lines();
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind("mpm: error: ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find("error"), std::string::npos);
    if(!mentions.empty())
    {
      EXPECT_NE(lines[0].find(mentions), std::string::npos) << lines[0];
    }
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
};

// Vertex and face counts from an OFF header.
std::pair<long, long> off_counts(const fs::path& p)
{
  std::ifstream in(p);
  std::string word;
  in >> word;
  EXPECT_EQ(word, "OFF");
  std::string line;
  long v = -1, f = -1;
  while(std::getline(in, line))
  {
    const auto hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream s(line);
    if(s >> v >> f) break;
  }
  return {v, f};
}

std::vector<long> seg_labels(const fs::path& p)
{
  std::ifstream in(p);
  std::vector<long> labels;
  for(long l; in >> l;) labels.push_back(l);
  EXPECT_TRUE(in.eof()) << p << ": non-numeric entry";
  return labels;
}

TEST_F(Cli, SynthWritesThreeConsistentFiles)
{
  const std::string prefix = path("sub/dir/grid"); // parent directories do not exist yet
  const Run_result r = run("synth hexa-grid --vertices 2000 --seed 3 --json -o " + quote(prefix));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;
  const json s = one_object(r);

  const fs::path off = prefix + ".off", seg = prefix + ".seg", annotation = prefix + ".json";
  ASSERT_TRUE(fs::is_regular_file(off));
  ASSERT_TRUE(fs::is_regular_file(seg));
  ASSERT_TRUE(fs::is_regular_file(annotation));
  EXPECT_EQ(s["files"]["mesh"], off.string());
  EXPECT_EQ(s["files"]["labels"], seg.string());
  EXPECT_EQ(s["files"]["annotation"], annotation.string());
  EXPECT_EQ(s["family"], "hexa-grid");
  EXPECT_EQ(s["seed"], 3);
  EXPECT_EQ(s["held_out_pose"], false);

  const auto [vertices, faces] = off_counts(off);
  EXPECT_EQ(s["vertices"].get<long>(), vertices);
  EXPECT_EQ(s["faces"].get<long>(), faces);
  EXPECT_GT(vertices, 1000);
  EXPECT_LT(vertices, 4000);

  const std::vector<long> labels = seg_labels(seg);
  EXPECT_EQ(static_cast<long>(labels.size()), faces);
  const std::set<long> distinct(labels.begin(), labels.end());
  EXPECT_EQ(s["parts"].get<std::size_t>(), distinct.size());

  // Every part is an instance of exactly one type.
  long instances = 0;
  for(const json& t : s["types"])
  {
    EXPECT_FALSE(t["name"].get<std::string>().empty());
    EXPECT_GE(t["true_modes"].get<int>(), 0);
    instances += t["instances"].get<long>();
  }
  EXPECT_EQ(instances, static_cast<long>(distinct.size()));
  EXPECT_GT(s["connections"]["total"].get<int>(), 0);
  EXPECT_EQ(s["connections"]["boundary"].get<int>() + s["connections"]["generalized"].get<int>(),
            s["connections"]["total"].get<int>());

  // The annotation names the type of every label.
  const json a = json::parse(slurp(annotation));
  EXPECT_TRUE(a.is_object());

  // Deterministic: the same options write the same mesh.
  const Run_result again = run("synth hexa-grid --vertices 2000 --seed 3 -o " + quote(path("again")));
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(slurp(off), slurp(path("again.off")));
  EXPECT_EQ(slurp(seg), slurp(path("again.seg")));

  // A held-out pose: same connectivity and labels, other positions.
  const Run_result pose = run("synth hexa-grid --vertices 2000 --seed 3 --pose-seed 7 --json -o " + quote(path("pose")));
  ASSERT_EQ(pose.status, 0) << pose.err;
  const json ps = one_object(pose);
  EXPECT_EQ(ps["held_out_pose"], true);
  EXPECT_EQ(ps["pose_seed"], 7);
  EXPECT_EQ(off_counts(path("pose.off")), off_counts(off));
  EXPECT_EQ(slurp(path("pose.seg")), slurp(seg));
  EXPECT_NE(slurp(path("pose.off")), slurp(off));
}

TEST_F(Cli, LearnAndInfoMatchTheSyntheticModel)
{
  const std::string prefix = path("grid"), model = path("models/grid.mpm");
  const Run_result synth = run("synth hexa-grid --vertices 2000 --json -o " + quote(prefix));
  ASSERT_EQ(synth.status, 0) << synth.err;
  const json truth = one_object(synth);

  const Run_result learn = run("learn " + quote(prefix + ".off") + " --labels " + quote(prefix + ".seg") +
                               " --annotation " + quote(prefix + ".json") + " --json -o " + quote(model));
  ASSERT_EQ(learn.status, 0) << learn.err;
  ASSERT_TRUE(fs::is_regular_file(model));
  const json learned = one_object(learn);
  EXPECT_GE(learned["time_seconds"].get<double>(), 0.);
  ASSERT_EQ(learned["inputs"].size(), 1u);
  EXPECT_EQ(learned["inputs"][0]["labels"], prefix + ".seg");

  const Run_result info = run("info --json " + quote(model));
  ASSERT_EQ(info.status, 0) << info.err;
  const json s = one_object(info);
  EXPECT_EQ(s["model"], model);

  // Types and instance counts are the generator's.
  std::map<std::string, int> expected, got;
  for(const json& t : truth["types"]) expected[t["name"]] = t["instances"];
  for(const json& t : s["types"]) got[t["name"]] = t["instances"];
  EXPECT_EQ(got, expected);
  EXPECT_EQ(s["totals"]["types"].get<std::size_t>(), truth["types"].size());
  EXPECT_EQ(s["totals"]["instances"], truth["parts"]);
  EXPECT_EQ(s["totals"]["rules"], truth["expected_rules"]);
  EXPECT_EQ(s["rules"].size(), s["totals"]["rules"].get<std::size_t>());

  ASSERT_EQ(s["examples"].size(), 1u);
  EXPECT_EQ(s["examples"][0]["vertices"], truth["vertices"]);
  EXPECT_EQ(s["examples"][0]["faces"], truth["faces"]);
  EXPECT_EQ(s["examples"][0]["parts"], truth["parts"]);
  EXPECT_EQ(s["examples"][0]["dockings"], truth["connections"]["total"]);

  for(const json& t : s["types"])
  {
    EXPECT_GT(t["vertices"].get<int>(), 0);
    EXPECT_EQ(t["sigmas"].size(), t["modes"].get<std::size_t>());
    EXPECT_GE(t["explained_variance"].get<double>(), 0.);
    EXPECT_LE(t["explained_variance"].get<double>(), 1. + 1e-9);
    double previous = 0.;
    for(const json& c : t["cumulative_variance"])
    {
      EXPECT_GE(c.get<double>(), previous - 1e-12);
      previous = c.get<double>();
    }
  }
  for(const json& r : s["rules"])
  {
    EXPECT_GT(r["pair_points"].get<int>(), 0);
    EXPECT_GT(r["observations"].get<int>(), 0);
  }
  // learn --json reports the same model as info --json.
  EXPECT_EQ(learned["types"], s["types"]);
  EXPECT_EQ(learned["rules"], s["rules"]);
  EXPECT_EQ(learned["parameters"], s["parameters"]);

  // The human-readable form names every type.
  const Run_result text = run("info " + quote(model));
  ASSERT_EQ(text.status, 0) << text.err;
  for(const auto& entry : expected)
  {
    EXPECT_NE(text.out.find(entry.first), std::string::npos) << entry.first;
  }
  EXPECT_NE(text.out.find("Part types"), std::string::npos);
  EXPECT_NE(text.out.find("Rules"), std::string::npos);
}

TEST_F(Cli, LearnCommandLineParametersOverrideTheAnnotation)
{
  const std::string prefix = path("grid"), model = path("grid.mpm");
  ASSERT_EQ(run("synth hexa-grid --vertices 2000 -o " + quote(prefix)).status, 0);
  // Default labels and annotation: the .seg and .json siblings of the mesh.
  const Run_result learn = run("learn " + quote(prefix + ".off") + " -o " + quote(model) +
                               " --modes 1 --docking-radius 0.125 --sigma-sub 0.25 --json");
  ASSERT_EQ(learn.status, 0) << learn.err;
  const json s = one_object(learn);
  EXPECT_EQ(s["inputs"][0]["labels"], prefix + ".seg");
  EXPECT_EQ(s["inputs"][0]["annotation"], prefix + ".json");
  EXPECT_EQ(s["parameters"]["modes"], 1);
  EXPECT_DOUBLE_EQ(s["parameters"]["docking_radius"].get<double>(), 0.125);
  EXPECT_DOUBLE_EQ(s["parameters"]["sigma_sub"].get<double>(), 0.25);
  for(const json& t : s["types"])
  {
    EXPECT_LE(t["modes"].get<int>(), 1) << t["name"];
  }
}

// The subcommands listed by `mpm --help`.
std::vector<std::string> listed_commands(const std::string& help)
{
  std::vector<std::string> names;
  std::istringstream in(help);
  bool in_list = false;
  for(std::string line; std::getline(in, line);)
  {
    if(line == "Commands:") { in_list = true; continue; }
    if(in_list && line.empty()) break;
    if(in_list)
    {
      std::istringstream s(line);
      std::string name;
      s >> name;
      names.push_back(name);
    }
  }
  return names;
}

TEST_F(Cli, HelpForEverySubcommand)
{
  const Run_result general = run("--help");
  ASSERT_EQ(general.status, 0);
  EXPECT_TRUE(general.err.empty());
  const std::vector<std::string> commands = listed_commands(general.out);
  for(const char* required : {"synth", "learn", "info"})
    EXPECT_NE(std::find(commands.begin(), commands.end(), required), commands.end()) << required;

  for(const std::string& c : commands)
  {
    const Run_result a = run(c + " --help"), b = run("help " + c), h = run(c + " -h");
    EXPECT_EQ(a.status, 0) << c;
    EXPECT_EQ(b.status, 0) << c;
    EXPECT_EQ(h.status, 0) << c;
    EXPECT_EQ(a.out, b.out) << c;
    EXPECT_EQ(a.out, h.out) << c;
    EXPECT_EQ(a.out.rfind("Usage: mpm " + c, 0), 0u) << a.out;
    EXPECT_NE(a.out.find("--json"), std::string::npos) << c;
    EXPECT_NE(a.out.find("--progress"), std::string::npos) << c;
  }
  // Defaults are shown.
  const Run_result synth = run("synth --help");
  EXPECT_NE(synth.out.find("--seed N"), std::string::npos);
  EXPECT_NE(synth.out.find("(default: 1)"), std::string::npos);
  EXPECT_NE(synth.out.find("hexa-grid"), std::string::npos);
  const Run_result learn = run("help learn");
  EXPECT_NE(learn.out.find("--explained-variance F"), std::string::npos);
  EXPECT_NE(learn.out.find("0.99"), std::string::npos);

  expect_error(run("help nosuchcommand"), 2, "nosuchcommand");
}

TEST_F(Cli, UsageErrorsExitTwoWithOneLine)
{
  expect_error(run("frobnicate"), 2, "frobnicate");
  expect_error(run("synth hexa-grid --bogus -o " + quote(path("x"))), 2, "--bogus");
  expect_error(run("info --bogus m.mpm"), 2, "--bogus");
  expect_error(run("--bogus"), 2, "--bogus");
  expect_error(run("synth hexa-grid"), 2, "-o");                       // missing output
  expect_error(run("synth"), 2, "FAMILY");                             // missing family
  expect_error(run("synth nosuchfamily -o " + quote(path("x"))), 2, "hexa-grid"); // lists the families
  expect_error(run("synth hexa-grid -o"), 2, "missing value");
  expect_error(run("synth hexa-grid --seed 1 --seed 2 -o " + quote(path("x"))), 2, "--seed");
  expect_error(run("info a.mpm b.mpm"), 2, "b.mpm");
  expect_error(run("learn --labels x.seg m.off -o " + quote(path("m.mpm"))), 2, "--labels");
  expect_error(run("learn m.off --explained-variance 1.5 -o " + quote(path("m.mpm"))), 2, "--explained-variance");
  expect_error(run("learn m.off --docking-radius 0 -o " + quote(path("m.mpm"))), 2, "--docking-radius");
  // No command at all: usage on stderr, exit 2.
  const Run_result none = run("");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("Usage: mpm"), std::string::npos);
  EXPECT_FALSE(fs::exists(path("x.off")));
}

TEST_F(Cli, BadVerticesValue)
{
  const std::string out = " -o " + quote(path("v"));
  expect_error(run("synth hexa-grid --vertices abc" + out), 2, "--vertices");
  expect_error(run("synth hexa-grid --vertices 12x" + out), 2, "not an integer");
  expect_error(run("synth hexa-grid --vertices 2.5" + out), 2, "not an integer");
  expect_error(run("synth hexa-grid --vertices -5" + out), 2, ">= 0");
  expect_error(run("synth hexa-grid --vertices 99999999999999999999" + out), 2, "out of range");
  expect_error(run("synth hexa-grid -o " + quote(path("v")) + " --vertices"), 2, "missing value");
  expect_error(run("synth hexa-grid --vertices --json" + out), 2, "missing value");
  EXPECT_FALSE(fs::exists(path("v.off")));
}

TEST_F(Cli, MissingOrBadInputFilesExitOneAndNameTheFile)
{
  const std::string missing = path("no_such_mesh.off");
  expect_error(run("learn " + quote(missing) + " -o " + quote(path("m.mpm"))), 1, "no_such_mesh.off");
  EXPECT_FALSE(fs::exists(path("m.mpm")));

  expect_error(run("info " + quote(path("no_such_model.mpm"))), 1, "no_such_model.mpm");

  // A file that is not a model.
  std::ofstream(path("garbage.mpm")) << "this is not a model\n";
  expect_error(run("info " + quote(path("garbage.mpm"))), 1, "garbage.mpm");

  // A label file that does not match the mesh.
  ASSERT_EQ(run("synth hexa-grid --vertices 2000 -o " + quote(path("grid"))).status, 0);
  std::ofstream(path("short.seg")) << "0 1 2\n";
  expect_error(run("learn " + quote(path("grid.off")) + " --labels " + quote(path("short.seg")) + " -o " +
                   quote(path("m.mpm"))),
               1, "short.seg");
  expect_error(run("learn " + quote(path("grid.off")) + " --labels " + quote(path("none.seg")) + " -o " +
                   quote(path("m.mpm"))),
               1, "none.seg");
}

TEST_F(Cli, ProgressIsOptInWhenStderrIsNotATerminal)
{
  const std::string prefix = path("grid");
  const Run_result quiet = run("synth hexa-grid --vertices 2000 --json -o " + quote(prefix));
  ASSERT_EQ(quiet.status, 0);
  EXPECT_TRUE(quiet.err.empty()) << quiet.err; // stderr is a file here: no progress
  const Run_result loud = run("learn " + quote(prefix + ".off") + " --progress --json -o " + quote(path("g.mpm")));
  ASSERT_EQ(loud.status, 0) << loud.err;
  one_object(loud); // progress never goes to stdout
  const auto lines = loud.err_lines();
  ASSERT_FALSE(lines.empty());
  for(const std::string& l : lines)
  {
    EXPECT_EQ(l.find('\r'), std::string::npos) << l; // plain lines, no carriage returns
    EXPECT_TRUE(l.rfind("mpm learn: ", 0) == 0 || l.rfind("mpm: warning: ", 0) == 0) << l;
  }
  // Progress ends at 100% (it stopped at the last step of the last stage).
  std::string last_progress;
  for(const std::string& l : lines)
    if(l.rfind("mpm learn: ", 0) == 0) last_progress = l;
  EXPECT_EQ(last_progress.substr(last_progress.size() - 5), " 100%") << last_progress;
}

// An output that is an input of the same command, however spelled, is
// refused with both names, and the input keeps its bytes.
TEST_F(Cli, OutputsThatAreInputsAreRefusedAndTheInputsKept)
{
  const std::string t = path("t");
  ASSERT_EQ(run("synth hexa-grid --vertices 2000 -o " + quote(t)).status, 0);
  ASSERT_EQ(run("learn " + quote(t + ".off") + " -o " + quote(path("m.mpm"))).status, 0);
  const std::string mesh = slurp(t + ".off"), labels = slurp(t + ".seg"), annotation = slurp(t + ".json"),
                    model = slurp(path("m.mpm"));
  const std::string respelled = (dir / "." / "t.off").string();
  const std::pair<std::string, std::string> refused[] = {
    {"learn " + quote(t + ".off") + " -o " + quote(respelled), "t.off"},
    {"learn " + quote(t + ".off") + " --labels " + quote(t + ".seg") + " --write-annotation " + quote(t + ".seg") +
       " -o " + quote(path("n.mpm")),
     "t.seg"},
    {"graph " + quote(path("m.mpm")) + " -o " + quote(path("m.mpm")), "m.mpm"},
    {"cut " + quote(t + ".off") + " --cuts " + quote(path("none.json")) + " -o " + quote(t), "t.off"},
    {"correspond " + quote(t + ".off") + " -o " + quote(t), "t.json"}, // the annotation found beside the mesh
  };
  for(const auto& [arguments, named] : refused)
  {
    const Run_result r = run(arguments);
    expect_error(r, 1, "would overwrite the input");
    EXPECT_NE(r.err.find(named), std::string::npos) << arguments << ": " << r.err;
  }
  EXPECT_EQ(slurp(t + ".off"), mesh);
  EXPECT_EQ(slurp(t + ".seg"), labels);
  EXPECT_EQ(slurp(t + ".json"), annotation);
  EXPECT_EQ(slurp(path("m.mpm")), model);
  EXPECT_FALSE(fs::exists(path("n.mpm")));
  // A prefix that is a directory would have written dir/.off.
  const Run_result directory = run("synth hexa-grid --vertices 2000 -o " + quote(dir.string() + "/"));
  expect_error(directory, 2, "is a directory, not a prefix");
  // A device is written, not replaced.
  EXPECT_EQ(run("learn " + quote(t + ".off") + " -o /dev/null").status, 0);
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// What would need more memory than the machine has is refused up front
// with the estimate (synth --vertices 2e9 allocated until the machine gave out).
TEST_F(Cli, OptionsNeedingMoreMemoryThanTheMachineHasAreRefused)
{
  expect_error(run("synth hand --vertices 2000000000 -o " + quote(path("huge"))), 2, "needs about");
  EXPECT_FALSE(fs::exists(path("huge.off")));
  ASSERT_EQ(run("synth hexa-grid --vertices 2000 -o " + quote(path("t"))).status, 0);
  ASSERT_EQ(run("learn " + quote(path("t.off")) + " -o " + quote(path("t.mpm"))).status, 0);
  // 100,000 graphs of 2,000 vertices need about 80 GB.
  if(double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE)) < 60e9)
    expect_error(run("spawn " + quote(path("t.mpm")) + " --count 100000"), 2, "of memory; this machine has");
}

// Progress runs once from 0 to 100% through correspondence and through
// writing: it restarted at 0% for every part type.
TEST_F(Cli, CorrespondProgressAdvancesAcrossPartTypes)
{
  const std::string t = path("hand");
  ASSERT_EQ(run("synth hand --vertices 2000 -o " + quote(t)).status, 0);
  const Run_result r = run("correspond " + quote(t + ".off") + " --progress -o " + quote(path("c")));
  ASSERT_EQ(r.status, 0) << r.err;
  std::map<std::string, std::vector<int>> percents; // "correspondence" (and refinement), "writing"
  for(const std::string& l : r.err_lines())
  {
    const std::string stage = l.rfind("mpm correspond: writing ", 0) == 0 ? "writing"
                            : l.rfind("mpm correspond: correspondence of ", 0) == 0 ||
                                  l.rfind("mpm correspond: refinement of ", 0) == 0
                              ? "correspondence"
                              : "";
    if(!stage.empty()) percents[stage].push_back(std::stoi(l.substr(l.rfind(' ') + 1)));
  }
  for(const auto& [stage, values] : percents)
  {
    ASSERT_GE(values.size(), 3u) << stage;
    EXPECT_TRUE(std::is_sorted(values.begin(), values.end())) << stage << ": " << r.err;
  }
  EXPECT_EQ(percents["writing"].back(), 100) << r.err;
}

// The solve advances the progress of assemble (it sat at "assembling 20%"
// for the whole solve of a large graph), and spawn advances by graph.
TEST_F(Cli, AssembleAndSpawnProgressAdvanceThroughTheirWork)
{
  const std::string t = path("grid");
  ASSERT_EQ(run("synth hexa-grid --vertices 2000 -o " + quote(t)).status, 0);
  ASSERT_EQ(run("learn " + quote(t + ".off") + " -o " + quote(path("g.mpm"))).status, 0);
  const Run_result r = run("assemble " + quote(path("g.mpm")) + " --progress -o " + quote(path("a.off")));
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<int> percents;
  bool embedding = false;
  for(const std::string& l : r.err_lines())
    if(l.rfind("mpm assemble: ", 0) == 0)
    {
      percents.push_back(std::stoi(l.substr(l.rfind(' ') + 1)));
      embedding = embedding || l.find("embedding") != std::string::npos;
    }
  EXPECT_TRUE(embedding) << r.err;
  EXPECT_TRUE(std::is_sorted(percents.begin(), percents.end())) << r.err;
  ASSERT_FALSE(percents.empty());
  EXPECT_EQ(percents.back(), 100) << r.err;

  // Spawning advances graph by graph (it sat at 10% for minutes).
  const Run_result spawn = run("spawn " + quote(path("g.mpm")) + " --count 5 --progress");
  ASSERT_EQ(spawn.status, 0) << spawn.err;
  std::vector<int> spawning;
  for(const std::string& l : spawn.err_lines())
    if(l.rfind("mpm spawn: spawning", 0) == 0) spawning.push_back(std::stoi(l.substr(l.rfind(' ') + 1)));
  EXPECT_GE(spawning.size(), 5u) << spawn.err;
  EXPECT_TRUE(std::is_sorted(spawning.begin(), spawning.end())) << spawn.err;
}

// A graph whose cycle cannot close is still written, but with a warning
// naming the cause and exit status 3; the open row it was made from is not.
TEST_F(Cli, DoubtfulAssemblyIsWrittenWithAWarningAndStatusThree)
{
  const std::string t = path("grid");
  ASSERT_EQ(run("synth hexa-grid --vertices 2000 -o " + quote(t)).status, 0);
  ASSERT_EQ(run("learn " + quote(t + ".off") + " -o " + quote(path("g.mpm"))).status, 0);
  ASSERT_EQ(run("graph " + quote(path("g.mpm")) + " -o " + quote(path("g.json"))).status, 0);
  json row = json::parse(slurp(path("g.json")));
  row["nodes"].erase(row["nodes"].begin() + 3, row["nodes"].end());
  json edges = json::array();
  for(const json& e : row["edges"])
    if(e["first"].get<int>() < 3 && e["second"].get<int>() < 3) edges.push_back(e);
  ASSERT_EQ(edges.size(), 2u);
  row["edges"] = edges;
  std::ofstream(path("row.json")) << row.dump(2);

  const Run_result open = run("assemble " + quote(path("g.mpm")) + " --graph " + quote(path("row.json")) +
                              " -o " + quote(path("open.off")) + " --json");
  ASSERT_EQ(open.status, 0) << open.err;
  EXPECT_TRUE(one_object(open)["warnings"].empty());

  const Run_result closed = run("assemble " + quote(path("g.mpm")) + " --graph " + quote(path("row.json")) +
                                " --close 0:2 -o " + quote(path("closed.off")) + " --json");
  EXPECT_EQ(closed.status, 3) << closed.err;
  const json s = one_object(closed);
  EXPECT_GT(s["energy_per_part"].get<double>(), 1e3 * s["training_energy_per_part"].get<double>());
  ASSERT_EQ(s["warnings"].size(), 1u) << s["warnings"];
  const std::string warning = s["warnings"][0];
  EXPECT_NE(warning.find("times that of the training example's graph"), std::string::npos) << warning;
  EXPECT_NE(warning.find("--close 0:2"), std::string::npos) << warning;
  EXPECT_NE(closed.err.find("mpm: warning: " + warning), std::string::npos) << closed.err;
  EXPECT_EQ(off_counts(path("closed.off")).first, s["vertices"].get<long>());

  // Stopped at the iteration cap (the closed row takes 8 iterations; the
  // open one converges in 1): a warning of its own.
  const Run_result capped = run("assemble " + quote(path("g.mpm")) + " --graph " + quote(path("row.json")) +
                                " --close 0:2 --iterations 1 -o " + quote(path("capped.off")) + " --json");
  EXPECT_EQ(capped.status, 3) << capped.err;
  EXPECT_NE(one_object(capped)["warnings"][0].get<std::string>().find("iteration cap (1)"), std::string::npos);
}

} // namespace
