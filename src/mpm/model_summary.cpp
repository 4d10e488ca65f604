// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The description of a model shared by `mpm info` and `mpm learn`: built once
// as JSON, rendered as tables from that JSON so both forms always agree.
#include "cli.h"

#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace mpm {

namespace {

using json = Json;
using CGAL::MPM::Docking_kind;

const char* kind_name(Docking_kind k) { return k == Docking_kind::boundary ? "boundary" : "generalized"; }

// Number of cumulative explained-variance fractions reported per space.
constexpr int reported_fractions = 5;

json space_summary(const CGAL::MPM::Shape_space& space)
{
  json cumulative = json::array();
  const int available = static_cast<int>(space.variances.size());
  for(int k = 1; k <= std::min(available, reported_fractions); ++k) cumulative.push_back(space.explained_variance(k));
  double max_residual = 0.;
  for(double r : space.instance_residuals) max_residual = std::max(max_residual, r);
  return {{"modes", space.number_of_modes()},
          {"explained_variance", space.explained_variance(space.number_of_modes())},
          {"cumulative_variance", cumulative},
          {"sigmas", std::vector<double>(space.sigmas.data(), space.sigmas.data() + space.sigmas.size())},
          {"max_residual", max_residual}};
}

json site_ref(const CGAL::MPM::Morphable_part_model& model, const CGAL::MPM::Site_ref& s)
{
  const bool valid = s.type >= 0 && s.type < static_cast<int>(model.types.size());
  return {{"type", valid ? model.types[s.type].name : std::string("?")}, {"type_index", s.type}, {"site", s.site}};
}

std::string site_label(const json& ref)
{
  return ref["type"].get<std::string>() + ":" + std::to_string(ref["site"].get<int>());
}

// A fraction in [0, 1] with three decimals.
std::string fraction(double f)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", f);
  return buffer;
}

std::string join_numbers(const json& values, std::size_t at_most, bool fractions)
{
  if(values.empty()) return "-";
  std::string r;
  for(std::size_t i = 0; i < values.size() && i < at_most; ++i)
    r += (i ? " " : "") + (fractions ? fraction(values[i].get<double>()) : format_number(values[i].get<double>(), 3));
  if(values.size() > at_most) r += " ...";
  return r;
}

std::string number(const json& v)
{
  if(v.is_number_integer()) return std::to_string(v.get<long long>());
  if(v.is_number()) return format_number(v.get<double>());
  return v.dump();
}

} // namespace

Json model_summary(const CGAL::MPM::Morphable_part_model& model, const std::string& path)
{
  const auto& p = model.parameters;
  std::vector<int> instances_of_type(model.types.size(), 0), observations_of_rule(model.rules.size(), 0);
  std::vector<std::vector<int>> rules_at_site(model.types.size());
  for(std::size_t t = 0; t < model.types.size(); ++t) rules_at_site[t].assign(model.types[t].sites.size(), 0);

  json examples = json::array();
  for(const auto& e : model.examples)
  {
    for(const auto& n : e.graph.nodes)
      if(n.type >= 0 && n.type < static_cast<int>(model.types.size())) ++instances_of_type[n.type];
    for(const auto& d : e.graph.edges)
      if(d.rule >= 0 && d.rule < static_cast<int>(model.rules.size())) ++observations_of_rule[d.rule];
    examples.push_back({{"name", e.name},
                        {"vertices", e.mesh.number_of_vertices()},
                        {"faces", e.mesh.number_of_faces()},
                        {"parts", e.graph.nodes.size()},
                        {"dockings", e.graph.edges.size()}});
  }

  json rules = json::array();
  for(std::size_t r = 0; r < model.rules.size(); ++r)
  {
    const auto& rule = model.rules[r];
    for(const auto* s : {&rule.first, &rule.second})
      if(s->type >= 0 && s->type < static_cast<int>(rules_at_site.size()) && s->site >= 0 &&
         s->site < static_cast<int>(rules_at_site[s->type].size()))
        ++rules_at_site[s->type][s->site];
    json j = {{"index", r},
              {"first", site_ref(model, rule.first)},
              {"second", site_ref(model, rule.second)},
              {"kind", kind_name(rule.kind)},
              {"seam", rule.seam.size()},
              {"pair_points", rule.points.size()},
              {"observations", observations_of_rule[r]}};
    j.update(space_summary(rule.space));
    rules.push_back(j);
  }

  json types = json::array();
  int total_instances = 0, total_sites = 0, total_modes = 0;
  for(std::size_t t = 0; t < model.types.size(); ++t)
  {
    const auto& type = model.types[t];
    json sites = json::array();
    for(std::size_t s = 0; s < type.sites.size(); ++s)
      sites.push_back({{"index", s},
                       {"kind", kind_name(type.sites[s].kind)},
                       {"vertices", type.sites[s].vertices.size()},
                       {"rules", rules_at_site[t][s]}});
    json j = {{"index", t},
              {"name", type.name},
              {"instances", instances_of_type[t]},
              {"vertices", type.number_of_vertices},
              {"triangles", type.triangles.size()},
              {"edges", type.edges.size()}};
    j.update(space_summary(type.space));
    j["sites"] = sites;
    types.push_back(j);
    total_instances += instances_of_type[t];
    total_sites += static_cast<int>(type.sites.size());
    total_modes += type.space.number_of_modes();
  }
  for(const auto& rule : model.rules) total_modes += rule.space.number_of_modes();

  return {{"model", path},
          {"format_version", CGAL::MPM::model_file_version},
          {"parameters",
           {{"sigma_sub", p.sigma_sub},
            {"sigma_bound", p.sigma_bound},
            {"docking_radius", p.docking_radius},
            {"modes", p.modes},
            {"explained_variance", p.explained_variance}}},
          {"totals",
           {{"types", model.types.size()},
            {"instances", total_instances},
            {"sites", total_sites},
            {"rules", model.rules.size()},
            {"modes", total_modes},
            {"examples", model.examples.size()}}},
          {"types", types},
          {"rules", rules},
          {"examples", examples}};
}

