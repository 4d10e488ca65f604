// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/internal/Json_reader.h>

namespace CGAL {
namespace MPM {

namespace {

using json = nlohmann::json;
using internal::Json_reader;

const char* const cut_format = "cgal-mpm-cuts";
constexpr int cut_version = 1;

// Structure and types only: whether the vertices exist, the cuts separate
// and the seeds fall into distinct regions depends on the mesh, so
// cut_mesh() checks that (for files and in-memory specifications alike).
Cut_line parse_cut(const Json_reader& reader, const json& c, const std::string& element)
{
  Cut_line cut;
  if(!c.is_object()) reader.fail(element, "must be an object with \"vertices\"");
  reader.check_keys(c, element, {"name", "vertices", "closed"});
  if(!c.contains("vertices")) reader.fail(element, "lacks \"vertices\"");
  const json& vertices = reader.array_of(c["vertices"], element + ".vertices");
  for(std::size_t k = 0; k < vertices.size(); ++k)
    cut.vertices.push_back(reader.non_negative(vertices[k], element + ".vertices[" + std::to_string(k) + "]"));
  if(c.contains("name")) cut.name = reader.string_of(c["name"], element + ".name");
  if(c.contains("closed")) {
    if(!c["closed"].is_boolean())
      reader.fail(element + ".closed", "must be true or false, not " + std::string(c["closed"].type_name()));
    cut.closed = c["closed"].get<bool>();
  }
  return cut;
}

} // namespace

Cut_specification parse_cut_specification(const std::string& text, const std::string& source)
{
  const Json_reader reader(source);
  const json root = reader.parse_document(text, cut_format, cut_version, "cut file");
  reader.check_keys(root, "", {"format", "version", "cuts", "parts"});
  if(!root.contains("cuts")) reader.fail("", "lacks \"cuts\"");

  Cut_specification spec;
  spec.source = source;
  const json& cuts = reader.array_of(root["cuts"], "cuts");
  for(std::size_t i = 0; i < cuts.size(); ++i)
    spec.cuts.push_back(parse_cut(reader, cuts[i], "cuts[" + std::to_string(i) + "]"));
  if(root.contains("parts")) {
    const json& parts = reader.array_of(root["parts"], "parts");
    for(std::size_t i = 0; i < parts.size(); ++i) {
      const std::string element = "parts[" + std::to_string(i) + "]";
      const json& p = parts[i];
      if(!p.is_object()) reader.fail(element, "must be an object with \"label\" and \"seed\"");
      reader.check_keys(p, element, {"label", "seed"});
      for(const char* required : {"label", "seed"})
        if(!p.contains(required)) reader.fail(element, std::string("lacks \"") + required + "\"");
      spec.parts.push_back({reader.non_negative(p["label"], element + ".label"),
                            reader.non_negative(p["seed"], element + ".seed")});
    }
  }
  return spec;
}

Cut_specification read_cut_specification(const std::string& path)
{
  return parse_cut_specification(internal::read_file(path), path);
}

} // namespace MPM
} // namespace CGAL
