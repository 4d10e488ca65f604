// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_VERTEX_BLOCK_H
#define CGAL_MPM_INTERNAL_VERTEX_BLOCK_H

#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/internal/Ldlt_inverse_gram.h>
#include <CGAL/MPM/internal/Ldlt_row_solve.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {
namespace embedding {

using Sparse = Eigen::SparseMatrix<double>;

/// LDLT factors an indefinite matrix without complaint (LLT refuses it): the
/// pivots say whether the matrix was positive definite, and where not. The
/// row with the smallest non-positive pivot, or -1.
template <class Ldlt>
int non_positive_pivot_row(const Ldlt& ldlt)
{
  const Eigen::VectorXd& pivots = ldlt.vectorD();
  Eigen::Index weakest = 0;
  if(pivots.size() == 0) return -1;
  for(Eigen::Index i = 0; i < pivots.size(); ++i)
    if(!(pivots[i] >= pivots[weakest])) weakest = i;
  if(pivots[weakest] > 0) return -1;
  return ldlt.permutationPinv().indices()[weakest];
}

/// The vertex block `A = A_f + U diag(w) U^T` of the embedding solver's
/// global step: the elastic matrix plus a diagonal (handles and anchors),
/// factored once as `A_f`. A change of handles changes a few diagonal
/// entries, a low-rank (Woodbury) update that needs no refactorization:
/// `A^-1 = A_f^-1 - C K^-1 C^T`, `C = A_f^-1 U`, `K = diag(1/w) + U^T C`.
/// The solver is chosen at run time (`Sparse_solver`), hence this interface.
class Vertex_block
{
public:
  virtual ~Vertex_block() = default;
  /// Factors `elastic + diag(diagonal)` as `A_f`, without update; false
  /// when it is not positive definite.
  virtual bool factor(const Sparse& elastic, const Eigen::VectorXd& diagonal) = 0;
  /// After a failed `factor()`: the row with the smallest pivot, or -1 when
  /// the solver does not tell.
  virtual int weakest_row() const = 0;
  /// Makes `diagonal` the block's diagonal terms by a low-rank update of
  /// `A_f` when at most `max_rank` entries differ from its own; false (and
  /// the block unchanged) otherwise.
  virtual bool update(const Eigen::VectorXd& diagonal, Eigen::Index max_rank) = 0;
  /// `A^-1 b`.
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const = 0;
  /// `A_f^-1 b`, ignoring the update.
  virtual Eigen::MatrixXd solve_factored(const Eigen::MatrixXd& b) const = 0;
  /// `X^T A_f^-1 X` for operands `X` local to a few vertices each (see
  /// `ldlt_inverse_gram()`), ignoring the update.
  virtual Eigen::MatrixXd inverse_gram(const std::vector<Local_columns>& operands) const = 0;
  /// `A x`.
  virtual Eigen::MatrixXd product(const Eigen::MatrixXd& x) const = 0;
  /// `A_f`.
  virtual const Sparse& factored_matrix() const = 0;
  /// The vertices `U` of the update (sorted), empty without one.
  virtual const std::vector<int>& update_vertices() const = 0;
  /// The update's weights `w`, one per update vertex.
  virtual const Eigen::VectorXd& update_weights() const = 0;
  /// `C = A_f^-1 U`, `n x k`.
  virtual const Eigen::MatrixXd& update_columns() const = 0;
  /// `K^-1`, `k x k`.
  virtual const Eigen::MatrixXd& capacitance_inverse() const = 0;
};

/// `Vertex_block` factored by `SolverTraits`, a model of
/// `SparseLinearAlgebraWithFactorTraits_d` that is a `CGAL::Eigen_solver_traits`
/// (whose Eigen solver back-substitutes many columns at once).
template <class SolverTraits>
class Factored_vertex_block final : public Vertex_block
{
public:
  bool factor(const Sparse& elastic, const Eigen::VectorXd& diagonal) override
  {
    diagonal_ = diagonal;
    system_ = elastic;
    for(Eigen::Index v = 0; v < diagonal.size(); ++v) system_.coeffRef(v, v) += diagonal[v];
    system_.makeCompressed();
    vertices_.clear();
    weights_.resize(0);
    columns_.resize(system_.rows(), 0);
    matrix_ = std::make_unique<typename SolverTraits::Matrix>(system_);
    typename SolverTraits::NT determinant;
    if(!traits_.factor(*matrix_, determinant)) return false;
    if constexpr(std::is_same_v<typename SolverTraits::Solver, Vertex_ldlt>)
    {
      // Below a few thousand rows a pass is too short to share between cores.
      int parts = 1;
#ifdef CGAL_LINKED_WITH_TBB
      if(system_.rows() > 5000) parts = tbb::this_task_arena::max_concurrency();
#endif
      row_solver_ = std::make_unique<Ldlt_row_solver>(traits_.solver(), parts);
      return (weakest_ = non_positive_pivot_row(traits_.solver())) < 0;
    }
    return true;
  }

