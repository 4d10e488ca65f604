// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/internal/Json_reader.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace CGAL {
namespace MPM {

namespace {

using json = nlohmann::json;
using internal::Json_reader;

const char* const annotation_format = "cgal-mpm-annotation";
constexpr int annotation_version = 1;

// The annotation-specific checks; the typed access, the key checks and the
// error messages come from Json_reader, shared with the handle file format.
class Annotation_parser
{
public:
  explicit Annotation_parser(const std::string& source) : reader_(source) {}

  Annotation parse(const std::string& text) const
  {
    const json root = reader_.parse_document(text, annotation_format, annotation_version, "annotation");
    reader_.check_keys(root, "", {"format", "version", "parts", "types", "parameters"});

    Annotation a;
    a.source = reader_.source();
    if(root.contains("parts")) parse_parts(reader_.array_of(root["parts"], "parts"), a);
    if(root.contains("types")) parse_types(reader_.array_of(root["types"], "types"), a);
    if(root.contains("parameters")) parse_parameters(reader_.object_of(root["parameters"], "parameters"), a.parameters);
    return a;
  }

private:
  void parse_parts(const json& parts, Annotation& a) const
  {
    std::map<int, std::size_t> entry_of_label;
    for(std::size_t i = 0; i < parts.size(); ++i) {
      const std::string element = "parts[" + std::to_string(i) + "]";
      const json& p = parts[i];
      if(!p.is_object()) reader_.fail(element, "must be an object with \"label\" and \"type\"");
      reader_.check_keys(p, element, {"label", "type", "landmarks"});
      for(const char* required : {"label", "type"})
        if(!p.contains(required)) reader_.fail(element, std::string("lacks \"") + required + "\"");
      const int label = reader_.non_negative(p["label"], element + ".label");
      const auto seen = entry_of_label.emplace(label, i);
      if(!seen.second)
        reader_.fail(element, "label " + std::to_string(label) + " appears twice (also in parts[" +
                                std::to_string(seen.first->second) + "])");
      a.part_type_of_label[label] = type_name(p["type"], element + ".type");
      if(p.contains("landmarks")) {
        const std::string where = element + ".landmarks";
        std::vector<int>& landmarks = a.landmarks_of_label[label];
        const json& l = reader_.array_of(p["landmarks"], where);
        for(std::size_t k = 0; k < l.size(); ++k) {
          const int v = reader_.non_negative(l[k], where + "[" + std::to_string(k) + "]");
          if(std::find(landmarks.begin(), landmarks.end(), v) != landmarks.end())
            reader_.fail(where, "vertex " + std::to_string(v) + " is listed twice");
          landmarks.push_back(v);
        }
      }
    }
  }

  void parse_types(const json& types, Annotation& a) const
  {
    std::set<std::string> used;
    for(const auto& entry : a.part_type_of_label) used.insert(entry.second);
    for(std::size_t i = 0; i < types.size(); ++i) {
      const std::string element = "types[" + std::to_string(i) + "]";
      const json& t = types[i];
      if(!t.is_object()) reader_.fail(element, "must be an object with \"name\" and \"modes\"");
      reader_.check_keys(t, element, {"name", "modes"});
      if(!t.contains("name")) reader_.fail(element, "lacks \"name\"");
      const std::string name = type_name(t["name"], element + ".name");
      // A type no part uses is almost always a misspelt name.
      if(used.count(name) == 0) reader_.fail(element, "type \"" + name + "\" is not the type of any part");
      if(a.modes_of_type.count(name) != 0) reader_.fail(element, "type \"" + name + "\" is listed twice");
      a.modes_of_type[name] = t.contains("modes") ? reader_.non_negative(t["modes"], element + ".modes") : 0;
    }
  }

  void parse_parameters(const json& p, Model_parameters& m) const
  {
    reader_.check_keys(p, "parameters", {"sigma_sub", "sigma_bound", "docking_radius", "modes", "explained_variance"});
    for(const auto& length : {std::make_pair("sigma_sub", &m.sigma_sub),
                              std::make_pair("sigma_bound", &m.sigma_bound),
                              std::make_pair("docking_radius", &m.docking_radius)}) {
      if(!p.contains(length.first)) continue;
      const std::string element = std::string("parameters.") + length.first;
      const double value = reader_.number_of(p[length.first], element);
      if(!(value > 0))
        reader_.fail(element, std::string(length.first) + " must be positive (got " + p[length.first].dump() + ")");
      *length.second = value;
    }
    if(p.contains("modes")) m.modes = reader_.non_negative(p["modes"], "parameters.modes");
    if(p.contains("explained_variance")) {
      const double value = reader_.number_of(p["explained_variance"], "parameters.explained_variance");
      if(!(value > 0 && value <= 1))
        reader_.fail("parameters.explained_variance",
                     "explained_variance must be in (0, 1] (got " + p["explained_variance"].dump() + ")");
      m.explained_variance = value;
    }
  }

  std::string type_name(const json& j, const std::string& element) const
  {
    std::string name = reader_.string_of(j, element);
    if(std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isspace(c); }))
      reader_.fail(element, "the type name is empty");
    return name;
  }

  Json_reader reader_;
};

} // namespace

Annotation parse_annotation(const std::string& text, const std::string& source)
{
  return Annotation_parser(source).parse(text);
}

Annotation read_annotation(const std::string& path)
{
  return parse_annotation(internal::read_file(path), path);
}

std::string annotation_to_json(const Annotation& annotation)
{
  json root;
  root["format"] = annotation_format;
  root["version"] = annotation_version;
  json parts = json::array();
  for(const auto& entry : annotation.part_type_of_label) {
    json part = {{"label", entry.first}, {"type", entry.second}};
    const auto landmarks = annotation.landmarks_of_label.find(entry.first);
    if(landmarks != annotation.landmarks_of_label.end()) part["landmarks"] = landmarks->second;
    parts.push_back(part);
  }
  for(const auto& entry : annotation.landmarks_of_label)
    if(annotation.part_type_of_label.count(entry.first) == 0)
      throw Input_error(annotation.source, "label " + std::to_string(entry.first),
                        "has landmarks but no part type, which the annotation format cannot express");
  root["parts"] = parts;
  json types = json::array();
  for(const auto& entry : annotation.modes_of_type) types.push_back({{"name", entry.first}, {"modes", entry.second}});
  if(!types.empty()) root["types"] = types;

  // Negative lengths mean "automatic", which the format expresses by omission.
  const Model_parameters& p = annotation.parameters;
  json parameters;
  if(p.sigma_sub > 0) parameters["sigma_sub"] = p.sigma_sub;
  if(p.sigma_bound > 0) parameters["sigma_bound"] = p.sigma_bound;
  if(p.docking_radius > 0) parameters["docking_radius"] = p.docking_radius;
  parameters["modes"] = p.modes;
  parameters["explained_variance"] = p.explained_variance;
  root["parameters"] = parameters;
  return root.dump(2) + "\n";
}

void write_annotation(const Annotation& annotation, const std::string& path)
{
  const std::string text = annotation_to_json(annotation);
  internal::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

} // namespace MPM
} // namespace CGAL
