// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quality_segmentation (issue 20): one click per human cut. For each
// segmented mesh of a directory, clicks the vertex of each human cut nearest
// the cut's centroid, runs cut_at_vertices() and compares the result with the
// human segmentation: cuts found, distance of each found cut to its human
// cut, and the Princeton Segmentation Benchmark's four measures.
#include "quality_common.h"

#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Cutting/Joint_proposal.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Cutting/Segmentation_measures.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <algorithm>
#include <chrono>
#include <iomanip>

namespace {

using namespace CGAL::MPM;

void evaluate(const std::string& name, const std::string& base, double search_range, double snap_band, bool details)
{
  const Labeled_mesh human = read_labeled_mesh(base + ".off", base + ".seg");
  const Indexed_mesh& m = human.mesh;
  const std::vector<Segmentation_cut> cuts = joint_cuts(segmentation_cuts(m, human.face_labels));
  std::vector<int> clicks;
  for(const Segmentation_cut& cut : cuts) clicks.push_back(central_cut_vertex(m, cut.vertices));
  Joint_cutting_options options;
  options.skip_unfound = true;
  options.search_range = search_range;
  options.snap_band = snap_band;
  const auto start = std::chrono::steady_clock::now();
  const Joint_cutting_result result = cut_at_vertices(m, clicks, options, base + ".off");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const double diagonal = internal::bounding_box_diagonal(m.points);
  double sum = 0., worst = 0.;
  int within = 0;
  for(const Joint_cut& c : result.cuts) {
    const std::size_t i = std::size_t(std::find(clicks.begin(), clicks.end(), c.vertex) - clicks.begin());
    const double d = cut_distance(m, c.path, cuts[i].vertices) / diagonal;
    sum += d;
    worst = std::max(worst, d);
    within += d < 0.01;
    if(details)
      std::cerr << name << ": click " << c.vertex << " on the cut between labels " << cuts[i].first_label << " and "
                << cuts[i].second_label << ": " << std::fixed << std::setprecision(2) << 100. * d << "% of the diagonal\n";
  }
  const Segmentation_comparison s = compare_segmentations(m, result.mesh.face_labels, human.face_labels);
  const double mean = result.cuts.empty() ? 0. : sum / double(result.cuts.size());
  std::cout << "| " << name << " | " << result.cuts.size() << " / " << cuts.size() << " | " << within << " | "
            << std::fixed << std::setprecision(2) << 100. * mean << " | " << 100. * worst << " | "
            << std::setprecision(3) << s.rand_index_error << " | " << s.cut_discrepancy << " | " << s.hamming.average
            << " | " << s.hamming.missing << " | " << s.hamming.false_alarm << " | " << s.consistency.global << " | "
            << s.consistency.local << " | " << std::setprecision(1) << seconds << " |\n"
            << std::flush;
  for(const Skipped_click& k : result.skipped) std::cerr << name << ": " << k.reason << "\n";
}

// Joints proposed with no click: how many human cuts a proposed cut lies
// within 1% of the diagonal of, proposed cuts that match none, and the
// benchmark's measures.
void evaluate_proposal(const std::string& name, const std::string& base, double sensitivity, bool details)
{
  const Labeled_mesh human = read_labeled_mesh(base + ".off", base + ".seg");
  const Indexed_mesh& m = human.mesh;
  const std::vector<Segmentation_cut> cuts = joint_cuts(segmentation_cuts(m, human.face_labels));
  Joint_proposal_options options;
  options.sensitivity = sensitivity;
  const auto start = std::chrono::steady_clock::now();
  const Joint_proposal proposal = cut_at_proposed_joints(m, options, base + ".off");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double diagonal = internal::bounding_box_diagonal(m.points);
  std::vector<char> matched_cut(proposal.cutting.cuts.size(), 0);
  int matched_human = 0;
  for(const Segmentation_cut& h : cuts) {
    bool matched = false;
    for(std::size_t i = 0; i < proposal.cutting.cuts.size(); ++i)
      if(cut_distance(m, proposal.cutting.cuts[i].path, h.vertices) / diagonal < 0.01) {
        matched = true;
        matched_cut[i] = 1;
      }
    matched_human += matched;
  }
  const int extra = int(std::count(matched_cut.begin(), matched_cut.end(), 0));
  if(details)
    for(const Joint_cut& c : proposal.cutting.cuts) {
      const auto j = std::find_if(proposal.joints.begin(), proposal.joints.end(),
                                  [&](const Proposed_joint& p) { return p.vertex == c.vertex; });
      double nearest = 1e9;
      for(const Segmentation_cut& h : cuts) nearest = std::min(nearest, cut_distance(m, c.path, h.vertices) / diagonal);
      std::cerr << name << ": cut at vertex " << c.vertex << ", limb " << j->limb << (j->at_base ? " (base)" : "")
                << ", strength " << j->strength << ", nearest human cut " << 100. * nearest << "% of the diagonal\n";
    }
  const Segmentation_comparison s = compare_segmentations(m, proposal.cutting.mesh.face_labels, human.face_labels);
  std::cout << "| " << name << " | " << proposal.limbs << " | " << proposal.cutting.cuts.size() << " | "
            << matched_human << " / " << cuts.size() << " | " << extra << " | " << std::fixed << std::setprecision(3)
            << s.rand_index_error << " | " << s.cut_discrepancy << " | " << s.hamming.average << " | "
            << s.consistency.global << " | " << s.consistency.local << " | " << std::setprecision(1) << seconds
            << " |\n"
            << std::flush;
}

} // namespace

