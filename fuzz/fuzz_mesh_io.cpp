// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the mesh readers, which work on paths. The first byte
// chooses the format (bits 0-1: .off .obj .ply .stl) and the labels (bits
// 2-3: a .seg file, `components`, `property:label`, none: read_mesh_file()
// only). The rest is the mesh file, followed, after an optional line
// `#SEG`, by the .seg file. Both are written to a private temporary
// directory (one per fuzzing process).
#include "fuzz_common.h"

#include <CGAL/MPM/IO/Mesh_io.h>

#include <cstring>
#include <unistd.h>

namespace {

std::string directory;

void remove_directory()
{
  for(const char* name : {"/in.off", "/in.obj", "/in.ply", "/in.stl", "/in.seg"})
    ::unlink((directory + name).c_str());
  ::rmdir(directory.c_str());
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/mpm_fuzz_mesh_XXXXXX";
  if(::mkdtemp(pattern.data()) == nullptr) { std::perror("mkdtemp"); std::abort(); }
  directory = pattern;
  std::atexit(remove_directory);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0) return 0;
  static const char* const extensions[4] = {".off", ".obj", ".ply", ".stl"};
  const std::uint8_t mode = data[0];
  const std::string rest = mpm_fuzz::as_string(data + 1, size - 1);
  const std::string separator = "#SEG\n";
  const std::size_t at = rest.find(separator);
  const std::string mesh_bytes = rest.substr(0, at);
  const std::string seg_bytes = at == std::string::npos ? std::string() : rest.substr(at + separator.size());

  const std::string mesh_path = directory + "/in" + extensions[mode & 3];
  const std::string seg_path = directory + "/in.seg";
  mpm_fuzz::write_bytes(mesh_path, mesh_bytes);
  mpm_fuzz::expect_input_errors_only([&] {
    switch((mode >> 2) & 3)
    {
    case 0:
    {
      mpm_fuzz::write_bytes(seg_path, seg_bytes);
      std::vector<std::string> warnings;
      const CGAL::MPM::Labeled_mesh m = CGAL::MPM::read_labeled_mesh(mesh_path, seg_path, &warnings);
      CGAL::MPM::validate_labeled_mesh(m);
      break;
    }
    case 1:
      CGAL::MPM::validate_labeled_mesh(CGAL::MPM::read_labeled_mesh(mesh_path, "components"));
      break;
    case 2:
      CGAL::MPM::validate_labeled_mesh(CGAL::MPM::read_labeled_mesh(mesh_path, "property:label"));
      break;
    default:
    {
      const CGAL::MPM::Mesh_file f = CGAL::MPM::read_mesh_file(mesh_path);
      (void)CGAL::MPM::connected_component_labels(f.mesh);
      break;
    }
    }
  });
  return 0;
}
