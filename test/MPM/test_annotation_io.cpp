// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Io_test_support.h"

#include <CGAL/MPM/IO/Annotation_io.h>

using namespace CGAL::MPM;

namespace {

const std::string full_annotation = R"({
  "format": "cgal-mpm-annotation", "version": 1,
  "parts": [{"label": 0, "type": "palm"},
            {"label": 1, "type": "proximal", "landmarks": [12, 40, 77]},
            {"label": 4, "type": "proximal", "landmarks": [3, 9, 1]}],
  "types": [{"name": "proximal", "modes": 3}],
  "parameters": {"sigma_sub": 0.05, "sigma_bound": 0.1, "docking_radius": 0.2, "modes": 2,
                 "explained_variance": 0.95}
})";

void expect_same(const Annotation& a, const Annotation& b)
{
  EXPECT_EQ(a.part_type_of_label, b.part_type_of_label);
  EXPECT_EQ(a.modes_of_type, b.modes_of_type);
  EXPECT_EQ(a.landmarks_of_label, b.landmarks_of_label);
  EXPECT_EQ(a.parameters.sigma_sub, b.parameters.sigma_sub);
  EXPECT_EQ(a.parameters.sigma_bound, b.parameters.sigma_bound);
  EXPECT_EQ(a.parameters.docking_radius, b.parameters.docking_radius);
  EXPECT_EQ(a.parameters.modes, b.parameters.modes);
  EXPECT_EQ(a.parameters.explained_variance, b.parameters.explained_variance);
}

std::string with_parameters(const std::string& parameters)
{
  return R"({"parts": [{"label": 0, "type": "a"}], "parameters": )" + parameters + "}";
}

} // namespace

TEST(AnnotationIo, ParsesEveryField)
{
  const Annotation a = parse_annotation(full_annotation, "hand.json");
  EXPECT_EQ(a.source, "hand.json");
  EXPECT_EQ(a.part_type_of_label, (std::map<int, std::string>{{0, "palm"}, {1, "proximal"}, {4, "proximal"}}));
  EXPECT_EQ(a.modes_of_type, (std::map<std::string, int>{{"proximal", 3}}));
  EXPECT_EQ(a.landmarks_of_label, (std::map<int, std::vector<int>>{{1, {12, 40, 77}}, {4, {3, 9, 1}}}));
  EXPECT_EQ(a.parameters.sigma_sub, 0.05);
  EXPECT_EQ(a.parameters.sigma_bound, 0.1);
  EXPECT_EQ(a.parameters.docking_radius, 0.2);
  EXPECT_EQ(a.parameters.modes, 2);
  EXPECT_EQ(a.parameters.explained_variance, 0.95);
}

TEST(AnnotationIo, EverythingIsOptional)
{
  const Annotation a = parse_annotation("{}", "empty.json");
  const Model_parameters defaults;
  EXPECT_TRUE(a.part_type_of_label.empty());
  EXPECT_EQ(a.parameters.sigma_sub, defaults.sigma_sub);
  EXPECT_EQ(a.parameters.docking_radius, defaults.docking_radius);
  EXPECT_EQ(a.parameters.explained_variance, defaults.explained_variance);
  expect_same(parse_annotation(annotation_to_json(a), "again"), a);
}

TEST(AnnotationIo, RoundTripsThroughTextAndFiles)
{
  Annotation a = parse_annotation(full_annotation, "hand.json");
  a.parameters.sigma_sub = 0.1 + 0.2; // not exactly representable in few digits
  expect_same(parse_annotation(annotation_to_json(a), "copy"), a);

  mpm_test::Scratch_directory dir;
  const std::string path = dir.file("hand.json");
  write_annotation(a, path);
  const std::string bytes = mpm_test::read_bytes(path);
  const Annotation b = read_annotation(path);
  expect_same(b, a);
  EXPECT_EQ(b.source, path);
  EXPECT_EQ(mpm_test::read_bytes(path), bytes) << "input modified";
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"hand.json"}));
  MPM_EXPECT_INPUT_ERROR(read_annotation(dir.file("none.json")), "none.json", "file not found");
}

TEST(AnnotationIo, MalformedJsonGivesTheBytePosition)
{
  MPM_EXPECT_INPUT_ERROR(parse_annotation("{\"parts\": [\n}", "bad.json"), "bad.json", "malformed JSON at byte 13: parse error at line 2, column 1");
  MPM_EXPECT_INPUT_ERROR(parse_annotation("", "empty.json"), "empty.json", "malformed JSON");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(std::string("\xff\xfe\x00\x01", 4), "bin.json"), "bin.json", "malformed JSON");
  MPM_EXPECT_INPUT_ERROR(parse_annotation("[1, 2]", "array.json"), "array.json", "must be a JSON object");
}

