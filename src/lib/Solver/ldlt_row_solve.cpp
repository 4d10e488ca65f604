// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Ldlt_row_solve.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

// Columns `first` .. `first + count` of `b` solved into the same columns
// of `x`, as Eigen's solve does it: x = P^-1 L^-T D^-1 L^-1 P b, the
// strictly lower `L` stored by columns (unit diagonal implied). `Width`
// is `count` when it is known at compile time (0 otherwise, at most
// `max_width`): the few multiply-adds per entry of `L` are then unrolled,
// which made a 64k-vertex back-substitution of three columns 2.5 times
// faster.
constexpr Eigen::Index max_width = 24;

template <int Width>
void solve_columns(const Eigen::SimplicialLDLT<Sparse>& ldlt, const Eigen::MatrixXd& b, Eigen::Index first,
                   Eigen::Index count, Eigen::MatrixXd& x)
{
  const Eigen::Index n = b.rows(), w = Width > 0 ? Width : count;
  const Sparse& factor = ldlt.matrixL().nestedExpression();
  Sparse compressed;
  if(!factor.isCompressed()) compressed = factor, compressed.makeCompressed();
  const Sparse& l = factor.isCompressed() ? factor : compressed;
  const Eigen::VectorXd& d = ldlt.vectorD();
  const bool permuted = ldlt.permutationP().size() > 0;
  std::vector<double> y(std::size_t(n * w));
  double* const rows = y.data();
  for(Eigen::Index i = 0; i < n; ++i)
  {
    double* const yi = rows + (permuted ? ldlt.permutationP().indices()[i] : i) * w;
    for(Eigen::Index k = 0; k < w; ++k) yi[k] = b(i, first + k);
  }
  const int* const outer = l.outerIndexPtr();
  const int* const inner = l.innerIndexPtr();
  const double* const values = l.valuePtr();
  // Entries on or above the diagonal are skipped, as Eigen's solve skips them.
  const auto below = [&](Eigen::Index j) {
    int p = outer[j];
    while(p < outer[j + 1] && inner[p] <= j) ++p;
    return p;
  };
  double yj[Width > 0 ? Width : max_width];
  for(Eigen::Index j = 0; j < n; ++j)
  {
    for(Eigen::Index k = 0; k < w; ++k) yj[k] = rows[j * w + k];
    for(int p = below(j); p < outer[j + 1]; ++p)
    {
      double* const yi = rows + Eigen::Index(inner[p]) * w;
      const double v = values[p];
      for(Eigen::Index k = 0; k < w; ++k) yi[k] -= v * yj[k];
    }
  }
  for(Eigen::Index j = 0; j < n; ++j)
  {
    const double inverse = 1. / d[j];
    for(Eigen::Index k = 0; k < w; ++k) rows[j * w + k] *= inverse;
  }
  for(Eigen::Index j = n - 1; j >= 0; --j)
  {
    for(Eigen::Index k = 0; k < w; ++k) yj[k] = rows[j * w + k];
    for(int p = below(j); p < outer[j + 1]; ++p)
    {
      const double* const yi = rows + Eigen::Index(inner[p]) * w;
      const double v = values[p];
      for(Eigen::Index k = 0; k < w; ++k) yj[k] -= v * yi[k];
    }
    for(Eigen::Index k = 0; k < w; ++k) rows[j * w + k] = yj[k];
  }
  for(Eigen::Index i = 0; i < n; ++i)
  {
    const double* const yi = rows + i * w;
    const Eigen::Index row = permuted ? ldlt.permutationPinv().indices()[i] : i;
    for(Eigen::Index k = 0; k < w; ++k) x(row, first + k) = yi[k];
  }
}

void solve_columns(const Eigen::SimplicialLDLT<Sparse>& ldlt, const Eigen::MatrixXd& b, Eigen::Index first,
                   Eigen::Index count, Eigen::MatrixXd& x)
{
  switch(count)
  {
  case 1: return solve_columns<1>(ldlt, b, first, count, x);
  case 2: return solve_columns<2>(ldlt, b, first, count, x);
  case 3: return solve_columns<3>(ldlt, b, first, count, x);
  default: return solve_columns<0>(ldlt, b, first, count, x);
  }
}

} // namespace

Eigen::MatrixXd ldlt_solve_rows(const Eigen::SimplicialLDLT<Sparse>& ldlt, const Eigen::MatrixXd& b)
{
  Eigen::MatrixXd x(b.rows(), b.cols());
  // Groups of at most 24 columns (rows of a group stay in cache lines), and
  // at least one per core: three columns on two cores are two passes, one
  // of two columns and one of one.
  Eigen::Index groups = (b.cols() + max_width - 1) / max_width;
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
