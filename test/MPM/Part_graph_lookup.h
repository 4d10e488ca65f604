// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Finding nodes and edges of a part graph in tests.
#ifndef MPM_TEST_PART_GRAPH_LOOKUP_H
#define MPM_TEST_PART_GRAPH_LOOKUP_H

#include <CGAL/MPM/Model/Morphable_part_model.h>
#include <CGAL/MPM/Model/Part_graph.h>

#include <string>

namespace mpm_test {

// The node of part type `type`, after skipping `skip` of them; -1 if there is none.
inline int node_of_type(const CGAL::MPM::Morphable_part_model& m, const CGAL::MPM::Part_graph& g, const std::string& type,
                        int skip = 0)
{
  for(std::size_t i = 0; i < g.nodes.size(); ++i)
    if(m.types[g.nodes[i].type].name == type && skip-- == 0) return int(i);
  return -1;
}

// The edge joining nodes `a` and `b`, either way; -1 if there is none.
inline int edge_between(const CGAL::MPM::Part_graph& g, int a, int b)
{
  for(std::size_t k = 0; k < g.edges.size(); ++k)
    if((g.edges[k].first == a && g.edges[k].second == b) || (g.edges[k].first == b && g.edges[k].second == a))
      return int(k);
  return -1;
}

} // namespace mpm_test

#endif
