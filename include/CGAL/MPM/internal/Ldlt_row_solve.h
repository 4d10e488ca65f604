// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_LDLT_ROW_SOLVE_H
#define CGAL_MPM_INTERNAL_LDLT_ROW_SOLVE_H

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace CGAL {
namespace MPM {
namespace internal {

// `A^-1 b` from Eigen's `SimplicialLDLT` factor of `A` (which solves the
// same, `ldlt.solve(b)`, the reference), with every column of `b` carried
// through one pass over the factor. The triangular solves of a large mesh
// are bound by reading `L`, which the column-by-column solve reads once per
// column: a displayed frame back-substitutes three. Wide right-hand sides
// are cut into column groups, and three columns into one group per core,
// solved in parallel (TBB).
Eigen::MatrixXd ldlt_solve_rows(const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& ldlt, const Eigen::MatrixXd& b);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
