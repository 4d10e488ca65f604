#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Shape_space.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

using namespace CGAL::MPM;

namespace {

Eigen::VectorXd flatten(const Point_matrix& p)
{
  Eigen::VectorXd v(3 * p.rows());
  for(Eigen::Index i = 0; i < p.rows(); ++i) v.segment<3>(3 * i) = p.row(i).transpose();
  return v;
}

Point_matrix unflatten(const Eigen::VectorXd& v)
{
  Point_matrix p(v.size() / 3, 3);
  for(Eigen::Index i = 0; i < p.rows(); ++i) p.row(i) = v.segment<3>(3 * i).transpose();
  return p;
}

// Modes orthogonal to the infinitesimal rigid motions of the mean: then the
// rigid placements of mean + B a (with centred a) are exactly a Procrustes
// fixed point, and the learned space must contain them to round-off.
struct Linear_family
{
  Point_matrix mean;
  Eigen::MatrixXd modes;

  Linear_family(int n, int d, std::mt19937& rng)
  {
    std::normal_distribution<double> g;
    mean = Point_matrix(n, 3);
    for(int i = 0; i < n; ++i) mean.row(i) << g(rng) * 3, g(rng) * 2, g(rng);
    mean.rowwise() -= mean.colwise().mean();
    Eigen::MatrixXd rigid(3 * n, 6);
    for(int i = 0; i < n; ++i)
    {
      const Eigen::Vector3d p = mean.row(i).transpose();
      rigid.block<3, 3>(3 * i, 0).setIdentity();
      rigid.block<3, 3>(3 * i, 3) << 0, p.z(), -p.y(), -p.z(), 0, p.x(), p.y(), -p.x(), 0;
    }
    Eigen::MatrixXd random(3 * n, d);
    for(Eigen::Index k = 0; k < random.size(); ++k) random.data()[k] = g(rng);
    Eigen::MatrixXd all(3 * n, 6 + d);
    all << rigid, random;
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(all);
    modes = (qr.householderQ() * Eigen::MatrixXd::Identity(3 * n, 6 + d)).rightCols(d);
  }

  Point_matrix shape(const Eigen::VectorXd& a) const { return mean + unflatten(modes * a); }
};

Rigid_motion random_motion(std::mt19937& rng)
{
  std::normal_distribution<double> g;
  Rigid_motion m;
  m.rotation = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
  m.translation = Eigen::Vector3d(g(rng), g(rng), g(rng)) * 10;
  return m;
}

} // namespace

TEST(Shape_space, rigid_motion_fit_recovers_motion)
{
  std::mt19937 rng(3);
  Linear_family family(40, 2, rng);
  const Rigid_motion m = random_motion(rng);
  const Rigid_motion fitted = fit_rigid_motion(family.mean, m.apply(family.mean));
  EXPECT_LT((fitted.rotation - m.rotation).norm(), 1e-12);
  EXPECT_LT((fitted.translation - m.translation).norm(), 1e-10);
  EXPECT_NEAR(fitted.rotation.determinant(), 1., 1e-12);
}

TEST(Shape_space, rigid_motion_fit_never_reflects)
{
  std::mt19937 rng(4);
  Linear_family family(30, 1, rng);
  Point_matrix mirrored = family.mean;
  mirrored.col(0) *= -1;
  const Rigid_motion fitted = fit_rigid_motion(family.mean, mirrored);
  EXPECT_NEAR(fitted.rotation.determinant(), 1., 1e-12);
}

