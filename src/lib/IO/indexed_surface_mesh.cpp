// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

namespace CGAL {
namespace MPM {
namespace internal {

Indexed_surface_mesh to_surface_mesh(const Indexed_mesh& mesh, const std::string& source, const std::string& user)
{
  return to_surface_mesh_of<Indexed_surface_mesh::Point>(mesh, source, user);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
