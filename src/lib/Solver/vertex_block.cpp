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

std::unique_ptr<Vertex_block> make_vertex_block(Sparse_solver which)
{
#ifdef CGAL_MPM_HAS_CHOLMOD
  if(which == Sparse_solver::cholmod)
    return std::make_unique<Factored_vertex_block<CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Sparse>>>>();
#else
  (void)which;
#endif
  return std::make_unique<Factored_vertex_block<CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Sparse>>>>();
}

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL
