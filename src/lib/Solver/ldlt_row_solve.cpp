// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Ldlt_row_solve.h>

#include <CGAL/MPM/internal/Parallel_for.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <queue>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

constexpr Eigen::Index max_width = 24;

// Eigen's strictly lower `L` (unit diagonal implied; its solve is
// x = P^-1 L^-T D^-1 L^-1 P b), read when the solver is made.
struct Factor_view
{
  const int* outer;
  const int* inner;
  const double* values;
  // The first entry of column j below the diagonal (entries on or above it
  // are skipped, as Eigen's solve skips them).
  int below(Eigen::Index j) const
  {
    int p = outer[j];
    while(p < outer[j + 1] && inner[p] <= j) ++p;
    return p;
  }
};

// Columns `first` .. `first + count` of `b` solved into the same columns of
// `x`, the rows of a vertex side by side. `Width` is `count` when it is
// known at compile time (0 otherwise, at most `max_width`): the few
// multiply-adds per entry of `L` are then unrolled, which made a 64k-vertex
// back-substitution of three columns 2.5 times faster. Both passes gather
// (each row reads the rows it depends on and writes only itself), reading
// their copy of `L` forwards; the parts of `partition` run in parallel, as a
// row of a subtree depends only on rows of its subtree (forward) or on
// rows of its subtree and the top (backward).
template <int Width>
void solve_columns(const Ldlt_row_solver::Solve_copies& l, const Eigen::PermutationMatrix<Eigen::Dynamic>& p,
                   const Eigen::PermutationMatrix<Eigen::Dynamic>& p_inverse,
                   const Ldlt_row_solver::Partition& partition, const Eigen::MatrixXd& b, Eigen::Index first,
                   Eigen::Index count, Eigen::MatrixXd& x)
{
  const Eigen::Index n = b.rows(), w = Width > 0 ? Width : count;
  const bool permuted = p.size() > 0;
  std::vector<double> y(std::size_t(n * w));
  double* const rows = y.data();
  for(Eigen::Index i = 0; i < n; ++i)
  {
    double* const yi = rows + (permuted ? p.indices()[i] : i) * w;
    for(Eigen::Index k = 0; k < w; ++k) yi[k] = b(i, first + k);
  }
  // Row i of L y = b, once the rows before it are known.
  const auto forward = [&](int i) {
    double yi[Width > 0 ? Width : max_width];
    for(Eigen::Index k = 0; k < w; ++k) yi[k] = rows[i * w + k];
    for(int q = l.rows.outer[std::size_t(i)]; q < l.rows.outer[std::size_t(i) + 1]; ++q)
    {
      const double* const yj = rows + Eigen::Index(l.rows.inner[std::size_t(q)]) * w;
      for(Eigen::Index k = 0; k < w; ++k) yi[k] -= l.rows.values[std::size_t(q)] * yj[k];
    }
    for(Eigen::Index k = 0; k < w; ++k) rows[i * w + k] = yi[k];
  };
  const std::vector<int>& top = partition.top;
  internal::parallel_for_each_index(partition.parts.size(), [&](std::size_t part) {
    std::for_each(partition.parts[part].begin(), partition.parts[part].end(), forward);
  });
  std::for_each(top.begin(), top.end(), forward);
  // Row j of D L^T x = y, once the rows after it are known (D^-1 applied
  // as the pass reaches the row).
  const auto backward = [&](int j) {
    double yj[Width > 0 ? Width : max_width];
    const double inverse = 1. / l.d[std::size_t(j)];
    for(Eigen::Index k = 0; k < w; ++k) yj[k] = rows[j * w + k] * inverse;
    const std::size_t r = std::size_t(n - 1 - j);
    for(int q = l.reversed_columns.outer[r]; q < l.reversed_columns.outer[r + 1]; ++q)
    {
      const double* const yi = rows + Eigen::Index(l.reversed_columns.inner[std::size_t(q)]) * w;
      for(Eigen::Index k = 0; k < w; ++k) yj[k] -= l.reversed_columns.values[std::size_t(q)] * yi[k];
    }
    for(Eigen::Index k = 0; k < w; ++k) rows[j * w + k] = yj[k];
  };
  std::for_each(top.rbegin(), top.rend(), backward);
  internal::parallel_for_each_index(partition.parts.size(), [&](std::size_t part) {
    std::for_each(partition.parts[part].rbegin(), partition.parts[part].rend(), backward);
  });
  for(Eigen::Index i = 0; i < n; ++i)
  {
    const double* const yi = rows + i * w;
    const Eigen::Index row = permuted ? p_inverse.indices()[i] : i;
    for(Eigen::Index k = 0; k < w; ++k) x(row, first + k) = yi[k];
  }
}

