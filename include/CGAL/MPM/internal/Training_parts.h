// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_TRAINING_PARTS_H
#define CGAL_MPM_INTERNAL_TRAINING_PARTS_H

// The parts of training meshes and the dockings found between them
// (docking_discovery.cpp), from which learning (learning.cpp) makes the
// part types, docking sites and rules.

#include <CGAL/MPM/Model/Docking_rule.h>
#include <CGAL/MPM/Model/Part_type.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// One part of one training mesh.
struct Part_instance
{
  int example = 0;
  int label = 0;
  int type = 0;
  int instance = 0;           // index among the instances of its type
  std::vector<int> vertices;  // local -> mesh vertex
};

// One docking found in a training mesh, between parts `a` and `b`.
struct Observation
{
  int example = 0;
  int a = 0, b = 0;
  Docking_kind kind = Docking_kind::boundary;
  std::vector<int> site_a, site_b;          // sorted local ids
  std::vector<std::pair<int, int>> seam;    // (local in a, local in b), sorted
  std::vector<Seam_vertex> merged;          // a stitched seam: side 0 is a
  Site_ref ref_a, ref_b;
};

// Boundary dockings: parts whose faces share an edge. Generalized dockings:
// parts of different connected components within the docking radius.
// With `corresponded`, a part rebuilt by dense correspondence (detached
// from the neighbours it shared seams with) docks only to those.
std::vector<Observation> find_dockings(const std::vector<Training_input>& inputs,
                                       const std::vector<Part_instance>& parts, double radius,
                                       const Corresponded_training* corresponded,
                                       const std::vector<Training_input>* originals);

// A boundary site is the exact seam; generalized sites of different
// observations are the same site when they mostly overlap (Jaccard >= 1/2),
// since their extent varies with the shape.
int find_or_add_site(Part_type& type, Docking_kind kind, const std::vector<int>& vertices);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
