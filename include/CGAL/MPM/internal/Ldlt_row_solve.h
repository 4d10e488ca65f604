// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_LDLT_ROW_SOLVE_H
#define CGAL_MPM_INTERNAL_LDLT_ROW_SOLVE_H

#include <CGAL/MPM/internal/Vertex_ordering.h>

#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// `A^-1 b` from the `SimplicialLDLT` factor of `A` (which solves the
// same, `ldlt.solve(b)`, the reference), with every column of `b` carried
// through one pass over the factor. The triangular solves of a large mesh
// are bound by reading `L`, which the column-by-column solve reads once per
// column: a displayed frame back-substitutes three.
//
// Wide right-hand sides are cut into column groups solved in parallel
// (TBB). Narrow ones (a frame's three columns) are solved in parallel over
// the elimination tree instead: independent subtrees of about equal work,
// one set per core, then their common ancestors (the top of the tree). Cut
// by columns, three columns on two cores were a pass of two beside a pass
// of one.
//
// The passes read their own copies of `L` (24 bytes per entry of `L` for
// both, 48 MB on the 64k-vertex spider), laid out so that each reads memory
// forwards and only gathers. Read backwards in Eigen's storage, the
// backward pass took 11-13 ms there against 4 ms forwards; the forward pass
// scattering into rows below took 6 ms against 4 ms gathering by rows.
class Ldlt_row_solver
{
public:
  /// Keeps a reference to `ldlt`, which must outlive the solver and not be
  /// refactored; splits its elimination tree into `parts` (1: no split).
  Ldlt_row_solver(const Vertex_ldlt& ldlt, int parts);
  /// `A^-1 b`.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;
  /// The parts the tree was split into (fewer than asked when it has no
  /// independent subtrees of about equal work).
  int number_of_parts() const { return static_cast<int>(split_.parts.size()); }

  // The columns of `L` a pass visits: independent subtrees, their columns
  // in increasing order per part, and the common ancestors (`top`).
  struct Partition
  {
    std::vector<std::vector<int>> parts;
    std::vector<int> top;
  };
  // Entries of `L` below the diagonal, compressed by rows or by columns.
  struct Compressed_lower
  {
    std::vector<int> outer;
    std::vector<int> inner;
    std::vector<double> values;
  };
  // `L` as each pass reads it, forwards in memory (the prefetcher's
  // direction): by rows for the forward pass, by columns from the last to
  // the first for the backward pass (its entry r is L's column n - 1 - r);
  // and `D`.
  struct Solve_copies
  {
    Compressed_lower rows;
    Compressed_lower reversed_columns;
    std::vector<double> d;
  };

private:
  const Vertex_ldlt* ldlt_; // for its permutation
  Solve_copies copies_;
  Partition whole_, split_; // one part without a top; the tree's split
};

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
