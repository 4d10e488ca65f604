#include <CGAL/MPM/internal/Ldlt_row_solve.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <gtest/gtest.h>

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
// column solve gives (the same operations in the same order per column),
// for one, three (a displayed frame), a few (groups of every width the
// solve unrolls) and many columns (the set-up's batches, cut into groups
// solved in parallel).
TEST(Ldlt_row_solve, agrees_with_eigens_solve)
{
  const Eigen::SparseMatrix<double> a = vertex_block_like(3000);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(a);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  for(const Eigen::Index columns : {1, 2, 3, 7, 50})
  {
    const Eigen::MatrixXd b = Eigen::MatrixXd::Random(a.rows(), columns);
    const Eigen::MatrixXd reference = ldlt.solve(b);
    const Eigen::MatrixXd rows = internal::ldlt_solve_rows(ldlt, b);
    ASSERT_EQ(rows.rows(), reference.rows());
    ASSERT_EQ(rows.cols(), reference.cols());
    EXPECT_LE((rows - reference).norm(), 1e-13 * reference.norm()) << columns << " columns";
    EXPECT_LT((a * rows - b).norm(), 1e-8 * b.norm()) << columns << " columns";
  }
}
