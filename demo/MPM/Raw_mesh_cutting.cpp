// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Raw_mesh_cutting.h"

#include <CGAL/MPM/Cutting/Joint_proposal.h>
#include <CGAL/MPM/Cutting/Segmentation_measures.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>

#include <limits>

namespace mpm_demo {

namespace MPM = CGAL::MPM;

Raw_mesh_cutting::Raw_mesh_cutting(const std::string& path)
  : path_(path), mesh_(MPM::read_mesh_file(path).mesh), labels_(mesh_.triangles.size(), 0)
{
}

Raw_mesh_cutting::~Raw_mesh_cutting() = default;

const MPM::Joint_cutter& Raw_mesh_cutting::cutter()
{
  if(!cutter_) cutter_ = std::make_unique<MPM::Joint_cutter>(mesh_, MPM::Joint_cutting_options(), path_);
  return *cutter_;
}

void Raw_mesh_cutting::recut(const std::vector<int>& clicks)
{
  MPM::Joint_cutting_result result = cutter().cut(clicks);
  replace_cuts(std::move(result.mesh.face_labels), std::move(result.cuts));
}

void Raw_mesh_cutting::replace_cuts(std::vector<int>&& labels, std::vector<MPM::Joint_cut>&& cuts)
{
  labels_ = std::move(labels);
  cuts_ = std::move(cuts);
  // Types and their corrections belong to the segmentation they were made for.
  types_.reset();
  corrections_.clear();
}

const MPM::Joint_cut& Raw_mesh_cutting::add_cut(int vertex)
{
  std::vector<int> clicks;
  for(const MPM::Joint_cut& c : cuts_) clicks.push_back(c.vertex);
  clicks.push_back(vertex);
  recut(clicks);
  return cuts_.back();
}

int Raw_mesh_cutting::remove_cut_near(int vertex)
{
  if(cuts_.empty()) return -1;
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < cuts_.size(); ++i) {
    const double d = MPM::cut_distance(mesh_, {vertex}, cuts_[i].path);
    if(d < best) {
      best = d;
      nearest = i;
    }
  }
  const int removed = cuts_[nearest].vertex;
  std::vector<int> clicks;
  for(std::size_t i = 0; i < cuts_.size(); ++i)
    if(i != nearest) clicks.push_back(cuts_[i].vertex);
  if(clicks.empty())
    replace_cuts(std::vector<int>(mesh_.triangles.size(), 0), {});
  else
    recut(clicks);
  return removed;
}

int Raw_mesh_cutting::propose(double sensitivity)
{
  MPM::Joint_proposal_options options;
  options.sensitivity = sensitivity;
  MPM::Joint_proposal proposal = MPM::cut_at_proposed_joints(mesh_, options, path_);
  replace_cuts(std::move(proposal.cutting.mesh.face_labels), std::move(proposal.cutting.cuts));
  return proposal.limbs;
}

const MPM::Part_type_proposal& Raw_mesh_cutting::part_types()
{
  if(!types_) types_ = std::make_unique<MPM::Part_type_proposal>(MPM::propose_part_types(labeled_mesh()));
  for(const auto& [label, type] : corrections_) types_->annotation.part_type_of_label[label] = type;
  for(MPM::Segment_proposal& s : types_->segments) {
    const auto c = corrections_.find(s.label);
    if(c != corrections_.end()) s.type = c->second;
  }
  return *types_;
}

void Raw_mesh_cutting::set_part_type(int label, const std::string& type)
{
  if(std::find(labels_.begin(), labels_.end(), label) == labels_.end())
    throw MPM::Input_error(path_, "label " + std::to_string(label), "is no segment of the cut mesh");
  if(type.empty()) throw MPM::Input_error(path_, "label " + std::to_string(label), "needs a non-empty type name");
  corrections_[label] = type;
}

MPM::Labeled_mesh Raw_mesh_cutting::labeled_mesh() const { return {mesh_, labels_, path_}; }

} // namespace mpm_demo
