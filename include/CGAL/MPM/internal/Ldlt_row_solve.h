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
// The backward pass reads a copy of `L` with its columns in reverse order
// (12 bytes per entry: 24 MB on the 64k-vertex spider). Read backwards in
// Eigen's storage, that pass took 11-13 ms there against 4 ms for the
// forward pass over as many entries.
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
  // in increasing order per part, and the common ancestors (`top`), with
  // each row's index in `top` (-1 outside it; empty without a top).
  struct Partition
  {
    std::vector<std::vector<int>> parts;
    std::vector<int> top;
    std::vector<int> top_slot;
  };
  // The entries of `L` below the diagonal, column by column from the last
  // column to the first (compressed columns).
  struct Reversed_columns
  {
    std::vector<int> outer;
    std::vector<int> inner;
    std::vector<double> values;
  };

private:
  const Vertex_ldlt* ldlt_;
  Eigen::SparseMatrix<double> compressed_; // when Eigen's factor is not compressed
  Eigen::VectorXd d_;                      // Eigen hands D out by value
  Reversed_columns reversed_;              // read by the backward pass
  Partition whole_, split_; // one part without a top; the tree's split
};

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
