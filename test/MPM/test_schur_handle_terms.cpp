#include <CGAL/MPM/internal/Schur_blocks.h>

#include <gtest/gtest.h>

#include <vector>

using namespace CGAL::MPM;
using namespace CGAL::MPM::internal::embedding;

namespace {

// Two clusters sharing a vertex, with two and one modes: random Laplacian
// operands stand in for L M and L B (the handle terms only multiply them).
std::vector<Cluster_data> two_clusters(int n)
{
  std::vector<Cluster_data> clusters(2);
  for(int c = 0; c < 2; ++c)
  {
    Cluster_data& d = clusters[std::size_t(c)];
    for(int v = c * (n / 2 - 1); v < (c == 0 ? n / 2 : n); ++v) d.vertices.push_back(v);
    const Eigen::Index size = Eigen::Index(d.vertices.size());
    d.laplacian_mean = Point_matrix::Random(size, 3);
    const int modes = c == 0 ? 2 : 1;
    for(int k = 0; k < modes; ++k)
    {
      d.modes.push_back(Point_matrix::Random(size, 3));
      d.laplacian_modes.push_back(Point_matrix::Random(size, 3));
    }
    d.offset = c == 0 ? 0 : 2;
  }
  return clusters;
}

} // namespace

// A drag sets the handle terms from a basis computed once per handle set
// (affine in the targets); they must be those of the reference, which
// takes b0 and z = A^-1 b0 over all vertices.
TEST(SchurHandleTerms, the_basis_at_the_targets_is_the_reference)
{
  const int n = 40, k = 3;
  const std::vector<Cluster_data> clusters = two_clusters(n);
  const std::vector<int> handles{3, 17, 38};
  const Point_matrix anchor_rhs = Point_matrix::Random(n, 3), anchor_solution = Point_matrix::Random(n, 3);
  const Eigen::MatrixXd handle_columns = Eigen::MatrixXd::Random(n, k);

  Schur_blocks reference, fast;
  reference.mode_gram = fast.mode_gram = Eigen::MatrixXd::Zero(3, 3);
  fast.set_handle_basis(clusters, anchor_rhs, anchor_solution, handles, handle_columns);
  for(int frame = 0; frame < 2; ++frame)
  {
    const Eigen::MatrixXd targets = Eigen::MatrixXd::Random(k, 3);
    Point_matrix b0 = anchor_rhs;
    for(int h = 0; h < k; ++h) b0.row(handles[std::size_t(h)]) += targets.row(h);
    reference.set_handle_terms(clusters, b0, anchor_solution + handle_columns * targets);
    fast.set_handle_targets(targets);

    EXPECT_NEAR(fast.b0_z, reference.b0_z, 1e-12 * std::abs(reference.b0_z));
    ASSERT_EQ(fast.z_blocks.size(), 3u);
    for(std::size_t a = 0; a < 3; ++a) EXPECT_LT((fast.z_blocks[a] - reference.z_blocks[a]).norm(), 1e-12) << "mode " << a;
    ASSERT_EQ(fast.zlm_blocks.size(), 2u);
    for(std::size_t c = 0; c < 2; ++c)
      EXPECT_LT((fast.zlm_blocks[c] - reference.zlm_blocks[c]).norm(), 1e-12) << "cluster " << c;
  }
}
