// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_MODEL_PARAMETERS_H
#define CGAL_MPM_MODEL_PARAMETERS_H

#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Parameters of a morphable part model. A negative length means "choose
/// automatically" as documented per field.
struct Model_parameters
{
  /// Flexibility outside the learned subspace, in units of the model's
  /// length: deviations of edge vectors from the subspace are weighted by
  /// sigma_sub^-2. Negative: half the median, over part types with modes,
  /// of the per-vertex standard deviation of the strongest mode
  /// (sigma_1 / sqrt(vertices)), so that leaving the subspace costs more than
  /// moving within it at any mesh resolution; 0.2% of the bounding-box
  /// diagonal when no type varies.
  double sigma_sub = -1.;
  /// Width of the blending region at part borders. Negative: a third of
  /// each cluster's diameter.
  double sigma_bound = -1.;
  /// Influence radius r of a docking: pair geometry is everything within r of
  /// the seam (boundary docking) or of the other part (generalized docking).
  /// Negative: 5% of the bounding-box diagonal of the first example.
  double docking_radius = -1.;
  /// Number of modes kept per shape space; 0 chooses by `explained_variance`.
  int modes = 0;
  /// Fraction of the variance the kept modes must explain when `modes` is 0.
  double explained_variance = 0.99;
};

/// \ingroup PkgMPMRef
/// What the user says about a labelled mesh: which labels are parts of which
/// type, optional landmark vertices, and the model parameters. Read from the
/// JSON annotation format documented in `doc/MPM/File_formats.md`.
struct Annotation
{
  /// Part type name of each face label. Labels not listed are an error when
  /// the map is non-empty; an empty map groups parts by identical connectivity.
  std::map<int, std::string> part_type_of_label;
  /// Per-type override of the number of modes (0 or absent: use `parameters`).
  std::map<std::string, int> modes_of_type;
  /// Landmark vertex ids (indices into the mesh) per label, in corresponding
  /// order across the instances of a type.
  std::map<int, std::vector<int>> landmarks_of_label;
  /// Model parameters.
  Model_parameters parameters;
  /// File the annotation was read from (for error messages), may be empty.
  std::string source;
};

} // namespace MPM
} // namespace CGAL

#endif