void print_model_summary(std::ostream& out, const Json& s)
{
  const json& totals = s["totals"];
  auto count = [&](const char* key, const std::string& noun) {
    const long long n = totals[key].get<long long>();
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
  };
  out << "Model " << s["model"].get<std::string>() << ": " << count("types", "part type") << ", "
      << count("instances", "instance") << ", " << count("sites", "docking site") << ", " << count("rules", "rule")
      << ", " << count("modes", "mode") << ", " << count("examples", "example") << "\n";

  const json& p = s["parameters"];
  auto length = [](const json& v, const char* automatic) {
    return v.get<double>() < 0 ? std::string(automatic) : format_number(v.get<double>());
  };
  out << "\nParameters\n"
      << "  sigma_sub           " << length(p["sigma_sub"], "auto (2% of the bounding-box diagonal)") << "\n"
      << "  sigma_bound         " << length(p["sigma_bound"], "auto (a third of each cluster's diameter)") << "\n"
      << "  docking_radius      " << length(p["docking_radius"], "auto (5% of the bounding-box diagonal)") << "\n"
      << "  modes               "
      << (p["modes"].get<int>() == 0 ? std::string("by explained variance") : number(p["modes"])) << "\n"
      << "  explained_variance  " << number(p["explained_variance"]) << "\n";

  out << "\nPart types\n";
  Table types({"#", "name", "instances", "vertices", "modes", "explained", "cumulative", "sigmas", "max residual"},
              {true, false, true, true, true, true, false, false, true});
  for(const json& t : s["types"])
    types.add_row({number(t["index"]), t["name"], number(t["instances"]), number(t["vertices"]), number(t["modes"]),
                   fraction(t["explained_variance"].get<double>()),
                   join_numbers(t["cumulative_variance"], reported_fractions, true),
                   join_numbers(t["sigmas"], 4, false), format_number(t["max_residual"].get<double>(), 3)});
  types.print(out);

  out << "\nDocking sites\n";
  Table sites({"type", "site", "kind", "vertices", "rules"}, {false, true, false, true, true});
  for(const json& t : s["types"])
    for(const json& site : t["sites"])
      sites.add_row({t["name"], number(site["index"]), site["kind"], number(site["vertices"]), number(site["rules"])});
  if(sites.empty()) out << "  (none)\n";
  else sites.print(out);

  out << "\nRules\n";
  Table rules({"#", "site a", "", "site b", "kind", "seam", "pair points", "modes", "explained", "observed"},
              {true, false, false, false, false, true, true, true, true, true});
  for(const json& r : s["rules"])
    rules.add_row({number(r["index"]), site_label(r["first"]), "<->", site_label(r["second"]), r["kind"],
                   number(r["seam"]), number(r["pair_points"]), number(r["modes"]),
                   fraction(r["explained_variance"].get<double>()), number(r["observations"])});
  if(rules.empty()) out << "  (none)\n";
  else rules.print(out);

  out << "\nExamples\n";
  Table examples({"name", "vertices", "faces", "parts", "dockings"}, {false, true, true, true, true});
  for(const json& e : s["examples"])
    examples.add_row({e["name"], number(e["vertices"]), number(e["faces"]), number(e["parts"]), number(e["dockings"])});
  examples.print(out);
}

} // namespace mpm
