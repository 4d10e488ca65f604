// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_SEGMENTATION_MEASURES_H
#define CGAL_MPM_SEGMENTATION_MEASURES_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Hamming distance between a segmentation and a reference (Chen et al.
/// 2009, section 4.2), as fractions of the surface area.
struct Hamming_distance
{
  double missing = 0.;     ///< Rm: area of reference segments outside their best-matching segment
  double false_alarm = 0.; ///< Rf: area of segments outside their best-matching reference segment
  double average = 0.;     ///< (Rm + Rf) / 2, the benchmark's "Hamming distance"
};

/// \ingroup PkgMPMRef
/// Global and local consistency error (Chen et al. 2009, section 4.4, after
/// Martin et al. 2001), area weighted; both are 0 when one segmentation
/// refines the other.
struct Consistency_error
{
  double global = 0.; ///< GCE
  double local = 0.;  ///< LCE
};

/// \ingroup PkgMPMRef
/// All four measures of the Princeton Segmentation Benchmark for one pair of segmentations.
struct Segmentation_comparison
{
  double cut_discrepancy = 0.;  ///< see `cut_discrepancy()`
  Hamming_distance hamming;     ///< see `hamming_distance()`
  double rand_index_error = 0.; ///< see `rand_index_error()`
  Consistency_error consistency; ///< see `consistency_error()`
};

/// \ingroup PkgMPMRef
/// Cut Discrepancy: the mean geodesic distance from points on the cuts of
/// `labels` (edges between faces of different labels) to the nearest cut of
/// `reference`, plus the same the other way, divided by the mean Euclidean
/// distance from the surface to its centroid (the benchmark's normalisation).
/// Geodesic distance is approximated by shortest paths along mesh edges from
/// the cut vertices; a cut is sampled at its vertices, each weighted by half
/// the length of its cut edges. Symmetric; 0 when the cuts coincide. When
/// exactly one segmentation has no cut the measure is undefined: NaN.
/// Throws `Input_error` when a label vector has not one entry per face.
double cut_discrepancy(const Indexed_mesh& mesh, const std::vector<int>& labels,
                       const std::vector<int>& reference);

/// \ingroup PkgMPMRef
/// Hamming distance of `labels` against the ground truth `reference`, face
/// area weighted: each reference segment is matched to the segment of
/// `labels` that covers most of it, and Rm is the area it leaves out; Rf is
/// the same with the roles swapped.
Hamming_distance hamming_distance(const Indexed_mesh& mesh, const std::vector<int>& labels,
                                  const std::vector<int>& reference);

/// \ingroup PkgMPMRef
/// 1 - Rand Index, face area weighted: the area-weighted fraction of pairs
/// of distinct faces that one segmentation puts in one segment and the other
/// does not (the benchmark reports this "Rand Index error"). Symmetric.
double rand_index_error(const Indexed_mesh& mesh, const std::vector<int>& labels,
                        const std::vector<int>& reference);

/// \ingroup PkgMPMRef
/// GCE and LCE, face area weighted. Symmetric.
Consistency_error consistency_error(const Indexed_mesh& mesh, const std::vector<int>& labels,
                                    const std::vector<int>& reference);

/// \ingroup PkgMPMRef
/// One cut of a segmentation: a connected set of edges between faces of the
/// same two labels.
struct Segmentation_cut
{
  int first_label = 0;       ///< the smaller of the two labels
  int second_label = 0;      ///< the larger one
  std::vector<int> vertices; ///< its vertices, in increasing order
  int edges = 0;             ///< its edges: as many as vertices for a closed loop, one fewer for an open stretch
};

/// \ingroup PkgMPMRef
/// The cuts of a segmentation (a seam loop around a limb, or one stretch of
/// the border between two parts where a part touches several others), ordered
/// by label pair. Throws `Input_error` when `labels` has not one entry per face.
std::vector<Segmentation_cut> segmentation_cuts(const Indexed_mesh& mesh, const std::vector<int>& labels);

/// \ingroup PkgMPMRef
/// The cuts of `cuts` (`segmentation_cuts()`) a user would click as joints:
/// the closed seam loops, and, where a part's seam runs along several
/// neighbours (a phalanx touching the next finger, a ring pinched where an
/// arm leaves the body), the longest open stretch of at least one of its
/// two parts; the short stretches between touching neighbours are no joints.
/// In the order of `cuts`.
std::vector<Segmentation_cut> joint_cuts(const std::vector<Segmentation_cut>& cuts);

/// \ingroup PkgMPMRef
/// The vertex of `cut` (a vertex set, such as `Segmentation_cut::vertices`) nearest
/// its centroid: where a user would click to name that cut. `cut` must not be empty.
int central_cut_vertex(const Indexed_mesh& mesh, const std::vector<int>& cut);

/// \ingroup PkgMPMRef
/// Mean Euclidean distance from the vertices of `path` to the nearest vertex
/// of `cut`: how far a found cut lies from a known one. Both must not be empty.
double cut_distance(const Indexed_mesh& mesh, const std::vector<int>& path, const std::vector<int>& cut);

/// \ingroup PkgMPMRef
/// The four measures at once, `reference` taken as the ground truth.
Segmentation_comparison compare_segmentations(const Indexed_mesh& mesh, const std::vector<int>& labels,
                                              const std::vector<int>& reference);

} // namespace MPM
} // namespace CGAL

#endif
