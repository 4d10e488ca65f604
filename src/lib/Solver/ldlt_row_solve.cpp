// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Ldlt_row_solve.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Columns `first` .. `first + count` of `b` solved into the same columns
// of `x`, as Eigen's solve does it: x = P^-1 L^-T D^-1 L^-1 P b, the
// strictly lower `L` stored by columns (unit diagonal implied).
void solve_columns(const Eigen::SimplicialLDLT<Sparse>& ldlt, const Eigen::MatrixXd& b, Eigen::Index first,
                   Eigen::Index count, Eigen::MatrixXd& x)
{
  const Eigen::Index n = b.rows();
  const Sparse& factor = ldlt.matrixL().nestedExpression();
  Sparse compressed;
  if(!factor.isCompressed()) compressed = factor, compressed.makeCompressed();
  const Sparse& l = factor.isCompressed() ? factor : compressed;
  const Eigen::VectorXd& d = ldlt.vectorD();
  const bool permuted = ldlt.permutationP().size() > 0;
  Rows y(n, count);
  for(Eigen::Index i = 0; i < n; ++i)
    y.row(permuted ? ldlt.permutationP().indices()[i] : i) = b.block(i, first, 1, count);
  // Raw rows: Eigen's expressions on rows of a run-time width cost more
  // than the few multiply-adds they stand for.
  double* const rows = y.data();
  const int* const outer = l.outerIndexPtr();
  const int* const inner = l.innerIndexPtr();
  const double* const values = l.valuePtr();
  for(Eigen::Index j = 0; j < n; ++j)
  {
    const double* const yj = rows + j * count;
    for(int p = outer[j]; p < outer[j + 1]; ++p)
    {
      if(inner[p] <= j) continue;
      double* const yi = rows + Eigen::Index(inner[p]) * count;
      const double v = values[p];
      for(Eigen::Index k = 0; k < count; ++k) yi[k] -= v * yj[k];
    }
  }
  for(Eigen::Index j = 0; j < n; ++j)
  {
    double* const yj = rows + j * count;
    const double inverse = 1. / d[j];
    for(Eigen::Index k = 0; k < count; ++k) yj[k] *= inverse;
  }
  for(Eigen::Index j = n - 1; j >= 0; --j)
  {
    double* const yj = rows + j * count;
    for(int p = outer[j]; p < outer[j + 1]; ++p)
    {
      if(inner[p] <= j) continue;
      const double* const yi = rows + Eigen::Index(inner[p]) * count;
      const double v = values[p];
      for(Eigen::Index k = 0; k < count; ++k) yj[k] -= v * yi[k];
    }
  }
  for(Eigen::Index i = 0; i < n; ++i)
    x.block(permuted ? ldlt.permutationPinv().indices()[i] : i, first, 1, count) = y.row(i);
}

} // namespace

Eigen::MatrixXd ldlt_solve_rows(const Eigen::SimplicialLDLT<Sparse>& ldlt, const Eigen::MatrixXd& b)
{
  Eigen::MatrixXd x(b.rows(), b.cols());
  // Groups of at most 24 columns (rows of a group stay in cache lines), and
  // at least one per core: three columns on two cores are two passes, one
  // of two columns and one of one.
  Eigen::Index groups = (b.cols() + 23) / 24;
#ifdef CGAL_LINKED_WITH_TBB
  groups = std::max<Eigen::Index>(groups, std::min<Eigen::Index>(b.cols(), tbb::this_task_arena::max_concurrency()));
#endif
  const Eigen::Index width = groups > 0 ? (b.cols() + groups - 1) / groups : 0;
  const auto solve_group = [&](Eigen::Index g) {
    const Eigen::Index first = g * width;
    if(first < b.cols()) solve_columns(ldlt, b, first, std::min(width, b.cols() - first), x);
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(groups > 1 && b.rows() > 5000)
  {
    tbb::parallel_for(Eigen::Index(0), groups, solve_group);
    return x;
  }
#endif
  for(Eigen::Index g = 0; g < groups; ++g) solve_group(g);
  return x;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
