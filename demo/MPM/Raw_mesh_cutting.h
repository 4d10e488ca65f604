// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The demo's start from a mesh nobody has segmented: cuts added one click
// per joint or proposed all at once, the part types proposed from the
// resulting segmentation with the user's corrections, ready to learn.
#ifndef MPM_DEMO_RAW_MESH_CUTTING_H
#define MPM_DEMO_RAW_MESH_CUTTING_H

#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mpm_demo {

class Raw_mesh_cutting
{
public:
  /// Reads the mesh; throws `Input_error` naming the file.
  explicit Raw_mesh_cutting(const std::string& path);
  ~Raw_mesh_cutting();

  const std::string& path() const { return path_; }
  const CGAL::MPM::Indexed_mesh& mesh() const { return mesh_; }
  /// One label per face: the regions the cuts separate (all 0 before any cut).
  const std::vector<int>& labels() const { return labels_; }
  const std::vector<CGAL::MPM::Joint_cut>& cuts() const { return cuts_; }

  /// Adds the cut around the limb at `vertex`. Throws `Input_error` naming
  /// the vertex (on the body, a joint already cut, ...) and keeps the cuts.
  const CGAL::MPM::Joint_cut& add_cut(int vertex);
  /// Removes the cut passing nearest to `vertex`; returns the vertex it was
  /// clicked at, or -1 when there is no cut.
  int remove_cut_near(int vertex);
  /// Replaces the cuts with the joints `cut_at_proposed_joints()` proposes;
  /// returns the number of limbs found.
  int propose(double sensitivity);

  /// The part types proposed for the current segmentation, with the user's
  /// corrections (`set_part_type()`) applied to its annotation.
  const CGAL::MPM::Part_type_proposal& part_types();
  /// Gives the segment `label` the type `type` (kept until the cuts change).
  void set_part_type(int label, const std::string& type);
  CGAL::MPM::Labeled_mesh labeled_mesh() const;

private:
  void recut(const std::vector<int>& clicks);
  void replace_cuts(std::vector<int>&& labels, std::vector<CGAL::MPM::Joint_cut>&& cuts);
  const CGAL::MPM::Joint_cutter& cutter();

  std::string path_;
  CGAL::MPM::Indexed_mesh mesh_;
  std::unique_ptr<CGAL::MPM::Joint_cutter> cutter_; // built at the first click: the skeleton takes a second
  std::vector<int> labels_;
  std::vector<CGAL::MPM::Joint_cut> cuts_;
  std::unique_ptr<CGAL::MPM::Part_type_proposal> types_; // proposed when first asked after the cuts changed
  std::map<int, std::string> corrections_;
};

} // namespace mpm_demo

#endif
