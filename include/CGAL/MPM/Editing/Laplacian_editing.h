// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_LAPLACIAN_EDITING_H
#define CGAL_MPM_LAPLACIAN_EDITING_H

#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Indexed_mesh.h>

#include <Eigen/SparseCore>

#include <memory>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// The cotangent Laplacian `L` of a triangle mesh (n x n, symmetric,
/// positive semi-definite, rows summing to zero): `L(i,j) = -w_ij` and
/// `L(i,i) = sum_j w_ij` with `w_ij` half the sum of the cotangents opposite
/// edge ij, clamped as the embedding solver clamps its own: each cotangent
/// bounded above as CGAL's clamped cotangent bounds it (cosine 0.999), a
/// non-finite one counted as zero, and a weight below 1% of the mean
/// positive weight (negative, or from degenerate triangles only) raised to
/// it. Vertices in no triangle have an empty row.
Eigen::SparseMatrix<double> cotangent_laplacian(const Indexed_mesh& mesh);

/// \ingroup PkgMPMRef
/// Options of `Laplacian_editing`.
struct Laplacian_editing_options
{
  /// Handle stiffness relative to the mean diagonal of `L^T L`, the same
  /// convention as `Embedding_options::handle_weight`.
  double handle_weight = 100.;
  /// Anchor stiffness (relative likewise) pulling connected components
  /// without handles to their rest positions, which the energy cannot place.
  double anchor_weight = 1e-6;
};

/// \ingroup PkgMPMRef
/// Linear Laplacian surface editing (Sorkine et al. 2004, without the
/// rotation of the details): minimizes
/// `|L V - L V_rest|^2 + w sum_h |v_h - y_h|^2` over the positions `V`, with
/// `L` the cotangent Laplacian of the rest mesh. The details (Laplacian
/// coordinates) are kept in the rest orientation, so a rotation of all
/// handles is not reproduced: the surface shears toward the handles instead.
/// `L^T L + W_h` is factored once per handle vertex set
/// (`Eigen::SimplicialLDLT`); each deformation is three back-substitutions.
/// Vertices in no triangle stay where they are unless they are handles.
class Laplacian_editing
{
public:
  /// Copies `mesh` and builds its Laplacian. Throws `Input_error` for a
  /// triangle with an out-of-range corner or non-finite positions.
  explicit Laplacian_editing(const Indexed_mesh& mesh,
                             const Laplacian_editing_options& options = Laplacian_editing_options());
  ~Laplacian_editing();
  /// Movable, not copyable.
  Laplacian_editing(Laplacian_editing&&) noexcept;
  /// Movable, not copyable.
  Laplacian_editing& operator=(Laplacian_editing&&) noexcept;

  /// Sets the handles (see `validate_handles()`; an empty set is an
  /// error). Refactors only when the handle vertices change. Throws
  /// `Computation_error` when the factorization fails.
  void set_handles(const Handle_set& handles);

  /// The deformed positions (n x 3). Throws `Input_error` when no handles
  /// are set.
  Point_matrix deform() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace MPM
} // namespace CGAL

#endif