TEST(Shape_space, contains_linear_instances_with_true_mode_count)
{
  std::mt19937 rng(7);
  const int n = 60, d = 3, m = 9;
  Linear_family family(n, d, rng);
  std::normal_distribution<double> g;
  Eigen::MatrixXd latent(d, m);
  for(Eigen::Index k = 0; k < latent.size(); ++k) latent.data()[k] = g(rng) * 0.5;
  latent.colwise() -= latent.rowwise().mean();
  std::vector<Point_matrix> instances;
  for(int j = 0; j < m; ++j) instances.push_back(random_motion(rng).apply(family.shape(latent.col(j))));

  const Shape_space space = learn_shape_space(instances);
  ASSERT_EQ(space.number_of_modes(), d);
  EXPECT_GE(space.explained_variance(d), 1. - 1e-12);
  for(double r : space.instance_residuals) EXPECT_LT(r, 1e-9);
  // The learned modes span the true ones (up to the Procrustes gauge rotation).
  const Rigid_motion gauge = fit_rigid_motion(family.mean, space.mean);
  Eigen::MatrixXd rotated(3 * n, d);
  for(int k = 0; k < d; ++k)
    rotated.col(k) = flatten(unflatten(family.modes.col(k)) * gauge.rotation.transpose());
  const Eigen::MatrixXd projection = space.modes * (space.modes.transpose() * rotated);
  EXPECT_LT((projection - rotated).norm(), 1e-8);
  // Modes are orthonormal and sigmas are the square roots of the variances.
  EXPECT_LT((space.modes.transpose() * space.modes - Eigen::MatrixXd::Identity(d, d)).norm(), 1e-10);
  for(int k = 0; k < d; ++k) EXPECT_NEAR(space.sigmas[k] * space.sigmas[k], space.variances[k], 1e-12);
  // Instance coordinates and motions reproduce each instance.
  for(int j = 0; j < m; ++j)
  {
    const Point_matrix rebuilt = space.instance_motions[j].apply(space.shape(space.instance_coordinates.col(j)));
    EXPECT_LT((rebuilt - instances[j]).norm(), 1e-8 * instances[j].norm());
  }
}

TEST(Shape_space, fit_recovers_coordinates_of_a_new_shape)
{
  std::mt19937 rng(11);
  Linear_family family(50, 2, rng);
  std::vector<Point_matrix> instances;
  const double a[5][2] = {{0.3, -0.1}, {-0.2, 0.2}, {0.1, 0.1}, {-0.3, -0.3}, {0.1, 0.1}};
  for(const auto& ai : a) instances.push_back(random_motion(rng).apply(family.shape(Eigen::Vector2d(ai[0], ai[1]))));
  const Shape_space space = learn_shape_space(instances);
  ASSERT_EQ(space.number_of_modes(), 2);
  const Point_matrix target = random_motion(rng).apply(family.shape(Eigen::Vector2d(0.05, -0.15)));
  Eigen::VectorXd coordinates;
  Rigid_motion motion;
  EXPECT_LT(space.fit(target, coordinates, motion), 1e-8);
  EXPECT_LT((motion.apply(space.shape(coordinates)) - target).norm(), 1e-7 * target.norm());
}

TEST(Shape_space, single_instance_is_its_own_mean)
{
  std::mt19937 rng(5);
  Linear_family family(20, 1, rng);
  const Point_matrix only = random_motion(rng).apply(family.mean);
  const Shape_space space = learn_shape_space({only});
  EXPECT_EQ(space.number_of_modes(), 0);
  EXPECT_EQ(space.number_of_instances(), 1);
  EXPECT_LT((space.mean - only).norm(), 1e-12);
  EXPECT_EQ(space.explained_variance(0), 1.);
}

TEST(Shape_space, explained_variance_threshold_and_fixed_mode_count)
{
  std::mt19937 rng(9);
  Linear_family family(40, 3, rng);
  std::vector<Point_matrix> instances;
  std::normal_distribution<double> g;
  // Variances 1 : 0.01 : 0.0001 along the three modes.
  for(int j = 0; j < 12; ++j)
    instances.push_back(family.shape(Eigen::Vector3d(g(rng), 0.1 * g(rng), 0.01 * g(rng))));
  Shape_space_options options;
  options.explained_variance = 0.9;
  EXPECT_EQ(learn_shape_space(instances, options).number_of_modes(), 1);
  options.modes = 3;
  EXPECT_EQ(learn_shape_space(instances, options).number_of_modes(), 3);
}

TEST(Shape_space, rejects_inconsistent_instances)
{
  Point_matrix a = Point_matrix::Random(10, 3), b = Point_matrix::Random(11, 3);
  EXPECT_THROW(learn_shape_space({a, b}), Computation_error);
  Point_matrix c = Point_matrix::Random(10, 3);
  c(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(learn_shape_space({a, c}), Computation_error);
}
