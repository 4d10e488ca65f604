// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Model/Shape_grammar.h>

namespace CGAL {
namespace MPM {

Shape_grammar::Shape_grammar(const Morphable_part_model& model)
{
  for(std::size_t t = 0; t < model.types.size(); ++t)
    for(std::size_t s = 0; s < model.types[t].sites.size(); ++s)
    {
      const Site_ref site{static_cast<int>(t), static_cast<int>(s)};
      vertex_of_site_[site] = boost::add_vertex(site, graph_);
    }
  for(std::size_t r = 0; r < model.rules.size(); ++r)
    boost::add_edge(vertex(model.rules[r].first), vertex(model.rules[r].second), static_cast<int>(r), graph_);
}

std::vector<int> Shape_grammar::rules_between(const Site_ref& a, const Site_ref& b) const
{
  std::vector<int> rules;
  const auto ia = vertex_of_site_.find(a), ib = vertex_of_site_.find(b);
  if(ia == vertex_of_site_.end() || ib == vertex_of_site_.end()) return rules;
  for(auto [e, end] = boost::out_edges(ia->second, graph_); e != end; ++e)
    if(boost::target(*e, graph_) == ib->second) rules.push_back(graph_[*e]);
  return rules;
}

} // namespace MPM
} // namespace CGAL