// The elimination tree of `L` split into `count` sets of independent
// subtrees of about equal work (entries of `L`), by expanding the heaviest
// subtree into its children until no subtree holds more than a tenth of the
// rest; the expanded nodes are the top. Stops with fewer parts when the top
// would grow beyond a fifth of the work.
Ldlt_row_solver::Partition split_tree(const Factor_view& l, int n, int count)
{
  std::vector<int> parent(std::size_t(n), -1);
  std::vector<long> work(std::size_t(n), 1);
  std::vector<std::vector<int>> children{std::size_t(n)};
  for(int j = 0; j < n; ++j)
  {
    const int q = l.below(j);
    work[std::size_t(j)] += l.outer[j + 1] - q;
    for(int r = q; r < l.outer[j + 1]; ++r)
      if(parent[std::size_t(j)] < 0 || l.inner[r] < parent[std::size_t(j)]) parent[std::size_t(j)] = l.inner[r];
  }
  std::vector<long> subtree = work;
  for(int j = 0; j < n; ++j)
    if(parent[std::size_t(j)] >= 0)
    {
      subtree[std::size_t(parent[std::size_t(j)])] += subtree[std::size_t(j)];
      children[std::size_t(parent[std::size_t(j)])].push_back(j);
    }
  const auto lighter = [&](int a, int b) { return subtree[std::size_t(a)] < subtree[std::size_t(b)]; };
  std::priority_queue<int, std::vector<int>, decltype(lighter)> frontier(lighter);
  long frontier_work = 0, top_work = 0;
  for(int j = 0; j < n; ++j)
    if(parent[std::size_t(j)] < 0)
    {
      frontier.push(j);
      frontier_work += subtree[std::size_t(j)];
    }
  Ldlt_row_solver::Partition partition;
  while(!frontier.empty() && 10 * subtree[std::size_t(frontier.top())] > frontier_work && 5 * top_work < frontier_work)
  {
    const int j = frontier.top();
    frontier.pop();
    partition.top.push_back(j);
    top_work += work[std::size_t(j)];
    frontier_work -= subtree[std::size_t(j)];
    for(int c : children[std::size_t(j)])
    {
      frontier.push(c);
      frontier_work += subtree[std::size_t(c)];
    }
  }
  // Heaviest subtree first into the lightest part.
  std::vector<long> part_work(std::size_t(count), 0);
  partition.parts.assign(std::size_t(count), {});
  for(; !frontier.empty(); frontier.pop())
  {
    const std::size_t part = std::size_t(std::min_element(part_work.begin(), part_work.end()) - part_work.begin());
    part_work[part] += subtree[std::size_t(frontier.top())];
    std::vector<int> pending{frontier.top()};
    while(!pending.empty())
    {
      const int j = pending.back();
      pending.pop_back();
      partition.parts[part].push_back(j);
      pending.insert(pending.end(), children[std::size_t(j)].begin(), children[std::size_t(j)].end());
    }
  }
  partition.parts.erase(std::remove_if(partition.parts.begin(), partition.parts.end(),
                                       [](const std::vector<int>& part) { return part.empty(); }),
                        partition.parts.end());
  for(std::vector<int>& part : partition.parts) std::sort(part.begin(), part.end());
  std::sort(partition.top.begin(), partition.top.end());
  return partition;
}

} // namespace

