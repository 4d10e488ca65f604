// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_PART_GRAPH_IO_H
#define CGAL_MPM_PART_GRAPH_IO_H

#include <CGAL/MPM/Model/Morphable_part_model.h>
#include <CGAL/MPM/Model/Part_graph.h>

#include <map>
#include <string>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// How many dockings a docking site carries at most on one node: the
/// largest number observed on one training instance (1 for every site of the
/// synthetic families; at least 1 for a site that only a derived rule uses).
std::map<Site_ref, int> observed_site_degrees(const Morphable_part_model& model);

/// \ingroup PkgMPMRef
/// Checks `graph` against the grammar of `model` and throws `Input_error`
/// (source `source`, element `node N` or `edge N`) at the first problem: an
/// empty graph, an unknown part type, shape coordinates of the wrong length
/// or not finite, a node index out of range, a node docked to itself, a
/// rule index out of range, a docking that is not a rule (the nodes' types
/// are not the rule's site types), a docking site used on one node more
/// often than its observed degree, a cycle of boundary dockings whose seams
/// do not meet (they would identify two local vertices of one node: a tile
/// inserted into a grid), a graph in several pieces.
void validate_part_graph(const Morphable_part_model& model, const Part_graph& graph,
                         const std::string& source = "part graph");

/// \ingroup PkgMPMRef
/// The part graph of training example `example`: its instances with their
/// learned coordinates and its dockings (with the pair coordinates), as
/// learned. Throws `Input_error` for an index out of range.
Part_graph part_graph_of_example(const Morphable_part_model& model, int example = 0);

/// \ingroup PkgMPMRef
/// Parses a part graph in the JSON format `cgal-mpm-part-graph` version 1
/// (doc/MPM/Part_graphs.md) and validates it against `model`. Edges name a
/// rule by index (`"rule"`) or by the two docking sites (`"first_site"`,
/// `"second_site"`, resolved through `Shape_grammar::rules_between`; an
/// ambiguous or impossible pair is an error); node coordinates default to
/// the type's mean (zeros). Errors are `Input_error`s naming `source` and
/// the node or edge.
Part_graph parse_part_graph(const std::string& text, const Morphable_part_model& model,
                            const std::string& source = "part graph");

/// \ingroup PkgMPMRef
/// Reads and validates a part graph file (see `parse_part_graph()`).
Part_graph read_part_graph(const std::string& path, const Morphable_part_model& model);

/// \ingroup PkgMPMRef
/// The JSON text of `graph` (type names, coordinates, rule indices and, for
/// readability, the sites they dock). `parse_part_graph()` reads it back.
std::string part_graph_to_json(const Morphable_part_model& model, const Part_graph& graph);

/// \ingroup PkgMPMRef
/// Writes `part_graph_to_json()` to `path` atomically.
void write_part_graph(const Morphable_part_model& model, const Part_graph& graph, const std::string& path);

} // namespace MPM
} // namespace CGAL

#endif
