// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh_files.h"

#include <filesystem>
#include <limits>

namespace mpm {

namespace fs = std::filesystem;

std::vector<Mesh_files> collect_mesh_files(const Args& args, bool first_is_model, bool write_annotation)
{
  std::vector<Mesh_files> meshes;
  bool model_seen = !first_is_model;
  for(const Arg_item& item : args.items)
  {
    if(item.option.empty())
    {
      if(!model_seen) model_seen = true;
      else meshes.push_back({item.value, "", "", "", false, false, false});
      continue;
    }
    const bool writes = write_annotation && item.option == "write-annotation";
    if(item.option != "labels" && item.option != "annotation" && !writes) continue;
    if(meshes.empty()) throw Usage_error("option --" + item.option + " must follow the MESH it belongs to");
    Mesh_files& m = meshes.back();
    if(writes)
    {
      if(!m.write_annotation.empty()) throw Usage_error("option --write-annotation given twice for " + m.mesh);
      m.write_annotation = item.value;
      continue;
    }
    bool& given = item.option == "labels" ? m.labels_given : m.annotation_given;
    if(given) throw Usage_error("option --" + item.option + " given twice for " + m.mesh);
    given = true;
    (item.option == "labels" ? m.labels : m.annotation) = item.value;
  }
  for(Mesh_files& m : meshes)
  {
    std::error_code ec;
    const std::string seg = fs::path(m.mesh).replace_extension(".seg").string();
    const std::string json = fs::path(m.mesh).replace_extension(".json").string();
    if(!m.labels_given) m.labels = fs::is_regular_file(seg, ec) ? seg : "components";
    if(!m.annotation_given && fs::is_regular_file(json, ec)) m.annotation = json;
  }
  return meshes;
}

std::vector<Option_spec> mesh_file_options()
{
  const double none = std::numeric_limits<double>::infinity();
  return {
    {"labels", 0, Value_kind::input_file, "SEG", "MESH.seg if present, else components", "part labels of the preceding MESH",
     -none, none, false, true},
    {"annotation", 0, Value_kind::input_file, "JSON", "MESH.json if present, else none", "annotation of the preceding MESH",
     -none, none, false, true},
  };
}

} // namespace mpm