int main(int argc, char** argv)
{
  const mpm_quality::Options options(
    argc, argv, {{"data", "../shared/data/psb"}, {"meshes", ""}, {"search-range", "0.5"}, {"snap-band", "0.5"}, {"auto", ""}, {"details", ""}},
    "usage: quality_segmentation [--data DIR] [--meshes a,b,...] [--search-range R] [--snap-band B] [--auto SENSITIVITY [--details 1]]\n"
    "For every DIR/NAME.off with DIR/NAME.seg, clicks one vertex per human cut, cuts with\n"
    "cut_at_vertices() and prints a Markdown table against the human segmentation. With\n"
    "--auto, cuts at the joints cut_at_proposed_joints() proposes instead (--details 1: each\n"
    "proposed cut, its limb and strength and its distance to the nearest human cut, on stderr;\n"
    "without --auto, each click's cut and its distance to its human cut).\n");
  const std::vector<std::string> names = options.meshes();
  if(!options.text("auto").empty()) {
    std::cout << "| mesh | limbs | cuts | human cuts matched within 1% | cuts matching none | Rand Index error | "
                 "Cut Discrepancy | Hamming | GCE | LCE | seconds |\n"
                 "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for(const std::string& name : names) {
      try {
        evaluate_proposal(name, options.text("data") + "/" + name, std::atof(options.text("auto").c_str()),
                          !options.text("details").empty());
      } catch(const std::exception& error) {
        std::cout << "| " << name << " | failed: " << error.what() << " |\n" << std::flush;
      }
    }
    return 0;
  }
  std::cout << "| mesh | cuts found / human | within 1% | mean distance, % diagonal | worst, % | Rand Index error | "
               "Cut Discrepancy | Hamming | Rm | Rf | GCE | LCE | seconds |\n"
               "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  const double search_range = std::atof(options.text("search-range").c_str());
  for(const std::string& name : names) {
    try {
      evaluate(name, options.text("data") + "/" + name, search_range, std::atof(options.text("snap-band").c_str()),
               !options.text("details").empty());
    } catch(const std::exception& error) {
      std::cout << "| " << name << " | failed: " << error.what() << " |\n" << std::flush;
    }
  }
  return 0;
}
