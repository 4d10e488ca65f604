// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Handles that bend every limb about its attachment to the root: one per
// tip, turned about the attachment so that the tip keeps its distance to it
// and moves by the asked fraction of the diagonal; the root held away from
// its seams.
#include <CGAL/MPM/Editing/Limb_bending.h>
#include <CGAL/MPM/Input_error.h>

#include "Learned_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <set>

namespace {

using namespace CGAL::MPM;

TEST(Limb_bending, every_finger_tip_turns_about_the_palm_and_the_palm_is_held_away_from_its_seams)
{
  const Morphable_part_model& model = mpm_test::learned(Synthetic_family::hand, 3000).model;
  const Training_example& ex = model.examples.front();
  const Labeled_mesh labeled = to_labeled_mesh(ex);
  const Handle_set handles = limb_bending_handles(model, 0, 0.1);
  const double diagonal = mpm_test::diagonal(labeled.mesh.points);
  int root = 0;
  for(std::size_t i = 0; i < ex.graph.nodes.size(); ++i)
    if(ex.graph.nodes[i].vertices.size() > ex.graph.nodes[std::size_t(root)].vertices.size()) root = int(i);
  const std::set<int> palm(ex.graph.nodes[std::size_t(root)].vertices.begin(),
                           ex.graph.nodes[std::size_t(root)].vertices.end());
  int moved = 0;
  for(int k = 0; k < handles.size(); ++k)
  {
    const int v = handles.vertices[std::size_t(k)];
    const double move = (handles.targets.row(k) - labeled.mesh.points.row(v)).norm();
    if(palm.count(v) > 0)
      EXPECT_EQ(move, 0.) << "palm vertex " << v;
    else
    {
      ++moved;
      EXPECT_NEAR(move, 0.1 * diagonal, 1e-9 * diagonal) << "tip vertex " << v;
    }
  }
  EXPECT_EQ(moved, 5); // five fingers
  // The palm is held away from its seams, which stay free to turn.
  EXPECT_LT(handles.size(), 5 + int(palm.size()));
  EXPECT_GT(handles.size(), 5 + int(palm.size()) / 4);
  for(const Part_node& finger : ex.graph.nodes)
    for(int v : finger.vertices)
      if(palm.count(v) == 0) continue;
      else if(&finger != &ex.graph.nodes[std::size_t(root)])
        EXPECT_EQ(std::count(handles.vertices.begin(), handles.vertices.end(), v), 0) << "seam vertex " << v;
  EXPECT_THROW(limb_bending_handles(model, 1), Input_error);
  EXPECT_THROW(limb_bending_handles(model, 0, -0.1), Input_error);
  EXPECT_THROW(limb_bending_handles(model, 0, std::numeric_limits<double>::quiet_NaN()), Input_error);
}

} // namespace
