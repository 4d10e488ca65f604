// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_SHAPE_SPACE_FIT_H
#define CGAL_MPM_SHAPE_SPACE_FIT_H

#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <memory>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// The shape-space fit alone: the baseline that shows what the elastic
/// coupling of MPM adds. Each part instance of a training example is fitted,
/// independently of the others, to the handles that lie on it: a rigid
/// motion `R, t` and shape coordinates `lambda` minimize
///
///     sigma_sub^-2 sum_h |R (m_h + B_h lambda) + t - y_h|^2 + sum_k lambda_k^2 / (4 sigma_k^2)
///
/// where `m` is the instance's own rest shape and `B`, `sigma` the modes and
/// deviations of its type (the means exchanged as in
/// `make_deformation_problem()`, so handles at their rest positions give the
/// input back). Rotation and coordinates are alternated to convergence; a
/// part with one handle only translates, a part with two handles (or all on
/// a line) turns by the smallest rotation aligning them. Parts without
/// handles keep their rest shape; a vertex shared by several parts (a seam)
/// gets the mean of their positions; vertices in no part stay at rest.
class Shape_space_fit
{
public:
  /// Prepares example `example` of `model`. Throws `Input_error` when the
  /// example does not exist.
  explicit Shape_space_fit(const Morphable_part_model& model, int example = 0);
  ~Shape_space_fit();
  /// Movable, not copyable.
  Shape_space_fit(Shape_space_fit&&) noexcept;
  /// Movable, not copyable.
  Shape_space_fit& operator=(Shape_space_fit&&) noexcept;

  /// Sets the handles (see `validate_handles()`; an empty set is an error).
  void set_handles(const Handle_set& handles);

  /// The fitted positions (n x 3).
  Point_matrix deform() const;

  /// Number of alternation steps of the last `deform()`, summed over the parts.
  int iterations() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace MPM
} // namespace CGAL

#endif
