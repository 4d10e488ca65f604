// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace CGAL {
namespace MPM {

Shape_grammar::Shape_grammar(const Morphable_part_model& model)
{
  for(std::size_t t = 0; t < model.types.size(); ++t)
  {
    for(std::size_t s = 0; s < model.types[t].sites.size(); ++s)
      boost::add_vertex(Site_ref{static_cast<int>(t), static_cast<int>(s)}, graph_);
    first_vertex_.push_back(boost::num_vertices(graph_));
  }
  for(std::size_t r = 0; r < model.rules.size(); ++r)
  {
    const Docking_rule& rule = model.rules[r];
    rule_sites_.emplace_back(rule.first, rule.second);
    boost::add_edge(vertex(rule.first), vertex(rule.second), static_cast<int>(r), graph_);
  }
}

bool Shape_grammar::has_site(const Site_ref& site) const
{
  return site.type >= 0 && std::size_t(site.type) + 1 < first_vertex_.size() && site.site >= 0 &&
         first_vertex_[site.type] + site.site < first_vertex_[site.type + 1];
}

Shape_grammar::vertex_descriptor Shape_grammar::vertex(const Site_ref& site) const
{
  if(!has_site(site))
    throw std::out_of_range("no docking site " + std::to_string(site.site) + " of part type " +
                            std::to_string(site.type) + " in the grammar");
  return first_vertex_[site.type] + site.site;
}

std::vector<int> Shape_grammar::rules_between(const Site_ref& a, const Site_ref& b) const
{
  std::vector<int> rules;
  if(!has_site(a) || !has_site(b)) return rules;
  const vertex_descriptor vb = vertex(b);
  for(auto [e, end] = boost::out_edges(vertex(a), graph_); e != end; ++e)
    if(boost::target(*e, graph_) == vb) rules.push_back(graph_[*e]);
  // A rule docking a site to itself is an out-edge twice.
  std::sort(rules.begin(), rules.end());
  rules.erase(std::unique(rules.begin(), rules.end()), rules.end());
  return rules;
}

bool Shape_grammar::describes(const Morphable_part_model& model) const
{
  if(first_vertex_.size() != model.types.size() + 1 || rule_sites_.size() != model.rules.size()) return false;
  for(std::size_t t = 0; t < model.types.size(); ++t)
    if(first_vertex_[t + 1] - first_vertex_[t] != model.types[t].sites.size()) return false;
  for(std::size_t r = 0; r < model.rules.size(); ++r)
    if(!(rule_sites_[r].first == model.rules[r].first && rule_sites_[r].second == model.rules[r].second)) return false;
  return true;
}

const Shape_grammar& Morphable_part_model::grammar() const
{
  static const Shape_grammar none;
  const Shape_grammar& g = grammar_ ? *grammar_ : none;
  if(!g.describes(*this))
    throw std::logic_error("the model's grammar is out of date: call update_grammar() after changing the part "
                           "types' sites or the rules");
  return g;
}

void Morphable_part_model::update_grammar() { grammar_ = std::make_shared<const Shape_grammar>(*this); }

} // namespace MPM
} // namespace CGAL
