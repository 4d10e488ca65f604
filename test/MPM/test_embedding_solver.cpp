#include <CGAL/MPM/Editing/Arap_deformation.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include "Learned_models.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <functional>
#include <map>

using namespace CGAL::MPM;

namespace {

using mpm_test::diagonal;
using mpm_test::Learned;
using mpm_test::rows;

const Learned& learned(Synthetic_family family) { return mpm_test::learned(family, 3000); }

// One handle per part: the part vertex nearest to its centroid.
std::vector<int> handle_per_part(const Synthetic_model& s)
{
  std::vector<int> handles;
  for(const Synthetic_instance& i : s.instances)
  {
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for(int v : i.vertices) centroid += s.mesh.mesh.points.row(v);
    centroid /= double(i.vertices.size());
    int best = i.vertices.front();
    for(int v : i.vertices)
      if((s.mesh.mesh.points.row(v) - centroid).norm() < (s.mesh.mesh.points.row(best) - centroid).norm()) best = v;
    if(std::find(handles.begin(), handles.end(), best) == handles.end()) handles.push_back(best);
  }
  return handles;
}

class Solver_on_family : public ::testing::TestWithParam<Synthetic_family>
{};

} // namespace

// The fast paths (reduced: no vertex work per iteration; schur: one
// back-substitution per iteration) agree with the direct solve of the whole
// system, iteration by iteration.
TEST_P(Solver_on_family, fast_paths_agree_with_direct_every_iteration)
{
  const Learned& l = learned(GetParam());
  const Embedding_problem problem = make_deformation_problem(l.model);
  Embedding_options reduced, schur, direct;
  schur.global_step = Global_step::schur;
  direct.global_step = Global_step::direct;
  reduced.coupling_weight = schur.coupling_weight = direct.coupling_weight = 0.5;
  Embedding_solver a(problem, reduced), b(problem, schur), c(problem, direct);
  const std::vector<int> handles = handle_per_part(l.truth);
  const Point_matrix targets = rows(l.truth.draw_pose(7), handles);
  for(Embedding_solver* s : {&a, &b, &c}) s->set_handles(handles, targets);
  for(int it = 0; it < 5; ++it)
  {
    const double ea = a.iterate(), eb = b.iterate(), ec = c.iterate();
    EXPECT_NEAR(eb, ec, 1e-8 * std::abs(ec)) << "iteration " << it;
    // The reduced energy is a difference of two large sums (data term minus
    // b^T A^-1 b), exact only to about 1e-14 of the data term.
    EXPECT_NEAR(ea, ec, 1e-6 * std::abs(ec)) << "iteration " << it;
    EXPECT_LT((b.positions() - c.positions()).norm(), 1e-8 * c.positions().norm()) << "iteration " << it;
    EXPECT_LT((a.positions() - c.positions()).norm(), 1e-8 * c.positions().norm()) << "iteration " << it;
    for(int k = 0; k < a.number_of_clusters(); ++k)
    {
      EXPECT_LT((a.coordinates(k) - c.coordinates(k)).norm(), 1e-7 * (1. + c.coordinates(k).norm()));
      EXPECT_LT((b.coordinates(k) - c.coordinates(k)).norm(), 1e-7 * (1. + c.coordinates(k).norm()));
      EXPECT_LT((a.rotation(k) - c.rotation(k)).norm(), 1e-7);
    }
  }
}

// Newton's step on the rotations (the default) reaches the minimum the
// local/global steps reach when run to a tight tolerance (or a lower
// energy), never raising the energy, in a few iterations (measured 2-7):
// converging that fast needs the exact Hessian.
// A drag toward a held-out pose and the symmetrization, on every family.
TEST_P(Solver_on_family, newton_reaches_the_local_global_minimum_in_a_few_iterations)
{
  const Learned& l = learned(GetParam());
  const std::vector<int> handles = handle_per_part(l.truth);
  const Point_matrix targets = rows(l.truth.draw_pose(7), handles);
  for(const bool drag : {true, false})
  {
    SCOPED_TRACE(drag ? "drag" : "symmetrize");
    const Embedding_problem problem = drag ? make_deformation_problem(l.model) : make_symmetrization_problem(l.model);
    Embedding_options plain;
    plain.newton = plain.quasi_newton = false;
    plain.anderson_history = 0;
    plain.max_iterations = 20000;
    plain.tolerance = 1e-12;
    Embedding_solver newton(problem), reference(problem, plain);
    if(drag)
      for(Embedding_solver* s : {&newton, &reference}) s->set_handles(handles, targets);
    const Solve_report r = newton.solve();
    reference.solve(); // 105-3,150 iterations
    EXPECT_TRUE(r.converged);
    EXPECT_LE(r.iterations, 8); // 12-60 on four families with the coordinates left out of the Hessian
    for(std::size_t i = 1; i + 1 < r.energies.size(); ++i)
      EXPECT_LE(r.energies[i], r.energies[i - 1] + 1e-9 * r.energies.front()) << "iteration " << i;
    const double scale = l.truth.mesh.mesh.points.squaredNorm();
    // Positions are not compared: in the valleys these energies have, the
    // slow reference stops 1e-3 of the size away at the same energy.
    EXPECT_LE(newton.energy(), reference.energy() + 1e-6 * reference.energy() + 1e-12 * scale);
  }
}

