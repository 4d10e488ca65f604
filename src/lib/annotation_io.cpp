// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Annotation_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Atomic_file.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>

namespace CGAL {
namespace MPM {

namespace {

using json = nlohmann::json;

const char* const annotation_format = "cgal-mpm-annotation";
constexpr int annotation_version = 1;

class Annotation_parser
{
public:
  explicit Annotation_parser(const std::string& source) : source_(source) {}

  Annotation parse(const std::string& text) const
  {
    json root;
    try {
      root = json::parse(text);
    } catch(const json::parse_error& e) {
      throw Input_error(source_, "", "malformed JSON at byte " + std::to_string(e.byte) + ": " +
                                       one_line(e.what()));
    }
    if(!root.is_object())
      throw Input_error(source_, "", "the annotation must be a JSON object, not " +
                                       std::string(root.type_name()));
    check_keys(root, "", {"format", "version", "parts", "types", "parameters"});

    Annotation a;
    a.source = source_;
    if(root.contains("format") && string_of(root["format"], "format") != annotation_format)
      throw Input_error(source_, "format", "\"" + root["format"].get<std::string>() +
                                             "\" is not \"" + annotation_format + "\"");
    if(root.contains("version")) {
      const int version = integer_of(root["version"], "version");
      if(version != annotation_version)
        throw Input_error(source_, "version", "annotation version " + std::to_string(version) +
                                                ", this build reads version " +
                                                std::to_string(annotation_version));
    }
    if(root.contains("parts")) parse_parts(array_of(root["parts"], "parts"), a);
    if(root.contains("types")) parse_types(array_of(root["types"], "types"), a);
    if(root.contains("parameters")) parse_parameters(root["parameters"], a.parameters);
    return a;
  }

private:
  void parse_parts(const json& parts, Annotation& a) const
  {
    std::map<int, std::size_t> entry_of_label;
    for(std::size_t i = 0; i < parts.size(); ++i) {
      const std::string element = "parts[" + std::to_string(i) + "]";
      const json& p = parts[i];
      if(!p.is_object())
        throw Input_error(source_, element, "must be an object with \"label\" and \"type\"");
      check_keys(p, element, {"label", "type", "landmarks"});
      for(const char* required : {"label", "type"})
        if(!p.contains(required))
          throw Input_error(source_, element, std::string("lacks \"") + required + "\"");
      const int label = non_negative(p["label"], element + ".label");
      const auto seen = entry_of_label.emplace(label, i);
      if(!seen.second)
        throw Input_error(source_, element, "label " + std::to_string(label) + " appears twice (also in parts[" +
                                              std::to_string(seen.first->second) + "])");
      a.part_type_of_label[label] = type_name(p["type"], element + ".type");
      if(p.contains("landmarks")) {
        const std::string where = element + ".landmarks";
        std::vector<int>& landmarks = a.landmarks_of_label[label];
        const json& l = array_of(p["landmarks"], where);
        for(std::size_t k = 0; k < l.size(); ++k) {
          const int v = non_negative(l[k], where + "[" + std::to_string(k) + "]");
          if(std::find(landmarks.begin(), landmarks.end(), v) != landmarks.end())
            throw Input_error(source_, where, "vertex " + std::to_string(v) + " is listed twice");
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
      if(!t.is_object())
        throw Input_error(source_, element, "must be an object with \"name\" and \"modes\"");
      check_keys(t, element, {"name", "modes"});
      if(!t.contains("name"))
        throw Input_error(source_, element, "lacks \"name\"");
      const std::string name = type_name(t["name"], element + ".name");
      // A type no part uses is almost always a misspelt name.
      if(used.count(name) == 0)
        throw Input_error(source_, element, "type \"" + name + "\" is not the type of any part");
      if(a.modes_of_type.count(name) != 0)
        throw Input_error(source_, element, "type \"" + name + "\" is listed twice");
      a.modes_of_type[name] = t.contains("modes") ? non_negative(t["modes"], element + ".modes") : 0;
    }
  }

  void parse_parameters(const json& p, Model_parameters& m) const
  {
    if(!p.is_object())
      throw Input_error(source_, "parameters", "must be an object, not " + std::string(p.type_name()));
    check_keys(p, "parameters", {"sigma_sub", "sigma_bound", "docking_radius", "modes", "explained_variance"});
    for(const auto& length : {std::make_pair("sigma_sub", &m.sigma_sub),
                              std::make_pair("sigma_bound", &m.sigma_bound),
                              std::make_pair("docking_radius", &m.docking_radius)}) {
      if(!p.contains(length.first)) continue;
      const std::string element = std::string("parameters.") + length.first;
      const double value = number_of(p[length.first], element);
      if(!(value > 0))
        throw Input_error(source_, element, std::string(length.first) + " must be positive (got " +
                                              p[length.first].dump() + ")");
      *length.second = value;
    }
    if(p.contains("modes")) m.modes = non_negative(p["modes"], "parameters.modes");
    if(p.contains("explained_variance")) {
      const double value = number_of(p["explained_variance"], "parameters.explained_variance");
      if(!(value > 0 && value <= 1))
        throw Input_error(source_, "parameters.explained_variance",
                          "explained_variance must be in (0, 1] (got " + p["explained_variance"].dump() + ")");
      m.explained_variance = value;
    }
  }

  void check_keys(const json& object, const std::string& element,
                  std::initializer_list<const char*> allowed) const
  {
    for(auto it = object.begin(); it != object.end(); ++it)
      if(std::none_of(allowed.begin(), allowed.end(), [&](const char* k) { return it.key() == k; })) {
        std::string list;
        for(const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
        throw Input_error(source_, element.empty() ? "key \"" + it.key() + "\"" : element,
                          "unknown key \"" + it.key() + "\" (allowed: " + list + ")");
      }
  }

  const json& array_of(const json& j, const std::string& element) const
  {
    if(!j.is_array())
      throw Input_error(source_, element, "must be an array, not " + std::string(j.type_name()));
    return j;
  }

  std::string string_of(const json& j, const std::string& element) const
  {
    if(!j.is_string())
      throw Input_error(source_, element, "must be a string, not " + std::string(j.type_name()));
    return j.get<std::string>();
  }

  std::string type_name(const json& j, const std::string& element) const
  {
    std::string name = string_of(j, element);
    if(std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isspace(c); }))
      throw Input_error(source_, element, "the type name is empty");
    return name;
  }

  double number_of(const json& j, const std::string& element) const
  {
    if(!j.is_number())
      throw Input_error(source_, element, "must be a number, not " + std::string(j.type_name()));
    return j.get<double>();
  }

  int integer_of(const json& j, const std::string& element) const
  {
    if(!j.is_number_integer())
      throw Input_error(source_, element, "must be an integer, not " +
                                            (j.is_number() ? j.dump() : std::string(j.type_name())));
    const auto value = j.get<std::int64_t>();
    if(j.is_number_unsigned() ? j.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<int>::max())
                              : (value > std::numeric_limits<int>::max() ||
                                 value < std::numeric_limits<int>::min()))
      throw Input_error(source_, element, j.dump() + " is too large");
    return int(value);
  }

  int non_negative(const json& j, const std::string& element) const
  {
    const int value = integer_of(j, element);
    if(value < 0)
      throw Input_error(source_, element, "must not be negative (got " + std::to_string(value) + ")");
    return value;
  }

  // nlohmann's messages start with an exception id users need not see and
  // quote the text near the error, which may hold line breaks.
  static std::string one_line(std::string s)
  {
    const std::size_t id_end = s.find("] ");
    if(s.rfind("[json.exception", 0) == 0 && id_end != std::string::npos) s.erase(0, id_end + 2);
    for(char& c : s)
      if(std::iscntrl(static_cast<unsigned char>(c))) c = ' ';
    return s;
  }

  std::string source_;
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