Ldlt_row_solver::Ldlt_row_solver(const Vertex_ldlt& ldlt, int parts)
  : ldlt_(&ldlt)
{
  const Sparse& factor = ldlt.matrixL().nestedExpression();
  Sparse compressed;
  if(!factor.isCompressed()) compressed = factor, compressed.makeCompressed();
  const Sparse& l = factor.isCompressed() ? factor : compressed;
  const int n = static_cast<int>(l.rows());
  const Eigen::VectorXd d = ldlt.vectorD();
  copies_.d.assign(d.data(), d.data() + d.size());
  const Factor_view view{l.outerIndexPtr(), l.innerIndexPtr(), l.valuePtr()};
  // L's rows (its entries by row, in increasing column) and its columns
  // from the last to the first.
  Compressed_lower& by_row = copies_.rows;
  by_row.outer.assign(std::size_t(n) + 1, 0);
  for(int j = 0; j < n; ++j)
    for(int q = view.below(j); q < view.outer[j + 1]; ++q) ++by_row.outer[std::size_t(view.inner[q]) + 1];
  for(int i = 0; i < n; ++i) by_row.outer[std::size_t(i) + 1] += by_row.outer[std::size_t(i)];
  by_row.inner.resize(std::size_t(by_row.outer.back()));
  by_row.values.resize(by_row.inner.size());
  std::vector<int> next(by_row.outer.begin(), by_row.outer.end() - 1);
  Compressed_lower& reversed = copies_.reversed_columns;
  reversed.outer.assign(std::size_t(n) + 1, 0);
  reversed.inner.reserve(by_row.inner.size());
  reversed.values.reserve(by_row.inner.size());
  for(int j = 0; j < n; ++j)
    for(int q = view.below(j); q < view.outer[j + 1]; ++q)
    {
      const std::size_t at = std::size_t(next[std::size_t(view.inner[q])]++);
      by_row.inner[at] = j;
      by_row.values[at] = view.values[q];
    }
  for(int r = 0; r < n; ++r)
  {
    const int j = n - 1 - r;
    for(int q = view.below(j); q < view.outer[j + 1]; ++q)
    {
      reversed.inner.push_back(view.inner[q]);
      reversed.values.push_back(view.values[q]);
    }
    reversed.outer[std::size_t(r) + 1] = int(reversed.inner.size());
  }
  whole_.parts.assign(1, std::vector<int>(std::size_t(n)));
  for(int j = 0; j < n; ++j) whole_.parts[0][std::size_t(j)] = j;
  split_ = parts > 1 ? split_tree(view, n, parts) : whole_;
}

Eigen::MatrixXd Ldlt_row_solver::solve(const Eigen::MatrixXd& b) const
{
  Eigen::MatrixXd x(b.rows(), b.cols());
  // Groups of at most 24 columns (rows of a group stay in cache lines), at
  // least one per core when each gets 6 columns or more; fewer columns go
  // through the tree's parts in parallel instead (measured on the 64k
  // spider: 3 columns 5.0 ms against 6.7 ms as groups of 2 and 1, 19
  // columns 29.8 ms against 22.6 ms as groups of 10 and 9).
  Eigen::Index groups = (b.cols() + max_width - 1) / max_width;
#ifdef CGAL_LINKED_WITH_TBB
  const Eigen::Index cores = tbb::this_task_arena::max_concurrency();
  if(b.cols() >= 6 * cores) groups = std::max(groups, cores);
#endif
  const Partition& partition = groups > 1 ? whole_ : split_;
  const Eigen::Index width = groups > 0 ? (b.cols() + groups - 1) / groups : 0;
  const auto solve_group = [&](std::size_t g) {
    const Eigen::Index first = Eigen::Index(g) * width, count = std::min(width, b.cols() - first);
    const auto& p = ldlt_->permutationP();
    const auto& p_inverse = ldlt_->permutationPinv();
    switch(count)
    {
    case 1: return solve_columns<1>(copies_, p, p_inverse, partition, b, first, count, x);
    case 2: return solve_columns<2>(copies_, p, p_inverse, partition, b, first, count, x);
    case 3: return solve_columns<3>(copies_, p, p_inverse, partition, b, first, count, x);
    default: return solve_columns<0>(copies_, p, p_inverse, partition, b, first, count, x);
    }
  };
  internal::parallel_for_each_index(std::size_t(groups), solve_group);
  return x;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