// The angle of the rigid motion that best aligns `a` with `b`.
double turn_between(const Point_matrix& a, const Point_matrix& b)
{
  const Eigen::Matrix4d fit = Eigen::umeyama(Eigen::Matrix3Xd(a.transpose()), Eigen::Matrix3Xd(b.transpose()), false);
  return Eigen::AngleAxisd(Eigen::Matrix3d(fit.topLeftCorner<3, 3>())).angle();
}

// Turns the handles leave free cost no energy: a piece without handles
// turns about its anchored vertex, a hand held by two finger tips about the
// line between them. Newton's steps leave those turns out, so the result
// stays where local/global steps leave it: the hexa-grid's caricature turned
// by 0.008 rad against the input (0.086 rad before), the two-handle drag by
// 0.006 rad against the local/global result (0.28 rad before).
TEST(Embedding_solver, newton_steps_leave_out_the_turns_the_handles_leave_free)
{
  const Learned& grid = learned(Synthetic_family::hexa_grid);
  Embedding_solver caricature(make_caricature_problem(grid.model, 2.));
  ASSERT_TRUE(caricature.solve().converged);
  EXPECT_LT(turn_between(caricature.positions(), grid.truth.mesh.mesh.points), 0.02);

  const Learned& hand = learned(Synthetic_family::hand);
  const Point_matrix pose = hand.truth.draw_pose(101);
  const Handle_set tips = farthest_point_handles(hand.truth.mesh.mesh, 2, pose);
  Embedding_options plain;
  plain.newton = false;
  Embedding_solver newton(make_deformation_problem(hand.model)), reference(make_deformation_problem(hand.model), plain);
  for(Embedding_solver* s : {&newton, &reference})
  {
    s->set_handles(tips.vertices, tips.targets);
    ASSERT_TRUE(s->solve().converged);
  }
  EXPECT_LT(turn_between(newton.positions(), reference.positions()), 0.05);
}

// A drag gives the same handles new targets: the reduced step then reuses
// the solutions it keeps per handle set instead of a back-substitution, and
// still agrees with the direct reference, iteration by iteration.
TEST_P(Solver_on_family, new_targets_of_the_same_handles_agree_with_direct)
{
  const Learned& l = learned(GetParam());
  const Embedding_problem problem = make_deformation_problem(l.model);
  Embedding_options direct;
  direct.global_step = Global_step::direct;
  Embedding_solver reduced(problem), reference(problem, direct);
  const std::vector<int> handles = handle_per_part(l.truth);
  reduced.set_handles(handles, rows(l.truth.draw_pose(3), handles));
  reduced.preprocess();
  const Point_matrix targets = rows(l.truth.draw_pose(7), handles);
  reduced.set_handles(handles, targets);
  reference.set_handles(handles, targets);
  for(int it = 0; it < 3; ++it)
  {
    const double er = reduced.iterate(), ed = reference.iterate();
    EXPECT_NEAR(er, ed, 1e-6 * std::abs(ed)) << "iteration " << it;
    EXPECT_LT((reduced.positions() - reference.positions()).norm(), 1e-8 * reference.positions().norm())
      << "iteration " << it;
  }
}

