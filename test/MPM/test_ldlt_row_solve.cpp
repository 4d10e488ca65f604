#include <CGAL/MPM/internal/Ldlt_row_solve.h>
#include <CGAL/MPM/internal/Vertex_block.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

using namespace CGAL::MPM;

namespace {

// The graph Laplacian of a synthetic hand's edges plus a small diagonal:
// the shape of the solver's vertex block (a mesh Laplacian and handle
// terms), symmetric positive definite.
Eigen::SparseMatrix<double> vertex_block_like(int vertices)
{
  Synthetic_options o;
  o.vertices = vertices;
  const Indexed_mesh mesh = make_synthetic_model(Synthetic_family::hand, o).mesh.mesh;
  std::vector<Eigen::Triplet<double>> t;
  for(const Triangle& f : mesh.triangles)
    for(int k = 0; k < 3; ++k)
    {
      const int a = f[std::size_t(k)], b = f[std::size_t((k + 1) % 3)];
      const double w = 0.5 + 0.1 * ((a + b) % 7);
      t.emplace_back(a, b, -w);
      t.emplace_back(b, a, -w);
      t.emplace_back(a, a, w);
      t.emplace_back(b, b, w);
    }
  for(int v = 0; v < mesh.number_of_vertices(); ++v) t.emplace_back(v, v, v % 97 == 0 ? 10. : 1e-3);
  Eigen::SparseMatrix<double> a(mesh.number_of_vertices(), mesh.number_of_vertices());
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

} // namespace

// One pass over the factor for all columns gives what Eigen's column by
// column solve gives (the same operations per column, up to the order in
// which a part's updates of the tree's top add up), for one, three (a
// displayed frame), a few (groups of every width the solve unrolls) and
// many columns (the set-up's batches, cut into groups solved in parallel),
// with the elimination tree whole or split into two or three parts.
TEST(Ldlt_row_solver, agrees_with_eigens_solve)
{
  const Eigen::SparseMatrix<double> a = vertex_block_like(3000);
  internal::Vertex_ldlt ldlt(a);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  for(const int parts : {1, 2, 3})
  {
    const internal::Ldlt_row_solver solver(ldlt, parts);
    EXPECT_EQ(solver.number_of_parts(), parts);
    for(const Eigen::Index columns : {1, 2, 3, 7, 50})
    {
      const Eigen::MatrixXd b = Eigen::MatrixXd::Random(a.rows(), columns);
      const Eigen::MatrixXd reference = ldlt.solve(b);
      const Eigen::MatrixXd rows = solver.solve(b);
      ASSERT_EQ(rows.rows(), reference.rows());
      ASSERT_EQ(rows.cols(), reference.cols());
      EXPECT_LE((rows - reference).norm(), 1e-13 * reference.norm()) << columns << " columns, " << parts << " parts";
      EXPECT_LT((a * rows - b).norm(), 1e-8 * b.norm()) << columns << " columns, " << parts << " parts";
    }
  }
}

// X^T A^-1 X for operands local to patches of the mesh (the solver's
// cluster operands), from the elimination tree, against solving every
// column through the whole factor (the reference) and against Eigen's
// solve. The operands overlap, one repeats a row (its values add up), and
// their widths differ.
TEST(Ldlt_inverse_gram, agrees_with_solving_every_column)
{
  const Eigen::SparseMatrix<double> a = vertex_block_like(3000);
  const std::unique_ptr<internal::embedding::Vertex_block> block =
    internal::embedding::make_vertex_block(Sparse_solver::simplicial_ldlt);
  ASSERT_TRUE(block->factor(a, Eigen::VectorXd::Zero(a.rows())));
  std::vector<internal::Local_columns> operands;
  const int n = static_cast<int>(a.rows());
  for(int first = 0, width = 3; first < n; first += n / 7, width = 3 + (width % 9))
  {
    internal::Local_columns o;
    for(int v = first; v < std::min(n, first + n / 5); ++v) o.rows.push_back(v);
    o.rows.push_back(first);
    o.values = Eigen::MatrixXd::Random(Eigen::Index(o.rows.size()), width);
    operands.push_back(std::move(o));
  }
  const std::vector<Eigen::Index> offset = internal::column_offsets(operands);
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, offset.back());
  for(std::size_t o = 0; o < operands.size(); ++o)
    for(std::size_t i = 0; i < operands[o].rows.size(); ++i)
      x.block(operands[o].rows[i], offset[o], 1, operands[o].values.cols()) += operands[o].values.row(Eigen::Index(i));
  internal::Vertex_ldlt ldlt(a);
  const Eigen::MatrixXd eigen = x.transpose() * ldlt.solve(x);
  const Eigen::MatrixXd reference = internal::embedding::inverse_gram_by_solves(*block, operands);
  const Eigen::MatrixXd tree = block->inverse_gram(operands);
  ASSERT_EQ(tree.rows(), offset.back());
  ASSERT_EQ(tree.cols(), offset.back());
  EXPECT_LE((reference - eigen).norm(), 1e-12 * eigen.norm());
  EXPECT_LE((tree - reference).norm(), 1e-12 * reference.norm());
  EXPECT_EQ(tree, tree.transpose());
}

// The vertex block's ordering is a permutation that gives the factor no
// more entries than Eigen's AMD (with CHOLMOD, SuiteSparse's AMD with the
// elimination tree postordered: fewer), and the same solutions.
TEST(Vertex_ordering, fills_no_more_than_eigens_amd)
{
  const Eigen::SparseMatrix<double> a = vertex_block_like(3000);
  internal::Vertex_ordering::PermutationType inverse;
  internal::Vertex_ordering()(Eigen::SparseMatrix<double>(a), inverse);
  ASSERT_EQ(inverse.size(), a.rows());
  std::vector<int> rows(inverse.indices().data(), inverse.indices().data() + inverse.size());
  std::sort(rows.begin(), rows.end());
  for(int i = 0; i < int(rows.size()); ++i) ASSERT_EQ(rows[std::size_t(i)], i);

  const internal::Vertex_ldlt ours(a);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> eigens(a);
  ASSERT_EQ(ours.info(), Eigen::Success);
  const Eigen::Index fill = ours.matrixL().nestedExpression().nonZeros();
  const Eigen::Index eigens_fill = eigens.matrixL().nestedExpression().nonZeros();
#ifdef CGAL_MPM_HAS_CHOLMOD
  EXPECT_LT(fill, eigens_fill);
#else
  EXPECT_EQ(fill, eigens_fill);
#endif
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(a.rows(), 3);
  EXPECT_LE((ours.solve(b) - eigens.solve(b)).norm(), 1e-12 * eigens.solve(b).norm());
}
