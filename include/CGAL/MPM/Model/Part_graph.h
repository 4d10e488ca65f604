// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_PART_GRAPH_H
#define CGAL_MPM_PART_GRAPH_H

#include <CGAL/MPM/Model/Docking_rule.h>
#include <CGAL/MPM/Model/Shape_space.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// An instance of a part type in a part graph.
struct Part_node
{
  int type = -1;                   ///< index of the part type
  int label = -1;                  ///< face label in the source mesh (-1 when assembled)
  std::vector<int> vertices;       ///< local vertex id -> vertex of the assembled mesh
  Eigen::VectorXd coordinates;     ///< shape coordinates in the type's space
  Rigid_motion motion;             ///< mean frame -> placement of this instance
};

/// \ingroup PkgMPMRef
/// A docking between two nodes by a rule. `first` plays the rule's side 0.
struct Part_edge
{
  int first = -1;  ///< node at the rule's `first` site
  int second = -1; ///< node at the rule's `second` site
  int rule = -1;   ///< index of the rule in the model
  Eigen::VectorXd coordinates; ///< shape coordinates of the pair geometry
  Rigid_motion motion;         ///< mean frame -> placement of the pair geometry
  /// This docking's own merged seam (a seam of a training mesh whose two
  /// parts were put in correspondence separately, so that each observation
  /// samples it differently); empty: the rule's `Docking_rule::merged_seam`
  /// or `Docking_rule::seam` applies.
  std::vector<Seam_vertex> merged_seam;
};

/// \ingroup PkgMPMRef
/// A part graph (an assembly): instances as nodes, dockings as edges.
/// `adjacency_graph()` gives it to Boost.Graph's algorithms.
struct Part_graph
{
  std::vector<Part_node> nodes; ///< instances
  std::vector<Part_edge> edges; ///< dockings
};

} // namespace MPM
} // namespace CGAL

#endif
