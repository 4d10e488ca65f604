// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_PART_TYPE_H
#define CGAL_MPM_PART_TYPE_H

#include <CGAL/MPM/Model/Docking_site.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Shape_space.h>

#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// An edge of a cluster's connectivity, between two of its points. Virtual
/// edges are not mesh edges: they tie a generalized docking together or a
/// disconnected part (a polygon soup) to its central element; they get
/// uniform weights.
struct Cluster_edge
{
  int source = 0;          ///< first point (index in the cluster)
  int target = 0;          ///< second point
  bool is_virtual = false; ///< not an edge of the mesh
};

/// \ingroup PkgMPMRef
/// A part type: the common connectivity of its instances (local vertex
/// numbering shared by all of them), its docking sites and its shape space.
struct Part_type
{
  std::string name;                 ///< user-facing name (from the annotation)
  int number_of_vertices = 0;       ///< local vertices of one instance
  std::vector<Triangle> triangles;  ///< local triangles (same for every instance)
  std::vector<Cluster_edge> edges;  ///< mesh edges plus virtual edges, source < target
  std::vector<Docking_site> sites;  ///< docking sites, indexed by `Site_ref::site`
  Shape_space space;                ///< learned shape space of the instances
};

} // namespace MPM
} // namespace CGAL

#endif