TEST_P(Solver_on_family, rest_state_is_the_minimum)
{
  const Learned& l = learned(GetParam());
  Embedding_solver solver(make_deformation_problem(l.model));
  const std::vector<int> handles = handle_per_part(l.truth);
  solver.set_handles(handles, rows(l.truth.mesh.mesh.points, handles));
  const Solve_report report = solver.solve();
  const Point_matrix& rest = l.truth.mesh.mesh.points;
  EXPECT_LT((solver.positions() - rest).norm(), 1e-9 * rest.norm());
  EXPECT_LT(report.energy(), 1e-12 * rest.squaredNorm());
}

TEST_P(Solver_on_family, rigid_motion_of_all_handles_moves_the_input_rigidly)
{
  const Learned& l = learned(GetParam());
  Embedding_solver solver(make_deformation_problem(l.model));
  const std::vector<int> handles = handle_per_part(l.truth);
  Rigid_motion m;
  m.rotation = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  m.translation = Eigen::Vector3d(0.5, -2, 1);
  const Point_matrix moved = m.apply(l.truth.mesh.mesh.points);
  solver.set_handles(handles, rows(moved, handles));
  solver.solve();
  EXPECT_LT((solver.positions() - moved).norm(), 1e-8 * moved.norm());
}

TEST_P(Solver_on_family, caricature_factor_one_is_the_input)
{
  const Learned& l = learned(GetParam());
  Embedding_solver solver(make_caricature_problem(l.model, 1.));
  solver.solve();
  EXPECT_LT((solver.positions() - l.truth.mesh.mesh.points).norm(), 1e-9 * l.truth.mesh.mesh.points.norm());
}

// Sparse handles of a held-out pose (two per part): MPM reconstructs the
// pose better than CGAL's ARAP with the same handles, on every family.
TEST_P(Solver_on_family, held_out_pose_error_is_below_arap)
{
  const Learned& l = learned(GetParam());
  const Point_matrix pose = l.truth.draw_pose(5);
  const Handle_set handles = handles_per_part(l.truth.mesh, 2, pose);
  Embedding_solver mpm(make_deformation_problem(l.model));
  mpm.set_handles(handles.vertices, handles.targets);
  const Solve_report report = mpm.solve();
  Arap_deformation arap(l.truth.mesh.mesh);
  arap.set_handles(handles);
  arap.preprocess();
  const int arap_iterations = arap.deform(200, 1e-6);
  const double d = diagonal(pose), root_n = std::sqrt(double(pose.rows()));
  const double rest_error = (l.truth.mesh.mesh.points - pose).norm() / root_n / d;
  const double mpm_error = (mpm.positions() - pose).norm() / root_n / d;
  const double arap_error = (arap.positions() - pose).norm() / root_n / d;
  std::cout << family_name(GetParam()) << ": " << handles.vertices.size() << " handles, RMS error / diagonal: rest "
            << rest_error << ", ARAP " << arap_error << " (" << arap_iterations << " iterations), MPM " << mpm_error
            << " (" << report.iterations << " iterations)\n";
  EXPECT_LT(mpm_error, arap_error);
}

INSTANTIATE_TEST_SUITE_P(All, Solver_on_family, ::testing::ValuesIn(all_synthetic_families()),
                         [](const ::testing::TestParamInfo<Synthetic_family>& info) {
                           std::string name = family_name(info.param);
                           for(char& c : name)
                             if(c == '-') c = '_';
                           return name;
                         });

TEST(Embedding_solver, held_out_pose_from_handles_beats_the_rest_pose)
{
  const Learned& l = learned(Synthetic_family::hand);
  Embedding_solver solver(make_deformation_problem(l.model));
  const std::vector<int> handles = handle_per_part(l.truth);
  const Point_matrix pose = l.truth.draw_pose(3);
  solver.set_handles(handles, rows(pose, handles));
  const Solve_report report = solver.solve();
  const double d = diagonal(pose);
  const double rest_error = (l.truth.mesh.mesh.points - pose).norm() / std::sqrt(double(pose.rows())) / d;
  const double error = (solver.positions() - pose).norm() / std::sqrt(double(pose.rows())) / d;
  std::cout << "hand: rest RMS " << rest_error << ", MPM RMS " << error << " after " << report.iterations << " iterations\n";
  EXPECT_LT(error, 0.5 * rest_error);
  // Energies never increase (up to the rounding of the reduced energy).
  for(std::size_t i = 1; i < report.energies.size(); ++i)
    EXPECT_LE(report.energies[i], report.energies[i - 1] * (1 + 1e-7));
  EXPECT_NEAR(report.energy(), solver.energy(), 1e-12 * solver.energy());
}

