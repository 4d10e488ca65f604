// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_MORPHABLE_PART_MODEL_H
#define CGAL_MPM_MORPHABLE_PART_MODEL_H

#include <CGAL/MPM/Model/Docking_rule.h>
#include <CGAL/MPM/Model/Model_parameters.h>
#include <CGAL/MPM/Model/Part_graph.h>
#include <CGAL/MPM/Model/Part_type.h>
#include <CGAL/MPM/Model/Training_example.h>

#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

class Shape_grammar;

/// \ingroup PkgMPMRef
/// A learned morphable part model: part types with their shape spaces,
/// docking rules with the shape spaces of their pair geometry (together the
/// grammar, see `Shape_grammar`), and the training examples as part graphs.
/// Learning and reading a model build its grammar; code that changes the
/// sites of `types` or the `rules` calls `update_grammar()` after.
struct Morphable_part_model
{
  /// The parameters, with `sigma_sub` and `docking_radius` resolved; a
  /// negative `sigma_bound` stays automatic (resolved per cluster when solving).
  Model_parameters parameters;
  std::vector<Part_type> types;     ///< part types
  std::vector<Docking_rule> rules;  ///< observed docking rules
  std::vector<Training_example> examples; ///< the training meshes

  /// Index of the type called `name`, or -1.
  int find_type(const std::string& name) const
  {
    for(std::size_t i = 0; i < types.size(); ++i)
      if(types[i].name == name) return static_cast<int>(i);
    return -1;
  }

  /// The grammar of `types`' sites and `rules`, built once by
  /// `update_grammar()` (copies of the model share it). Throws
  /// `std::logic_error` when sites or rules changed since.
  const Shape_grammar& grammar() const;
  /// Builds `grammar()` from the current sites and rules.
  void update_grammar();

private:
  // Shared and immutable, so that copying a model copies no graph; a
  // pointer, so that this header does not pull in Boost.Graph.
  std::shared_ptr<const Shape_grammar> grammar_;
};

} // namespace MPM
} // namespace CGAL

#endif