// nlohmann's parser keeps the last of two equal keys; the readers refuse
// them (every JSON format goes through the same reader).
TEST(AnnotationIo, DuplicateKeysAreRefusedByTheirPath)
{
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [], "parts": []})", "a.json"), "a.json: parts: the key is given twice");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": "a"}, {"label": 1, "label": 2, "type": "a"}]})", "a.json"),
                         "a.json: parts[1].label: the key is given twice");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"modes": 1, "modes": 2})"), "a.json"),
                         "a.json: parameters.modes: the key is given twice");
}

TEST(AnnotationIo, UnknownKeysAreNamed)
{
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"part": []})", "a.json"), "a.json", "unknown key \"part\"",
                         "allowed: format, version, parts, types, parameters");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": "a", "colour": 3}]})", "a.json"),
                         "a.json: parts[0]: unknown key \"colour\"");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"sigma": 1})"), "a.json"),
                         "a.json: parameters: unknown key \"sigma\"");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": "a"}], "types": [{"name": "a", "mode": 1}]})", "a.json"),
                         "a.json: types[0]: unknown key \"mode\"");
}

TEST(AnnotationIo, WrongTypesAndValuesAreRejected)
{
  const std::string s = "x.json";
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": {}})", s), "x.json: parts: must be an array");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": "0", "type": "a"}]})", s), "parts[0].label", "must be an integer");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 1.5, "type": "a"}]})", s), "parts[0].label", "must be an integer");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 1e12, "type": "a"}]})", s), "parts[0].label");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 99999999999, "type": "a"}]})", s), "parts[0].label", "too large");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": -1, "type": "a"}]})", s), "parts[0].label", "must not be negative");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"type": "a"}]})", s), "parts[0]", "lacks \"label\"");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0}]})", s), "parts[0]", "lacks \"type\"");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": ""}]})", s), "parts[0].type", "empty");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": 3}]})", s), "parts[0].type", "must be a string");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": "a"}, {"label": 0, "type": "b"}]})", s),
                         "x.json: parts[1]: label 0 appears twice (also in parts[0])");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": "a", "landmarks": [1, -2]}]})", s),
                         "parts[0].landmarks[1]", "must not be negative");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": "a", "landmarks": [1, 1]}]})", s),
                         "parts[0].landmarks", "listed twice");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": "a"}], "types": [{"name": "b"}]})", s),
                         "types[0]", "\"b\" is not the type of any part");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": 0, "type": "a"}], "types": [{"name": "a", "modes": -1}]})", s),
                         "types[0].modes", "must not be negative");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"format": "obj"})", s), "x.json: format:", "cgal-mpm-annotation");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"version": 2})", s), "x.json: version: annotation version 2, this build reads version 1");
}

TEST(AnnotationIo, ParameterRanges)
{
  const std::string s = "p.json";
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"docking_radius": 0})"), s),
                         "p.json: parameters.docking_radius: docking_radius must be positive (got 0)");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"docking_radius": -0.5})"), s),
                         "parameters.docking_radius", "docking_radius must be positive (got -0.5)");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"docking_radius": "big"})"), s),
                         "parameters.docking_radius", "must be a number");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"sigma_sub": 0})"), s), "sigma_sub must be positive");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"sigma_bound": -1})"), s), "sigma_bound must be positive");
  for(const std::string bad : {"0", "1.01", "-0.5"})
    MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"explained_variance": )" + bad + "}"), s),
                           "parameters.explained_variance", "must be in (0, 1]");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"modes": -3})"), s), "parameters.modes", "must not be negative");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters("[]"), s), "parameters", "must be an object");
  EXPECT_EQ(parse_annotation(with_parameters(R"({"explained_variance": 1})"), s).parameters.explained_variance, 1.);
}

TEST(AnnotationIo, NumbersBeyondTheDoubleRangeAreInputErrors)
{
  // nlohmann::json throws out_of_range (406) for these while parsing.
  MPM_EXPECT_INPUT_ERROR(parse_annotation(with_parameters(R"({"sigma_sub": 1e999})"), "big.json"), "big.json",
                         "malformed JSON", "1e999");
  MPM_EXPECT_INPUT_ERROR(parse_annotation(R"({"parts": [{"label": -1e999, "type": "a"}]})", "big.json"), "big.json",
                         "malformed JSON", "-1e999");

  mpm_test::Scratch_directory dir;
  const std::string path = dir.file("big.json");
  mpm_test::write_bytes(path, with_parameters(R"({"docking_radius": 1e999})"));
  MPM_EXPECT_INPUT_ERROR(read_annotation(path), path, "malformed JSON", "1e999");
}