TEST(Embedding_solver, rejects_bad_handles)
{
  const Learned& l = learned(Synthetic_family::hexa_grid);
  Embedding_solver solver(make_deformation_problem(l.model));
  const int n = l.truth.mesh.mesh.number_of_vertices();
  Point_matrix one = Point_matrix::Zero(1, 3);
  try
  {
    solver.set_handles({n + 5}, one);
    FAIL();
  }
  catch(const Input_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos);
  }
  Point_matrix nan = one;
  nan(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solver.set_handles({3}, nan), Input_error);
  EXPECT_THROW(solver.set_handles({3, 3}, Point_matrix::Zero(2, 3)), Input_error);
  // The solver still works after rejected input.
  solver.set_handles({3}, rows(l.truth.mesh.mesh.points, {3}));
  solver.solve();
  EXPECT_TRUE(solver.positions().allFinite());
}

TEST(Embedding_solver, rejects_bad_options)
{
  const Learned& l = learned(Synthetic_family::hexa_grid);
  const Embedding_problem problem = make_deformation_problem(l.model);
  const auto message = [&](Embedding_options o) {
    try
    {
      Embedding_solver solver(problem, o);
    }
    catch(const Input_error& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<std::string, std::function<void(Embedding_options&)>>> cases = {
    {"handle_weight", [](Embedding_options& o) { o.handle_weight = -1; }},
    {"anchor_weight", [&](Embedding_options& o) { o.anchor_weight = nan; }},
    {"coupling_weight", [](Embedding_options& o) { o.coupling_weight = -0.5; }},
    {"tolerance", [&](Embedding_options& o) { o.tolerance = inf; }},
    {"max_iterations", [](Embedding_options& o) { o.max_iterations = -3; }},
    {"anderson_history", [](Embedding_options& o) { o.anderson_history = -1; }}};
  for(const auto& [option, spoil] : cases)
  {
    Embedding_options o;
    spoil(o);
    EXPECT_NE(message(o).find(option), std::string::npos) << option;
  }
}

// A target far beyond what doubles can square: every global step fails, the
// error names the handle, and the solver keeps the state it had.
class Overflowing_handle : public ::testing::TestWithParam<Global_step>
{};

TEST_P(Overflowing_handle, fails_naming_the_handle_and_keeps_the_state)
{
  const Learned& l = learned(Synthetic_family::hand);
  Embedding_options options;
  options.global_step = GetParam();
  Embedding_solver solver(make_deformation_problem(l.model), options);
  const std::vector<int> handles = handle_per_part(l.truth);
  const Point_matrix pose = l.truth.draw_pose(3);
  solver.set_handles(handles, rows(pose, handles));
  solver.solve();
  const Point_matrix before = solver.positions();
  const double energy_before = solver.energy();
  Point_matrix far = rows(pose, handles);
  far(1, 0) = 1e200;
  solver.set_handles(handles, far);
  try
  {
    solver.solve();
    FAIL() << "no error";
  }
  catch(const Computation_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("handle 1 "), std::string::npos) << e.what();
  }
  EXPECT_EQ((solver.positions() - before).norm(), 0.);
  // Back to reasonable targets, the solve goes on from the kept state.
  solver.set_handles(handles, rows(pose, handles));
  EXPECT_NEAR(solver.energy(), energy_before, 1e-9 * energy_before);
  solver.solve();
  EXPECT_TRUE(solver.positions().allFinite());
  EXPECT_LE(solver.energy(), energy_before * (1 + 1e-9));
}

INSTANTIATE_TEST_SUITE_P(All_global_steps, Overflowing_handle,
                         ::testing::Values(Global_step::reduced, Global_step::schur, Global_step::direct));

// A sub-part deviation so small that its stiffness overflows: the factorization
// cannot be positive definite, and the error names a part instead of
// returning NaN positions.
TEST(Embedding_solver, overflowing_stiffness_is_a_named_factorization_failure)
{
  const Learned& l = learned(Synthetic_family::hexa_grid);
  Embedding_problem problem = make_deformation_problem(l.model);
  problem.sigma_sub = 1e-160;
  try
  {
    Embedding_solver solver(problem);
    solver.set_handles({3}, rows(l.truth.mesh.mesh.points, {3}));
    solver.solve();
    FAIL() << "no error; positions finite: " << solver.positions().allFinite();
  }
  catch(const Computation_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
}

namespace {

// Instances of each multi-instance type, in correspondence, from positions `x`.
std::map<int, std::vector<Point_matrix>> instances_by_type(const Morphable_part_model& model, const Point_matrix& x)
{
  std::map<int, std::vector<Point_matrix>> r;
  for(const Part_node& node : model.examples[0].graph.nodes)
    if(model.types[node.type].space.number_of_instances() > 1) r[node.type].push_back(rows(x, node.vertices));
  return r;
}

// Variance across instances after generalized Procrustes alignment.
double variance_across_instances(const std::vector<Point_matrix>& instances)
{
  return learn_shape_space(instances).total_variance();
}

Eigen::Vector3d face_normal(const Point_matrix& x, const Triangle& t)
{
  const Eigen::Vector3d a = x.row(t[0]), b = x.row(t[1]), c = x.row(t[2]);
  return (b - a).cross(c - a);
}

// Faces whose normal turns over relative to their part's best rigid motion.
int flipped_faces(const Morphable_part_model& model, const Point_matrix& before, const Point_matrix& after)
{
  int flips = 0;
  for(const Part_node& node : model.examples[0].graph.nodes)
  {
    const Rigid_motion m = fit_rigid_motion(rows(before, node.vertices), rows(after, node.vertices));
    for(const Triangle& local : model.types[node.type].triangles)
    {
      const Triangle t = {node.vertices[local[0]], node.vertices[local[1]], node.vertices[local[2]]};
      if(face_normal(after, t).dot(m.rotation * face_normal(before, t)) <= 0) ++flips;
    }
  }
  return flips;
}

class Symmetrize : public ::testing::TestWithParam<Synthetic_family>
{};

} // namespace

TEST_P(Symmetrize, variance_drops_by_95_percent_without_flips)
{
  const Learned& l = learned(GetParam());
  Embedding_solver solver(make_symmetrization_problem(l.model));
  const Solve_report report = solver.solve();
  const Point_matrix& input = l.truth.mesh.mesh.points;
  ASSERT_TRUE(solver.positions().allFinite());
  const auto before = instances_by_type(l.model, input);
  const auto after = instances_by_type(l.model, solver.positions());
  ASSERT_FALSE(before.empty());
  for(const auto& [type, instances] : before)
  {
    const double v0 = variance_across_instances(instances), v1 = variance_across_instances(after.at(type));
    std::cout << family_name(GetParam()) << " " << l.model.types[type].name << ": variance " << v0 << " -> " << v1
              << " (" << 100 * (1 - v1 / v0) << "% less), " << report.iterations << " iterations\n";
    EXPECT_LT(v1, 0.05 * v0) << l.model.types[type].name;
  }
  EXPECT_EQ(flipped_faces(l.model, input, solver.positions()), 0);
}

INSTANTIATE_TEST_SUITE_P(Hexa_grid_and_hand, Symmetrize,
                         ::testing::Values(Synthetic_family::hexa_grid, Synthetic_family::hand),
                         [](const ::testing::TestParamInfo<Synthetic_family>& info) {
                           return info.param == Synthetic_family::hand ? std::string("hand") : std::string("hexa_grid");
                         });

TEST(Caricature, factor_two_doubles_the_distance_from_the_mean_within_the_subspace)
{
  // The hexa-grid varies linearly: doubling is exact up to the solver's
  // tolerance. The hand's bends are not linear in its modes, so doubled
  // coordinates of neighbouring segments disagree slightly at their seams.
  const std::pair<Synthetic_family, double> cases[] = {{Synthetic_family::hexa_grid, 0.01},
                                                       {Synthetic_family::hand, 0.05}};
  for(const auto& [family, bound] : cases)
  {
    const Learned& l = learned(family);
    Embedding_options options;
    options.max_iterations = 5000;
    options.tolerance = 1e-10;
    Embedding_solver solver(make_caricature_problem(l.model, 2.), options);
    solver.solve();
    double worst = 0.;
    for(const Part_node& node : l.model.examples[0].graph.nodes)
    {
      const Shape_space& space = l.model.types[node.type].space;
      if(space.number_of_modes() == 0) continue;
      Eigen::VectorXd fitted;
      Rigid_motion motion;
      space.fit(rows(solver.positions(), node.vertices), fitted, motion);
      worst = std::max(worst, (fitted - 2 * node.coordinates).norm() / node.coordinates.norm());
    }
    std::cout << family_name(family) << ": caricature coordinates within " << 100 * worst << "% of twice the input's\n";
    EXPECT_LT(worst, bound) << family_name(family);
  }
}

TEST(Embedding_solver, per_vertex_rotations_keep_rest_and_rigid_motions_and_decrease_the_energy)
{
  const Learned& l = learned(Synthetic_family::hand);
  Embedding_options options;
  options.rotations = Rotations::per_vertex;
  options.max_iterations = 20;
  const std::vector<int> handles = handle_per_part(l.truth);
  const Point_matrix& rest = l.truth.mesh.mesh.points;
  {
    Embedding_solver solver(make_deformation_problem(l.model), options);
    solver.set_handles(handles, rows(rest, handles));
    solver.solve();
    EXPECT_LT((solver.positions() - rest).norm(), 1e-9 * rest.norm());
  }
  {
    Rigid_motion m;
    m.rotation = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
    m.translation = Eigen::Vector3d(1, 2, 3);
    Embedding_solver solver(make_deformation_problem(l.model), options);
    solver.set_handles(handles, rows(m.apply(rest), handles));
    solver.solve();
    EXPECT_LT((solver.positions() - m.apply(rest)).norm(), 1e-8 * rest.norm());
  }
  Embedding_solver solver(make_deformation_problem(l.model), options);
  const Point_matrix pose = l.truth.draw_pose(3);
  solver.set_handles(handles, rows(pose, handles));
  const Solve_report report = solver.solve();
  for(std::size_t i = 1; i < report.energies.size(); ++i)
    EXPECT_LE(report.energies[i], report.energies[i - 1] * (1 + 1e-9));
  EXPECT_TRUE(solver.positions().allFinite());
}

// Changing the handle vertices is a low-rank update of the factored block:
// after adding and removing handles, every path agrees with a solver that
// factored the new handle set from scratch.
TEST(Embedding_solver, handle_set_change_by_low_rank_update_equals_refactoring)
{
  const Learned& l = learned(Synthetic_family::hand);
  const Embedding_problem problem = make_deformation_problem(l.model);
  const Point_matrix pose = l.truth.draw_pose(5);
  std::vector<int> first = handle_per_part(l.truth);
  std::vector<int> second(first.begin() + 2, first.end()); // two removed
  for(int v : {11, 222, 1333}) second.push_back(v);          // three added
  for(Global_step step : {Global_step::reduced, Global_step::schur, Global_step::direct})
  {
    Embedding_options options;
    options.global_step = step;
    Embedding_solver updated(problem, options), fresh(problem, options);
    updated.set_handles(first, rows(pose, first));
    updated.iterate(); // factors the first handle set
    updated.reset();
    updated.set_handles(second, rows(pose, second));
    fresh.set_handles(second, rows(pose, second));
    for(int it = 0; it < 4; ++it)
    {
      const double eu = updated.iterate(), ef = fresh.iterate();
      EXPECT_NEAR(eu, ef, 1e-6 * ef);
      EXPECT_LT((updated.positions() - fresh.positions()).norm(), 1e-8 * fresh.positions().norm())
        << "global step " << int(step) << ", iteration " << it;
    }
  }
}

// A solver preprocessed before any handle (a model just loaded) takes each
// later handle set as a low-rank update, also one that holds pieces the
// factored block anchored (the spine's separate vertebrae): positions and
// energies agree with a solver factored for that handle set from scratch,
// and no refactorization is needed for sets of up to 64 changed entries.
TEST(Embedding_solver, handle_sets_on_a_solver_factored_without_handles_equal_refactoring)
{
  for(Synthetic_family family : {Synthetic_family::hand, Synthetic_family::spine})
  {
    const Learned& l = learned(family);
    const Embedding_problem problem = make_deformation_problem(l.model);
    const Point_matrix pose = l.truth.draw_pose(5);
    const std::vector<int> first = handle_per_part(l.truth);
    const std::vector<int> second(first.begin(), first.begin() + first.size() / 2);
    Embedding_solver loaded(problem);
    loaded.preprocess();
    for(const std::vector<int>& handles : {first, second})
    {
      Embedding_solver fresh(problem);
      loaded.reset();
      loaded.set_handles(handles, rows(pose, handles));
      fresh.set_handles(handles, rows(pose, handles));
      const Solve_report ru = loaded.solve(), rf = fresh.solve();
      SCOPED_TRACE(family_name(family) + ", " + std::to_string(handles.size()) + " handles");
      EXPECT_EQ(ru.iterations, rf.iterations);
      // Reduced energies are differences of large sums (the handles' stiffness
      // times their squared targets), exact to about 1e-7 of themselves here.
      for(std::size_t i = 0; i < std::min(ru.energies.size(), rf.energies.size()); ++i)
        EXPECT_NEAR(ru.energies[i], rf.energies[i], 1e-6 * rf.energies[0]) << "iteration " << i + 1;
      EXPECT_NEAR(ru.energy(), rf.energy(), 1e-9 * rf.energy()) << "at the positions";
      EXPECT_LT((loaded.positions() - fresh.positions()).norm(), 1e-8 * fresh.positions().norm());
    }
  }
}

// A drag of the synthetic hand: a handle on every part, the first moved
// by half a percent of the diagonal each frame.
struct Hand_drag
{
  const Learned& l = learned(Synthetic_family::hand);
  const Embedding_problem problem = make_deformation_problem(l.model);
  const std::vector<int> handles = handle_per_part(l.truth);
  const Point_matrix& rest = problem.mesh.points;
  const Eigen::RowVector3d step = 0.005 * diagonal(rest) * Eigen::RowVector3d(1., 0.5, 0.);
};

// A drag: one handle moved a little each frame, each frame solved to
// convergence. Starting where the clusters turn once more as they turned
// in the frame before lands where starting at the last frame's solution
// lands (the same minimum, within the tolerance's reach), in fewer
// iterations, and each solve's energy still never increases.
TEST(Embedding_solver, drag_frames_start_at_predicted_rotations)
{
  const Hand_drag drag;
  const auto& [l, problem, handles, rest, step] = drag;
  Embedding_options plain;
  plain.predict_rotations = false;
  Embedding_solver predicted(problem), unpredicted(problem, plain);
  Point_matrix targets = rows(rest, handles);
  int iterations_predicted = 0, iterations_plain = 0;
  for(int frame = 0; frame < 10; ++frame)
  {
    targets.row(0) += step;
    predicted.set_handles(handles, targets);
    unpredicted.set_handles(handles, targets);
    const Solve_report a = predicted.solve(), b = unpredicted.solve();
    ASSERT_TRUE(a.converged && b.converged) << "frame " << frame;
    // The last energy is evaluated exactly at the positions, the others from
    // blocks (they differ by about 1e-7 here): the iterations' own.
    for(std::size_t k = 1; k + 1 < a.energies.size(); ++k) EXPECT_LE(a.energies[k], a.energies[k - 1]) << "frame " << frame;
    EXPECT_LT((predicted.positions() - unpredicted.positions()).cwiseAbs().maxCoeff(), 1e-4 * diagonal(rest))
      << "frame " << frame;
    if(frame >= 2)
    {
      iterations_predicted += a.iterations;
      iterations_plain += b.iterations;
    }
  }
  EXPECT_LT(iterations_predicted, iterations_plain);
}

// Newton's step predicts what the next one would remove: a drag frame stops
// on that, without an iteration that only confirms convergence (two per
// frame before), and the prediction holds: each frame's energy is within
// the tolerance of the minimum (a solve from rest to 1e-12).
TEST(Embedding_solver, drag_frames_stop_when_the_next_newton_step_would_not_pay)
{
  const Hand_drag drag;
  const auto& [l, problem, handles, rest, step] = drag;
  Embedding_solver solver(problem);
  Point_matrix targets = rows(rest, handles);
  const double tolerance = Embedding_options().tolerance;
  int iterations = 0;
  for(int frame = 0; frame < 12; ++frame)
  {
    targets.row(0) += step;
    solver.set_handles(handles, targets);
    const Solve_report report = solver.solve();
    ASSERT_TRUE(report.converged) << "frame " << frame;
    if(frame >= 2) iterations += report.iterations;
    Embedding_options tight;
    tight.tolerance = 1e-12;
    Embedding_solver again(problem, tight);
    again.set_handles(handles, targets);
    const double converged = again.solve().energy();
    EXPECT_LE(report.energy() - converged, tolerance * converged) << "frame " << frame;
  }
  EXPECT_LE(iterations, 12) << "10 frames";
}
