// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Vertex_block.h>

#include <Eigen/SparseCholesky>
#ifdef CGAL_MPM_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace CGAL {
namespace MPM {
namespace internal {
namespace embedding {

Eigen::MatrixXd inverse_gram_by_solves(const Vertex_block& block, const std::vector<Local_columns>& operands)
{
  const Eigen::Index n = block.factored_matrix().rows();
  const std::vector<Eigen::Index> offset = column_offsets(operands);
  Eigen::MatrixXd gram(offset.back(), offset.back());
  // Batches of operands of about 48 columns bound the memory of the
  // right-hand sides on large models.
  constexpr Eigen::Index batch_columns = 48;
  for(std::size_t first = 0; first < operands.size();)
  {
    std::size_t last = first + 1;
    while(last < operands.size() && offset[last + 1] - offset[first] <= batch_columns) ++last;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, offset[last] - offset[first]);
    for(std::size_t o = first; o < last; ++o)
      for(std::size_t i = 0; i < operands[o].rows.size(); ++i)
        rhs.block(operands[o].rows[i], offset[o] - offset[first], 1, operands[o].values.cols()) +=
          operands[o].values.row(Eigen::Index(i));
    const Eigen::MatrixXd solved = block.solve_factored(rhs);
    for(std::size_t o = 0; o < operands.size(); ++o)
    {
      Eigen::MatrixXd local(Eigen::Index(operands[o].rows.size()), solved.cols());
      for(std::size_t i = 0; i < operands[o].rows.size(); ++i) local.row(Eigen::Index(i)) = solved.row(operands[o].rows[i]);
      gram.block(offset[o], offset[first], operands[o].values.cols(), solved.cols()) = operands[o].values.transpose() * local;
    }
    first = last;
  }
  return gram;
}

std::unique_ptr<Vertex_block> make_vertex_block(Sparse_solver which)
{
#ifdef CGAL_MPM_HAS_CHOLMOD
  if(which == Sparse_solver::cholmod)
    return std::make_unique<Factored_vertex_block<CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Sparse>>>>();
#else
  (void)which;
#endif
  return std::make_unique<Factored_vertex_block<CGAL::Eigen_solver_traits<Vertex_ldlt>>>();
}

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL
