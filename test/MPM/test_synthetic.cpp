// The synthetic generators: mesh validity, ground-truth correspondence,
// determinism, held-out poses, shape spaces and dockings.
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Shape_space.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

using namespace CGAL::MPM;

namespace {

int small_size(Synthetic_family f)
{
  switch(f)
  {
  case Synthetic_family::spider: return 4000;
  case Synthetic_family::hand: return 3000;
  default: return 2000;
  }
}

Synthetic_options small_options(Synthetic_family f)
{
  Synthetic_options o;
  o.vertices = small_size(f);
  return o;
}

bool boundary_docked(Synthetic_family f)
{
  return f == Synthetic_family::hexa_grid || f == Synthetic_family::hand || f == Synthetic_family::spider;
}

// The faces of one label in global order, renumbered by first appearance.
struct Local_part
{
  std::vector<int> vertices;       // mesh vertex of each local vertex
  std::vector<Triangle> triangles; // local faces
};

Local_part local_part(const Labeled_mesh& m, int label)
{
  Local_part part;
  std::unordered_map<int, int> local;
  for(std::size_t f = 0; f < m.face_labels.size(); ++f)
  {
    if(m.face_labels[f] != label) continue;
    Triangle t;
    for(int k = 0; k < 3; ++k)
    {
      const int v = m.mesh.triangles[f][k];
      auto it = local.emplace(v, static_cast<int>(part.vertices.size())).first;
      if(it->second == static_cast<int>(part.vertices.size())) part.vertices.push_back(v);
      t[k] = it->second;
    }
    part.triangles.push_back(t);
  }
  return part;
}

Point_matrix instance_points(const Synthetic_model& s, const Synthetic_instance& i)
{
  Point_matrix p(static_cast<Eigen::Index>(i.vertices.size()), 3);
  for(std::size_t k = 0; k < i.vertices.size(); ++k) p.row(static_cast<Eigen::Index>(k)) = s.mesh.mesh.points.row(i.vertices[k]);
  return p;
}

std::pair<int, int> ordered(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Smallest vertex-to-vertex distance between two point sets (brute force
// after a bounding-box test).
double min_distance(const Point_matrix& a, const Point_matrix& b, double cutoff)
{
  const Eigen::RowVector3d alo = a.colwise().minCoeff(), ahi = a.colwise().maxCoeff();
  const Eigen::RowVector3d blo = b.colwise().minCoeff(), bhi = b.colwise().maxCoeff();
  const Eigen::RowVector3d gap = (blo - ahi).cwiseMax(alo - bhi).cwiseMax(0.);
  if(gap.norm() > cutoff) return gap.norm();
  double best = std::numeric_limits<double>::infinity();
  for(Eigen::Index i = 0; i < a.rows(); ++i)
    best = std::min(best, std::sqrt((b.rowwise() - a.row(i)).rowwise().squaredNorm().minCoeff()));
  return best;
}

class Synthetic : public ::testing::TestWithParam<Synthetic_family> {};

} // namespace

TEST(Synthetic_names, round_trip_and_unknown)
{
  for(Synthetic_family f : all_synthetic_families()) EXPECT_EQ(parse_family(family_name(f)), f);
  EXPECT_EQ(all_synthetic_families().size(), 5u);
  try
  {
    parse_family("octopus");
    FAIL() << "no exception";
  }
  catch(const Input_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("hexa-grid"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("octopus"), std::string::npos);
  }
}

namespace {

// Labels, parameters, validity and orientation of one generated mesh.
void check_mesh(const Synthetic_model& s)
{
  const Indexed_mesh& m = s.mesh.mesh;
  const int n = m.number_of_vertices();
  ASSERT_EQ(s.mesh.face_labels.size(), m.triangles.size());
  const int parts = static_cast<int>(s.instances.size());
  ASSERT_GT(parts, 1);
  for(int l : s.mesh.face_labels) ASSERT_TRUE(l >= 0 && l < parts);
  ASSERT_EQ(static_cast<int>(s.annotation.part_type_of_label.size()), parts);
  for(int l = 0; l < parts; ++l)
  {
    EXPECT_EQ(s.instances[l].label, l);
    EXPECT_EQ(s.annotation.part_type_of_label.at(l), s.instances[l].type);
  }
  EXPECT_TRUE(m.points.allFinite());
  EXPECT_GT(s.annotation.parameters.docking_radius, 0.);
  EXPECT_LT(s.annotation.parameters.sigma_bound, 0.);
  EXPECT_LT(s.annotation.parameters.sigma_sub, 0.);
  EXPECT_EQ(s.annotation.parameters.explained_variance, 0.99);
  EXPECT_GT(s.expected_rules, 0);

  // Every vertex is used; no degenerate or duplicate faces; consistent
  // orientation (each directed edge once, each edge in at most two faces).
  const double diagonal = (m.points.colwise().maxCoeff() - m.points.colwise().minCoeff()).norm();
  std::vector<bool> used(n, false);
  std::set<std::array<int, 3>> faces;
  std::set<std::pair<int, int>> directed;
  std::map<std::pair<int, int>, int> faces_of_edge;
  for(const Triangle& t : m.triangles)
  {
    const Eigen::Vector3d a = m.points.row(t[0]), b = m.points.row(t[1]), c = m.points.row(t[2]);
    ASSERT_GT((b - a).cross(c - a).norm(), 1e-10 * diagonal * diagonal);
    std::array<int, 3> key = t;
    std::sort(key.begin(), key.end());
    ASSERT_TRUE(faces.insert(key).second) << "duplicate face";
    for(int k = 0; k < 3; ++k)
    {
      used[t[k]] = true;
      ASSERT_TRUE(directed.insert({t[k], t[(k + 1) % 3]}).second) << "inconsistent orientation";
      ++faces_of_edge[ordered(t[k], t[(k + 1) % 3])];
    }
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
  for(const auto& [e, count] : faces_of_edge) ASSERT_LE(count, 2);

  // Outward orientation: each closed component has a positive signed volume.
  std::vector<int> component(n);
  std::iota(component.begin(), component.end(), 0);
  std::function<int(int)> find = [&](int v) { return component[v] == v ? v : component[v] = find(component[v]); };
  for(const Triangle& t : m.triangles)
    for(int k = 1; k < 3; ++k) component[find(t[k])] = find(t[0]);
  std::map<int, double> volume;
  std::map<int, bool> closed;
  for(const auto& [e, count] : faces_of_edge) closed.emplace(find(e.first), true).first->second &= count == 2;
  for(const Triangle& t : m.triangles)
  {
    const Eigen::Vector3d a = m.points.row(t[0]), b = m.points.row(t[1]), c = m.points.row(t[2]);
    volume[find(t[0])] += a.dot(b.cross(c)) / 6.;
  }
  int closed_components = 0;
  for(const auto& [c, v] : volume)
    if(closed[c])
    {
      ++closed_components;
      EXPECT_GT(v, 0.) << "component " << c;
    }
  if(s.family == Synthetic_family::hand || s.family == Synthetic_family::spider)
  {
    EXPECT_EQ(closed_components, 1); // watertight
  }
  else if(s.family == Synthetic_family::spine)
  {
    EXPECT_EQ(closed_components, parts);
  }
  else if(s.family == Synthetic_family::facade)
  {
    EXPECT_EQ(closed_components, parts - 1); // all but the wall
  }
}

} // namespace

TEST_P(Synthetic, mesh_is_valid_and_labelled_at_every_size)
{
  for(int size : {1500, small_size(GetParam()), 0})
  {
    SCOPED_TRACE(size);
    Synthetic_options o;
    o.vertices = size;
    const Synthetic_model s = make_synthetic_model(GetParam(), o);
    if(size > 0) EXPECT_NEAR(s.mesh.mesh.number_of_vertices(), size, 0.25 * size);
    check_mesh(s);
  }
}

TEST_P(Synthetic, correspondence_follows_first_appearance)
{
  const Synthetic_model s = make_synthetic_model(GetParam(), small_options(GetParam()));
  std::map<std::string, std::vector<Triangle>> connectivity;
  std::map<std::string, int> count;
  for(const Synthetic_instance& i : s.instances)
  {
    const Local_part p = local_part(s.mesh, i.label);
    EXPECT_EQ(p.vertices, i.vertices) << "label " << i.label;
    auto inserted = connectivity.emplace(i.type, p.triangles);
    if(!inserted.second)
    {
      EXPECT_EQ(inserted.first->second, p.triangles) << "label " << i.label;
    }
    ++count[i.type];
  }
  ASSERT_EQ(connectivity.size(), s.types.size());
  for(const Synthetic_type& t : s.types)
  {
    ASSERT_TRUE(count.count(t.name)) << t.name;
    if(count[t.name] == 1) EXPECT_EQ(t.modes, 0) << t.name;
    else EXPECT_GT(t.modes, 0) << t.name;
  }
  for(const Synthetic_instance& i : s.instances)
  {
    const auto t = std::find_if(s.types.begin(), s.types.end(), [&](const Synthetic_type& x) { return x.name == i.type; });
    EXPECT_EQ(static_cast<int>(i.latent.size()), t->modes);
  }
}

TEST_P(Synthetic, deterministic_and_held_out_poses)
{
  const Synthetic_options o = small_options(GetParam());
  const Synthetic_model a = make_synthetic_model(GetParam(), o);
  const Synthetic_model b = make_synthetic_model(GetParam(), o);
  EXPECT_TRUE(a.mesh.mesh.points == b.mesh.mesh.points); // bit-identical
  EXPECT_EQ(a.mesh.mesh.triangles, b.mesh.mesh.triangles);
  EXPECT_EQ(a.mesh.face_labels, b.mesh.face_labels);
  EXPECT_EQ(a.expected_rules, b.expected_rules);

  Synthetic_options pose = o;
  pose.held_out_pose = true;
  pose.pose_seed = 7;
  const Synthetic_model p = make_synthetic_model(GetParam(), pose);
  EXPECT_EQ(p.mesh.mesh.triangles, a.mesh.mesh.triangles);
  EXPECT_EQ(p.mesh.face_labels, a.mesh.face_labels);
  ASSERT_EQ(p.mesh.mesh.points.rows(), a.mesh.mesh.points.rows());
  EXPECT_GT((p.mesh.mesh.points - a.mesh.mesh.points).norm(), 1e-3 * a.mesh.mesh.points.norm());
  EXPECT_TRUE(a.draw_pose(7) == p.mesh.mesh.points);
  EXPECT_FALSE(a.draw_pose(8) == p.mesh.mesh.points);
  for(std::size_t i = 0; i < a.instances.size(); ++i) EXPECT_EQ(a.instances[i].vertices, p.instances[i].vertices);

  // Another seed changes only the shapes.
  Synthetic_options other = o;
  other.seed = 2;
  const Synthetic_model c = make_synthetic_model(GetParam(), other);
  EXPECT_EQ(c.mesh.mesh.triangles, a.mesh.mesh.triangles);
  EXPECT_FALSE(c.mesh.mesh.points == a.mesh.mesh.points);
}

TEST_P(Synthetic, shape_spaces_have_the_true_modes)
{
  const Synthetic_model s = make_synthetic_model(GetParam(), small_options(GetParam()));
  for(const Synthetic_type& t : s.types)
  {
    SCOPED_TRACE(t.name);
    std::vector<Point_matrix> instances;
    Eigen::MatrixXd latents(t.modes, 0);
    for(const Synthetic_instance& i : s.instances)
      if(i.type == t.name)
      {
        instances.push_back(instance_points(s, i));
        latents.conservativeResize(Eigen::NoChange, latents.cols() + 1);
        latents.col(latents.cols() - 1) = Eigen::Map<const Eigen::VectorXd>(i.latent.data(), t.modes);
      }
    if(instances.size() < 2) continue;
    if(t.linear) // training latents are centred
    {
      EXPECT_LT(latents.rowwise().mean().norm(), 1e-12);
    }
    // Shapes differ beyond rigid motion.
    const double size = (instances[0].rowwise() - instances[0].colwise().mean()).norm();
    for(std::size_t j = 1; j < instances.size(); ++j)
    {
      const Rigid_motion r = fit_rigid_motion(instances[j], instances[0]);
      EXPECT_GT((r.apply(instances[j]) - instances[0]).norm(), 1e-3 * size) << "instance " << j;
    }
    Shape_space_options options;
    options.modes = t.modes;
    const Shape_space space = learn_shape_space(instances, options);
    EXPECT_EQ(space.number_of_modes(), std::min<int>(t.modes, static_cast<int>(instances.size()) - 1));
    EXPECT_GE(space.explained_variance(t.modes), 0.99);
    if(t.linear)
    {
      for(double r : space.instance_residuals) EXPECT_LT(r, 1e-6);
    }
  }
}

TEST_P(Synthetic, dockings_match_the_geometry)
{
  const Synthetic_model s = make_synthetic_model(GetParam(), small_options(GetParam()));
  const Indexed_mesh& m = s.mesh.mesh;
  std::set<std::pair<int, int>> connected;
  for(const Synthetic_connection& c : s.connections)
  {
    EXPECT_EQ(c.boundary, boundary_docked(GetParam()));
    EXPECT_NE(c.first, c.second);
    EXPECT_TRUE(connected.insert(ordered(c.first, c.second)).second) << "repeated connection";
  }
  std::map<std::pair<int, int>, std::vector<int>> labels_of_edge;
  for(std::size_t f = 0; f < m.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k)
      labels_of_edge[ordered(m.triangles[f][k], m.triangles[f][(k + 1) % 3])].push_back(s.mesh.face_labels[f]);
  std::set<std::pair<int, int>> seams;
  for(const auto& [e, labels] : labels_of_edge)
  {
    if(std::adjacent_find(labels.begin(), labels.end(), std::not_equal_to<int>()) == labels.end()) continue;
    ASSERT_EQ(labels.size(), 2u) << "seam edge not shared by exactly two faces";
    seams.insert(ordered(labels[0], labels[1]));
  }
  if(boundary_docked(GetParam()))
  {
    EXPECT_EQ(seams, connected);
    return;
  }
  EXPECT_TRUE(seams.empty());
  // Generalized docking: docked parts within the radius, others farther.
  const double r = s.annotation.parameters.docking_radius;
  std::vector<Point_matrix> points;
  for(const Synthetic_instance& i : s.instances) points.push_back(instance_points(s, i));
  for(std::size_t a = 0; a < points.size(); ++a)
    for(std::size_t b = a + 1; b < points.size(); ++b)
    {
      const double d = min_distance(points[a], points[b], r);
      if(connected.count(ordered(static_cast<int>(a), static_cast<int>(b))))
        EXPECT_LT(d, r) << a << " " << b;
      else
        EXPECT_GT(d, r) << a << " " << b;
    }
}

INSTANTIATE_TEST_SUITE_P(All, Synthetic, ::testing::ValuesIn(all_synthetic_families()),
                         [](const ::testing::TestParamInfo<Synthetic_family>& info) {
                           std::string name = family_name(info.param);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(Synthetic_scale, expected_rules_per_family)
{
  const std::map<Synthetic_family, int> rules = {{Synthetic_family::hexa_grid, 3},
                                                 {Synthetic_family::facade, 20},
                                                 {Synthetic_family::hand, 7},
                                                 {Synthetic_family::spider, 11},
                                                 {Synthetic_family::spine, 1}};
  for(const auto& [f, r] : rules) EXPECT_EQ(make_synthetic_model(f, small_options(f)).expected_rules, r) << family_name(f);
}

TEST(Synthetic_scale, default_sizes_are_the_papers)
{
  const std::map<Synthetic_family, int> paper = {{Synthetic_family::hexa_grid, 51465},
                                                 {Synthetic_family::facade, 45493},
                                                 {Synthetic_family::hand, 23000},
                                                 {Synthetic_family::spider, 66453},
                                                 {Synthetic_family::spine, 16254}};
  for(const auto& [f, n] : paper)
  {
    const auto start = std::chrono::steady_clock::now();
    const Synthetic_model s = make_synthetic_model(f);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NEAR(s.mesh.mesh.number_of_vertices(), n, 0.1 * n) << family_name(f);
    EXPECT_LT(seconds, 2.) << family_name(f);
  }
}

TEST(Synthetic_scale, sizes_scale_resolution_not_structure)
{
  for(Synthetic_family f : all_synthetic_families())
  {
    Synthetic_options a, b;
    a.vertices = 3000;
    b.vertices = 12000;
    const Synthetic_model sa = make_synthetic_model(f, a), sb = make_synthetic_model(f, b);
    EXPECT_NEAR(sb.mesh.mesh.number_of_vertices(), 12000, 0.25 * 12000) << family_name(f);
    ASSERT_EQ(sa.instances.size(), sb.instances.size()) << family_name(f);
    for(std::size_t i = 0; i < sa.instances.size(); ++i) EXPECT_EQ(sa.instances[i].type, sb.instances[i].type);
    EXPECT_EQ(sa.expected_rules, sb.expected_rules);
    EXPECT_EQ(sa.connections.size(), sb.connections.size());
  }
}

TEST(Synthetic_scale, negative_size_is_an_input_error)
{
  Synthetic_options o;
  o.vertices = -5;
  EXPECT_THROW(make_synthetic_model(Synthetic_family::hand, o), Input_error);
}

// Requests below a family's coarsest structure give that structure, finite.
TEST(Synthetic, tiny_sizes_give_the_coarsest_finite_model)
{
  for(Synthetic_family f : all_synthetic_families())
  {
    Synthetic_options o;
    o.vertices = 10;
    const Synthetic_model m = make_synthetic_model(f, o);
    EXPECT_TRUE(m.mesh.mesh.points.allFinite()) << family_name(f);
    EXPECT_GT(m.mesh.mesh.number_of_faces(), 0) << family_name(f);
  }
}