  int weakest_row() const override { return weakest_; }

  bool update(const Eigen::VectorXd& diagonal, Eigen::Index max_rank) override
  {
    const Eigen::VectorXd change = diagonal - diagonal_;
    if((change.array() != 0.).count() > max_rank) return false;
    vertices_.clear();
    std::vector<double> weights;
    for(Eigen::Index v = 0; v < change.size(); ++v)
      if(change[v] != 0.)
      {
        vertices_.push_back(int(v));
        weights.push_back(change[v]);
      }
    weights_ = Eigen::Map<const Eigen::VectorXd>(weights.data(), Eigen::Index(weights.size()));
    const Eigen::Index k = Eigen::Index(vertices_.size());
    if(k == 0)
    {
      columns_.resize(system_.rows(), 0);
      return true;
    }
    Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(system_.rows(), k);
    for(Eigen::Index u = 0; u < k; ++u) unit(vertices_[std::size_t(u)], u) = 1.;
    columns_ = solve_factored(unit);
    Eigen::MatrixXd capacitance(k, k);
    for(Eigen::Index u = 0; u < k; ++u) capacitance.row(u) = columns_.row(vertices_[std::size_t(u)]);
    capacitance.diagonal() += weights_.cwiseInverse();
    capacitance_inverse_ = capacitance.inverse();
    return true;
  }

  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override
  {
    Eigen::MatrixXd x = solve_factored(b);
    if(!vertices_.empty())
    {
      Eigen::MatrixXd at_updates(vertices_.size(), x.cols());
      for(std::size_t u = 0; u < vertices_.size(); ++u) at_updates.row(Eigen::Index(u)) = x.row(vertices_[u]);
      x -= columns_ * (capacitance_inverse_ * at_updates);
    }
    return x;
  }

  // Columns are independent triangular solves: on large meshes they run in
  // parallel, which is most of the cost of a displayed frame. An LDLT factor
  // carries all columns through one pass over it (`Ldlt_row_solver`).
  Eigen::MatrixXd solve_factored(const Eigen::MatrixXd& b) const override
  {
    if constexpr(std::is_same_v<typename SolverTraits::Solver, Vertex_ldlt>)
      return row_solver_->solve(b);
#ifdef CGAL_LINKED_WITH_TBB
    if(b.rows() > 20000 && b.cols() > 1)
    {
      Eigen::MatrixXd x(b.rows(), b.cols());
      tbb::parallel_for(Eigen::Index(0), b.cols(), [&](Eigen::Index j) { x.col(j) = traits_.solver().solve(b.col(j)); });
      return x;
    }
#endif
    return traits_.solver().solve(b);
  }

  Eigen::MatrixXd inverse_gram(const std::vector<Local_columns>& operands) const override;

  Eigen::MatrixXd product(const Eigen::MatrixXd& x) const override
  {
    Eigen::MatrixXd product = system_ * x;
    for(std::size_t u = 0; u < vertices_.size(); ++u)
      product.row(vertices_[u]) += weights_[Eigen::Index(u)] * x.row(vertices_[u]);
    return product;
  }

  const Sparse& factored_matrix() const override { return system_; }
  const std::vector<int>& update_vertices() const override { return vertices_; }
  const Eigen::VectorXd& update_weights() const override { return weights_; }
  const Eigen::MatrixXd& update_columns() const override { return columns_; }
  const Eigen::MatrixXd& capacitance_inverse() const override { return capacitance_inverse_; }

private:
  // The traits hand out their solver by non-const reference only.
  mutable SolverTraits traits_;
  std::unique_ptr<typename SolverTraits::Matrix> matrix_;
  std::unique_ptr<Ldlt_row_solver> row_solver_; // with an LDLT factor
  Sparse system_;
  Eigen::VectorXd diagonal_;
  int weakest_ = -1;
  std::vector<int> vertices_;
  Eigen::VectorXd weights_;
  Eigen::MatrixXd columns_;
  Eigen::MatrixXd capacitance_inverse_;
};

/// `X^T A_f^-1 X` by solving every column of `X` through the whole factor
/// (`Vertex_block::solve_factored()`), in batches: the reference of
/// `Vertex_block::inverse_gram()`.
Eigen::MatrixXd inverse_gram_by_solves(const Vertex_block& block, const std::vector<Local_columns>& operands);

// An LDLT factor has an elimination tree to follow; other factors solve.
template <class SolverTraits>
Eigen::MatrixXd Factored_vertex_block<SolverTraits>::inverse_gram(const std::vector<Local_columns>& operands) const
{
  if constexpr(std::is_same_v<typename SolverTraits::Solver, Vertex_ldlt>)
    return ldlt_inverse_gram(traits_.solver(), operands);
  return inverse_gram_by_solves(*this, operands);
}

/// The factored vertex block of the kind `which` (the Cholmod one only when
/// built with it).
std::unique_ptr<Vertex_block> make_vertex_block(Sparse_solver which);

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
