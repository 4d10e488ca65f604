// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_LDLT_INVERSE_GRAM_H
#define CGAL_MPM_INTERNAL_LDLT_INVERSE_GRAM_H

#include <CGAL/MPM/internal/Vertex_ordering.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

/// Columns of an `n`-row operand that are zero outside a few rows: row
/// `rows[i]` of the operand is `values.row(i)` (repeated rows add up).
struct Local_columns
{
  std::vector<int> rows;
  Eigen::MatrixXd values;
};

/// The column offset of each operand in `X = [X_0 X_1 ...]`, and the total
/// width last.
std::vector<Eigen::Index> column_offsets(const std::vector<Local_columns>& operands);

/// `X^T A^-1 X` for the operands `X` side by side, from Eigen's
/// `SimplicialLDLT` factor `P A P^T = L D L^T`: with `Z = L^-1 P X` it is
/// `Z^T D^-1 Z`. A column of `Z` is zero outside the elimination-tree
/// ancestors of its operand's rows, so an operand local to a patch of the
/// mesh costs a forward solve over its ancestors only, and two operands
/// meet only where their ancestors do (measured on a 64k-vertex spider with
/// 65 cluster operands: a tenth of the flops of solving every column
/// through the whole factor). Operands are solved, and pairs multiplied,
/// in parallel (TBB). The reference is `inverse_gram_by_solves()`.
Eigen::MatrixXd ldlt_inverse_gram(const Vertex_ldlt& ldlt,
                                  const std::vector<Local_columns>& operands);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
