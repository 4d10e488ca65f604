// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Embedding_solver_impl.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/SparseCholesky>
#ifdef CGAL_MPM_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <type_traits>

namespace CGAL {
namespace MPM {
namespace internal {
namespace embedding {

namespace {

template <class EigenSolver>
class Traits_solver : public Vertex_block_solver
{
public:
  bool factor(const Sparse& a) override
  {
    matrix_ = std::make_unique<typename Traits::Matrix>(a);
    double d;
    if(!traits_.factor(*matrix_, d)) return false;
    if constexpr(std::is_same_v<EigenSolver, Eigen::SimplicialLDLT<Sparse>>)
      return (weakest_ = non_positive_pivot_row(traits_.solver())) < 0;
    return true;
  }

  int weakest_row() const override { return weakest_; }
  // Columns are independent triangular solves: on large meshes they run in
  // parallel, which is most of the cost of a displayed frame.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) override
  {
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

private:
  using Traits = CGAL::Eigen_solver_traits<EigenSolver>;
  Traits traits_;
  std::unique_ptr<typename Traits::Matrix> matrix_;
  int weakest_ = -1;
};

} // namespace

std::unique_ptr<Vertex_block_solver> make_vertex_block_solver(Sparse_solver which)
{
#ifdef CGAL_MPM_HAS_CHOLMOD
  if(which == Sparse_solver::cholmod)
    return std::make_unique<Traits_solver<Eigen::CholmodSupernodalLLT<Sparse>>>();
#else
  (void)which;
#endif
  return std::make_unique<Traits_solver<Eigen::SimplicialLDLT<Sparse>>>();
}

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL
