// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Ldlt_inverse_gram.h>

#include <CGAL/MPM/internal/Parallel_for.h>

#include <algorithm>
#include <utility>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Row_major = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// What the factor says about one operand: `z = L^-1 P X` on the rows it
// can reach (ascending), and `D^-1 z`.
struct Forward_solution
{
  std::vector<int> reach;
  Row_major z;
  Row_major scaled;
};

class Forward_solver
{
public:
  explicit Forward_solver(const Vertex_ldlt& ldlt)
    : ldlt_(ldlt), l_(compressed(ldlt.matrixL().nestedExpression(), copy_)), d_(ldlt.vectorD()), n_(int(l_.rows()))
  {
    const int* const outer = l_.outerIndexPtr();
    const int* const inner = l_.innerIndexPtr();
    parent_.assign(std::size_t(n_), -1);
    for(int j = 0; j < n_; ++j)
      for(int p = outer[j]; p < outer[j + 1]; ++p)
        if(inner[p] > j && (parent_[std::size_t(j)] < 0 || inner[p] < parent_[std::size_t(j)])) parent_[std::size_t(j)] = inner[p];
  }

  Forward_solution solve(const Local_columns& operand) const
  {
    Forward_solution s;
    std::vector<int> position(std::size_t(n_), -1);
    // The rows of L^-1 e_j that can be non-zero are j's ancestors in the
    // elimination tree.
    for(int row : operand.rows)
      for(int j = permuted(row); j >= 0 && position[std::size_t(j)] < 0; j = parent_[std::size_t(j)])
      {
        position[std::size_t(j)] = 0;
        s.reach.push_back(j);
      }
    std::sort(s.reach.begin(), s.reach.end());
    for(std::size_t i = 0; i < s.reach.size(); ++i) position[std::size_t(s.reach[i])] = int(i);
    const Eigen::Index w = operand.values.cols();
    s.z = Row_major::Zero(Eigen::Index(s.reach.size()), w);
    for(std::size_t i = 0; i < operand.rows.size(); ++i)
      s.z.row(position[std::size_t(permuted(operand.rows[i]))]) += operand.values.row(Eigen::Index(i));
    const int* const outer = l_.outerIndexPtr();
    const int* const inner = l_.innerIndexPtr();
    const double* const values = l_.valuePtr();
    double* const z = s.z.data();
    for(std::size_t i = 0; i < s.reach.size(); ++i)
    {
      const int j = s.reach[i];
      const double* const zj = z + Eigen::Index(i) * w;
      for(int p = outer[j]; p < outer[j + 1]; ++p)
      {
        if(inner[p] <= j) continue; // as Eigen's solve, which skips them
        double* const zi = z + Eigen::Index(position[std::size_t(inner[p])]) * w;
        const double v = values[p];
        for(Eigen::Index k = 0; k < w; ++k) zi[k] -= v * zj[k];
      }
    }
    s.scaled.resize(s.z.rows(), w);
    for(std::size_t i = 0; i < s.reach.size(); ++i)
      s.scaled.row(Eigen::Index(i)) = s.z.row(Eigen::Index(i)) / d_[s.reach[i]];
    return s;
  }

private:
  // `l` itself when compressed (Eigen's factor is), else a compressed copy in `copy`.
  static const Sparse& compressed(const Sparse& l, Sparse& copy)
  {
    if(l.isCompressed()) return l;
    copy = l;
    copy.makeCompressed();
    return copy;
  }

  int permuted(int row) const
  {
    return ldlt_.permutationP().size() > 0 ? ldlt_.permutationP().indices()[row] : row;
  }

  const Vertex_ldlt& ldlt_;
  Sparse copy_;
  const Sparse& l_;
  Eigen::VectorXd d_; // vectorD() returns a copy
  int n_;
  std::vector<int> parent_;
};

// `a.scaled^T b.z` over the rows both reach.
Eigen::MatrixXd meeting_product(const Forward_solution& a, const Forward_solution& b)
{
  std::vector<std::pair<Eigen::Index, Eigen::Index>> shared;
  for(std::size_t i = 0, j = 0; i < a.reach.size() && j < b.reach.size();)
  {
    if(a.reach[i] < b.reach[j]) ++i;
    else if(b.reach[j] < a.reach[i]) ++j;
    else shared.emplace_back(Eigen::Index(i++), Eigen::Index(j++));
  }
  Row_major left(Eigen::Index(shared.size()), a.z.cols()), right(Eigen::Index(shared.size()), b.z.cols());
  for(std::size_t k = 0; k < shared.size(); ++k)
  {
    left.row(Eigen::Index(k)) = a.scaled.row(shared[k].first);
    right.row(Eigen::Index(k)) = b.z.row(shared[k].second);
  }
  return left.transpose() * right;
}

} // namespace

std::vector<Eigen::Index> column_offsets(const std::vector<Local_columns>& operands)
{
  std::vector<Eigen::Index> offsets{0};
  for(const Local_columns& o : operands) offsets.push_back(offsets.back() + o.values.cols());
  return offsets;
}

Eigen::MatrixXd ldlt_inverse_gram(const Vertex_ldlt& ldlt, const std::vector<Local_columns>& operands)
{
  const Forward_solver forward(ldlt);
  std::vector<Forward_solution> solutions(operands.size());
  parallel_for_each_index(operands.size(), [&](std::size_t o) { solutions[o] = forward.solve(operands[o]); });

  const std::vector<Eigen::Index> offset = column_offsets(operands);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for(std::size_t a = 0; a < operands.size(); ++a)
    for(std::size_t b = a; b < operands.size(); ++b) pairs.emplace_back(a, b);
  Eigen::MatrixXd gram(offset.back(), offset.back());
  parallel_for_each_index(pairs.size(), [&](std::size_t k) {
    const auto [a, b] = pairs[k];
    Eigen::MatrixXd block = meeting_product(solutions[a], solutions[b]);
    if(a == b) block = 0.5 * (block + block.transpose()).eval(); // symmetric to the last bit
    gram.block(offset[a], offset[b], block.rows(), block.cols()) = block;
    gram.block(offset[b], offset[a], block.cols(), block.rows()) = block.transpose();
  });
  return gram;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
