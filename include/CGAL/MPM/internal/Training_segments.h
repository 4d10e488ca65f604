// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_TRAINING_SEGMENTS_H
#define CGAL_MPM_INTERNAL_TRAINING_SEGMENTS_H

// The segments of labelled training meshes, as learning
// (learning.cpp) and the correspondence of same-type segments
// (training_correspondence.cpp) both take them apart.

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/internal/Message_text.h>

#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// How messages name a segment: its label, and its type when known.
inline std::string label_element(int label, const std::string& type)
{
  return "label " + std::to_string(label) + (type.empty() ? "" : " (type " + quoted(type) + ")");
}

// Local numbering by first appearance in the part's faces (the known
// correspondence convention): the mesh vertex of each local vertex and the
// local triangles. `local_of` is scratch space of the mesh's size, all -1.
void local_part(const Indexed_mesh& mesh, const std::vector<int>& faces, std::vector<int>& local_of,
                std::vector<int>& vertices, std::vector<Triangle>& triangles);

// The faces of each label.
std::map<int, std::vector<int>> faces_by_label(const Labeled_mesh& lm);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
