// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/internal/Part_graph_problem.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Atomic_file.h>

#include <boost/crc.hpp>

#include <cstring>
#include <limits>

namespace CGAL {
namespace MPM {

namespace {

const char model_magic[8] = {'C', 'G', 'A', 'L', 'M', 'P', 'M', '\n'};
// magic, version, payload length; then the payload and its CRC-32.
constexpr std::size_t header_size = 8 + 4 + 8;
constexpr std::size_t trailer_size = 4;

std::uint32_t crc32(const char* data, std::size_t size)
{
  boost::crc_32_type crc;
  crc.process_bytes(data, size);
  return crc.checksum();
}

// ----------------------------------------------------------------------------
// Little-endian encoding, independent of the host's byte order.

class Writer
{
public:
  std::string bytes;

  void u8(std::uint8_t v) { bytes.push_back(char(v)); }
  void u32(std::uint32_t v) { for(int i = 0; i < 4; ++i) u8(std::uint8_t(v >> (8 * i))); }
  void u64(std::uint64_t v) { for(int i = 0; i < 8; ++i) u8(std::uint8_t(v >> (8 * i))); }
  void i32(int v) { u32(std::uint32_t(v)); }
  void f64(double v)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    u64(bits);
  }
  void count(std::size_t n) { u64(n); }
  void string(const std::string& s) { count(s.size()); bytes += s; }
  void ints(const std::vector<int>& v) { count(v.size()); for(int x : v) i32(x); }
  void doubles(const std::vector<double>& v) { count(v.size()); for(double x : v) f64(x); }
  void vector(const Eigen::VectorXd& v) { count(std::size_t(v.size())); for(Eigen::Index i = 0; i < v.size(); ++i) f64(v[i]); }
  template <class Matrix>
  void matrix(const Matrix& m)
  {
    count(std::size_t(m.rows()));
    count(std::size_t(m.cols()));
    for(Eigen::Index j = 0; j < m.cols(); ++j)
      for(Eigen::Index i = 0; i < m.rows(); ++i) f64(m(i, j));
  }
  void motion(const Rigid_motion& m)
  {
    for(int j = 0; j < 3; ++j) for(int i = 0; i < 3; ++i) f64(m.rotation(i, j));
    for(int i = 0; i < 3; ++i) f64(m.translation[i]);
  }
  void triangles(const std::vector<Triangle>& ts)
  {
    count(ts.size());
    for(const Triangle& t : ts) for(int c : t) i32(c);
  }
  void edges(const std::vector<Cluster_edge>& es)
  {
    count(es.size());
    for(const Cluster_edge& e : es) { i32(e.source); i32(e.target); u8(e.is_virtual ? 1 : 0); }
  }
  void merged_seam(const std::vector<Seam_vertex>& seam)
  {
    count(seam.size());
    for(const Seam_vertex& v : seam) {
      f64(v.parameter);
      for(int side = 0; side < 2; ++side) { i32(v.local[side]); i32(v.from[side]); i32(v.to[side]); f64(v.weight[side]); }
    }
  }
  void site_ref(const Site_ref& s) { i32(s.type); i32(s.site); }
  void kind(Docking_kind k) { u8(k == Docking_kind::boundary ? 0 : 1); }
  void space(const Shape_space& s)
  {
    matrix(s.mean);
    matrix(s.modes);
    vector(s.sigmas);
    vector(s.variances);
    matrix(s.instance_coordinates);
    count(s.instance_motions.size());
    for(const Rigid_motion& m : s.instance_motions) motion(m);
    doubles(s.instance_residuals);
  }
};

// Reads what Writer wrote. Every count is checked against the bytes left
// before anything is allocated, so a corrupt count cannot exhaust memory.
class Reader
{
public:
  Reader(const char* data, std::size_t size, const std::string& source)
    : data_(data), size_(size), source_(source) {}

  std::size_t remaining() const { return size_ - pos_; }

  std::uint8_t u8() { need(1); return std::uint8_t(data_[pos_++]); }
  std::uint32_t u32() { std::uint32_t v = 0; for(int i = 0; i < 4; ++i) v |= std::uint32_t(u8()) << (8 * i); return v; }
  std::uint64_t u64() { std::uint64_t v = 0; for(int i = 0; i < 8; ++i) v |= std::uint64_t(u8()) << (8 * i); return v; }
  int i32() { return int(u32()); }
  double f64()
  {
    const std::uint64_t bits = u64();
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  // A count of elements that take at least `bytes_each` bytes.
  std::size_t count(std::size_t bytes_each)
  {
    const std::uint64_t n = u64();
    if(n > remaining() / bytes_each)
      damaged("a count of " + std::to_string(n) + " exceeds the " + std::to_string(remaining()) + " bytes left");
    return std::size_t(n);
  }
  std::string string()
  {
    const std::size_t n = count(1);
    std::string s(data_ + pos_, n);
    pos_ += n;
    return s;
  }
  std::vector<int> ints() { std::vector<int> v(count(4)); for(int& x : v) x = i32(); return v; }
  std::vector<double> doubles() { std::vector<double> v(count(8)); for(double& x : v) x = f64(); return v; }
  Eigen::VectorXd vector()
  {
    Eigen::VectorXd v(Eigen::Index(count(8)));
    for(Eigen::Index i = 0; i < v.size(); ++i) v[i] = f64();
    return v;
  }
  template <class Matrix>
  Matrix matrix()
  {
    // An empty matrix may have many rows (3n x 0 modes), so only the product is bounded by the bytes left.
    const std::uint64_t rows = u64(), cols = u64();
    const std::uint64_t index_limit = std::uint64_t(std::numeric_limits<int>::max());
    if(rows > index_limit || cols > index_limit || (rows != 0 && cols > remaining() / 8 / rows))
      damaged("a " + std::to_string(rows) + " x " + std::to_string(cols) + " matrix exceeds the bytes left");
    if(Matrix::ColsAtCompileTime != Eigen::Dynamic && cols != std::size_t(Matrix::ColsAtCompileTime))
      damaged("a matrix of " + std::to_string(cols) + " columns where " +
              std::to_string(Matrix::ColsAtCompileTime) + " are required");
    Matrix m(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    for(Eigen::Index j = 0; j < m.cols(); ++j)
      for(Eigen::Index i = 0; i < m.rows(); ++i) m(i, j) = f64();
    return m;
  }
  Rigid_motion motion()
  {
    Rigid_motion m;
    for(int j = 0; j < 3; ++j) for(int i = 0; i < 3; ++i) m.rotation(i, j) = f64();
    for(int i = 0; i < 3; ++i) m.translation[i] = f64();
    return m;
  }
  std::vector<Triangle> triangles()
  {
    std::vector<Triangle> ts(count(12));
    for(Triangle& t : ts) for(int& c : t) c = i32();
    return ts;
  }
  std::vector<Cluster_edge> edges()
  {
    std::vector<Cluster_edge> es(count(9));
    for(Cluster_edge& e : es) { e.source = i32(); e.target = i32(); e.is_virtual = flag(); }
    return es;
  }
  bool flag()
  {
    const std::uint8_t v = u8();
    if(v > 1) damaged("a flag of value " + std::to_string(v));
    return v == 1;
  }
  std::vector<Seam_vertex> merged_seam()
  {
    std::vector<Seam_vertex> seam(count(8 + 2 * 20));
    for(Seam_vertex& v : seam) {
      v.parameter = f64();
      for(int side = 0; side < 2; ++side) { v.local[side] = i32(); v.from[side] = i32(); v.to[side] = i32(); v.weight[side] = f64(); }
    }
    return seam;
  }
  Site_ref site_ref() { Site_ref s; s.type = i32(); s.site = i32(); return s; }
  Docking_kind kind() { return flag() ? Docking_kind::generalized : Docking_kind::boundary; }
  Shape_space space()
  {
    Shape_space s;
    s.mean = matrix<Point_matrix>();
    s.modes = matrix<Eigen::MatrixXd>();
    s.sigmas = vector();
    s.variances = vector();
    s.instance_coordinates = matrix<Eigen::MatrixXd>();
    s.instance_motions.resize(count(12 * 8));
    for(Rigid_motion& m : s.instance_motions) m = motion();
    s.instance_residuals = doubles();
    return s;
  }

  [[noreturn]] void damaged(const std::string& what) const
  {
    throw Input_error(source_, "", "damaged model file (" + what + " at payload byte " + std::to_string(pos_) + ")");
  }

private:
  void need(std::size_t n) const
  {
    if(remaining() < n) damaged("payload ends early");
  }

  const char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::string source_;
};

// ----------------------------------------------------------------------------

std::string payload_of(const Morphable_part_model& model)
{
  Writer w;
  const Model_parameters& p = model.parameters;
  w.f64(p.sigma_sub);
  w.f64(p.sigma_bound);
  w.f64(p.docking_radius);
  w.i32(p.modes);
  w.f64(p.explained_variance);

  w.count(model.types.size());
  for(const Part_type& t : model.types) {
    w.string(t.name);
    w.i32(t.number_of_vertices);
    w.triangles(t.triangles);
    w.edges(t.edges);
    w.count(t.sites.size());
    for(const Docking_site& s : t.sites) { w.kind(s.kind); w.ints(s.vertices); }
    w.space(t.space);
  }

  w.count(model.rules.size());
  for(const Docking_rule& r : model.rules) {
    w.site_ref(r.first);
    w.site_ref(r.second);
    w.kind(r.kind);
    w.count(r.seam.size());
    for(const auto& s : r.seam) { w.i32(s.first); w.i32(s.second); }
    w.merged_seam(r.merged_seam);
    w.count(r.points.size());
    for(const Pair_point& q : r.points) { w.i32(q.side); w.i32(q.local); }
    w.edges(r.edges);
    w.space(r.space);
  }

  w.count(model.examples.size());
  for(const Training_example& e : model.examples) {
    const Labeled_mesh surface = to_labeled_mesh(e);
    w.string(e.name);
    w.matrix(surface.mesh.points);
    w.triangles(surface.mesh.triangles);
    w.ints(surface.face_labels);
    w.count(e.graph.nodes.size());
    for(const Part_node& n : e.graph.nodes) {
      w.i32(n.type);
      w.i32(n.label);
      w.ints(n.vertices);
      w.vector(n.coordinates);
      w.motion(n.motion);
    }
    w.count(e.graph.edges.size());
    for(const Part_edge& g : e.graph.edges) {
      w.i32(g.first);
      w.i32(g.second);
      w.i32(g.rule);
      w.vector(g.coordinates);
      w.motion(g.motion);
      w.merged_seam(g.merged_seam);
    }
  }
  return std::move(w.bytes);
}

// The examples' meshes go to `example_meshes`, to be checked before they
// become the examples' surface meshes.
Morphable_part_model model_of(Reader& r, std::vector<Labeled_mesh>& example_meshes)
{
  Morphable_part_model model;
  Model_parameters& p = model.parameters;
  p.sigma_sub = r.f64();
  p.sigma_bound = r.f64();
  p.docking_radius = r.f64();
  p.modes = r.i32();
  p.explained_variance = r.f64();

  // Minimum sizes per element keep the counts honest; see Reader::count().
  model.types.resize(r.count(8 + 4 + 8 + 8 + 8));
  for(Part_type& t : model.types) {
    t.name = r.string();
    t.number_of_vertices = r.i32();
    t.triangles = r.triangles();
    t.edges = r.edges();
    t.sites.resize(r.count(1 + 8));
    for(Docking_site& s : t.sites) { s.kind = r.kind(); s.vertices = r.ints(); }
    t.space = r.space();
  }

  model.rules.resize(r.count(16 + 1 + 8 + 8 + 8));
  for(Docking_rule& rule : model.rules) {
    rule.first = r.site_ref();
    rule.second = r.site_ref();
    rule.kind = r.kind();
    rule.seam.resize(r.count(8));
    for(auto& s : rule.seam) { s.first = r.i32(); s.second = r.i32(); }
    rule.merged_seam = r.merged_seam();
    rule.points.resize(r.count(8));
    for(Pair_point& q : rule.points) { q.side = r.i32(); q.local = r.i32(); }
    rule.edges = r.edges();
    rule.space = r.space();
  }

  model.examples.resize(r.count(8 + 16 + 8 + 8 + 8 + 8));
  example_meshes.resize(model.examples.size());
  for(std::size_t i = 0; i < model.examples.size(); ++i) {
    Training_example& e = model.examples[i];
    e.name = r.string();
    example_meshes[i].mesh.points = r.matrix<Point_matrix>();
    example_meshes[i].mesh.triangles = r.triangles();
    example_meshes[i].face_labels = r.ints();
    e.graph.nodes.resize(r.count(8 + 8 + 8 + 12 * 8));
    for(Part_node& n : e.graph.nodes) {
      n.type = r.i32();
      n.label = r.i32();
      n.vertices = r.ints();
      n.coordinates = r.vector();
      n.motion = r.motion();
    }
    e.graph.edges.resize(r.count(12 + 8 + 12 * 8 + 8));
    for(Part_edge& g : e.graph.edges) {
      g.first = r.i32();
      g.second = r.i32();
      g.rule = r.i32();
      g.coordinates = r.vector();
      g.motion = r.motion();
      g.merged_seam = r.merged_seam();
    }
  }
  if(r.remaining() != 0) r.damaged(std::to_string(r.remaining()) + " bytes after the model");
  return model;
}

// ----------------------------------------------------------------------------
// Consistency of what parsed: every index other code will follow.

std::string example_element(int e, const std::string& name)
{
  return "example " + std::to_string(e) + " (\"" + name + "\")";
}

class Model_checker
{
public:
  Model_checker(const Morphable_part_model& m, const std::vector<Labeled_mesh>& example_meshes,
                const std::string& source)
    : m_(m), example_meshes_(example_meshes), source_(source)
  {}

  void check() const
  {
    for(std::size_t t = 0; t < m_.types.size(); ++t) check_type(int(t));
    for(std::size_t r = 0; r < m_.rules.size(); ++r) check_rule(int(r));
    for(std::size_t e = 0; e < m_.examples.size(); ++e) check_example(int(e));
  }

private:
  void check_type(int t) const
  {
    const Part_type& type = m_.types[t];
    const std::string element = "part type " + std::to_string(t) + " (\"" + type.name + "\")";
    const int n = type.number_of_vertices;
    if(n < 0) fail(element, "negative number of vertices");
    for(std::size_t f = 0; f < type.triangles.size(); ++f)
      for(int v : type.triangles[f])
        in_range(v, n, element + " triangle " + std::to_string(f), "vertex");
    check_edges(type.edges, n, element);
    for(std::size_t s = 0; s < type.sites.size(); ++s)
      for(int v : type.sites[s].vertices)
        in_range(v, n, element + " site " + std::to_string(s), "vertex");
    check_space(type.space, n, element);
  }

  void check_rule(int r) const
  {
    const Docking_rule& rule = m_.rules[r];
    const std::string element = "rule " + std::to_string(r);
    const int n[2] = {site_vertices(rule.first, element + " first site"),
                      site_vertices(rule.second, element + " second site")};
    for(std::size_t s = 0; s < rule.seam.size(); ++s) {
      in_range(rule.seam[s].first, n[0], element + " seam pair " + std::to_string(s), "first vertex");
      in_range(rule.seam[s].second, n[1], element + " seam pair " + std::to_string(s), "second vertex");
    }
    check_merged_seam(rule.merged_seam, n, element);
    for(std::size_t q = 0; q < rule.points.size(); ++q) {
      const Pair_point& p = rule.points[q];
      const std::string where = element + " point " + std::to_string(q);
      in_range(p.side, 2, where, "side");
      in_range(p.local, n[p.side], where, "vertex");
    }
    check_edges(rule.edges, int(rule.points.size()), element);
    check_space(rule.space, int(rule.points.size()), element);
  }

  void check_example(int e) const
  {
    const Training_example& ex = m_.examples[e];
    const Labeled_mesh& surface = example_meshes_[std::size_t(e)];
    const std::string element = example_element(e, ex.name);
    const int nv = surface.mesh.number_of_vertices();
    for(std::size_t f = 0; f < surface.mesh.triangles.size(); ++f)
      for(int v : surface.mesh.triangles[f])
        in_range(v, nv, element + " triangle " + std::to_string(f), "vertex");
    if(surface.face_labels.size() != surface.mesh.triangles.size())
      fail(element, std::to_string(surface.face_labels.size()) + " face labels for " +
                      std::to_string(surface.mesh.triangles.size()) + " faces");
    const auto& nodes = ex.graph.nodes;
    for(std::size_t i = 0; i < nodes.size(); ++i)
      in_range(nodes[i].type, int(m_.types.size()), element + " node " + std::to_string(i), "part type");
    for(std::size_t i = 0; i < ex.graph.edges.size(); ++i) {
      const Part_edge& g = ex.graph.edges[i];
      const std::string where = element + " edge " + std::to_string(i);
      in_range(g.first, int(nodes.size()), where, "first node");
      in_range(g.second, int(nodes.size()), where, "second node");
      in_range(g.rule, int(m_.rules.size()), where, "rule");
      const Docking_rule& rule = m_.rules[g.rule];
      if(nodes[g.first].type != rule.first.type || nodes[g.second].type != rule.second.type)
        fail(where, "its nodes are not of the part types rule " + std::to_string(g.rule) + " docks");
      coordinates_fit(g.coordinates, rule.space, where);
      const int n[2] = {m_.types[rule.first.type].number_of_vertices, m_.types[rule.second.type].number_of_vertices};
      check_merged_seam(g.merged_seam, n, where);
    }
    // Merged seams insert vertices into their parts, listed after the type's.
    std::vector<std::size_t> inserted(nodes.size(), 0);
    try {
      const internal::Graph_refinement refined = internal::refine_part_graph(m_, ex.graph);
      for(std::size_t i = 0; i < nodes.size(); ++i) inserted[i] = refined.nodes[i].inserted.size();
    } catch(const Input_error& error) {
      fail(element, error.what());
    }
    for(std::size_t i = 0; i < nodes.size(); ++i) {
      const std::string where = element + " node " + std::to_string(i);
      const Part_type& type = m_.types[nodes[i].type];
      if(nodes[i].vertices.size() != std::size_t(type.number_of_vertices) + inserted[i])
        fail(where, std::to_string(nodes[i].vertices.size()) + " vertices for a part type of " +
                      std::to_string(type.number_of_vertices) +
                      (inserted[i] ? " and " + std::to_string(inserted[i]) + " inserted seam vertices" : ""));
      for(int v : nodes[i].vertices) in_range(v, nv, where, "mesh vertex");
      coordinates_fit(nodes[i].coordinates, type.space, where);
    }
  }

  void check_merged_seam(const std::vector<Seam_vertex>& seam, const int n[2], const std::string& element) const
  {
    for(std::size_t k = 0; k < seam.size(); ++k) {
      const Seam_vertex& v = seam[k];
      const std::string where = element + " merged seam vertex " + std::to_string(k);
      for(int side = 0; side < 2; ++side) {
        // -1 marks a vertex inserted on that side; it then lies on an edge.
        in_range(v.local[side] + 1, n[side] + 1, where, "vertex");
        if(v.local[side] < 0) {
          in_range(v.from[side], n[side], where, "split edge start");
          in_range(v.to[side], n[side], where, "split edge end");
        }
        if(!(v.weight[side] >= 0. && v.weight[side] <= 1.)) fail(where, "interpolation weight outside [0, 1]");
      }
    }
  }

  int site_vertices(const Site_ref& s, const std::string& element) const
  {
    in_range(s.type, int(m_.types.size()), element, "part type");
    in_range(s.site, int(m_.types[s.type].sites.size()), element, "site");
    return m_.types[s.type].number_of_vertices;
  }

  void check_edges(const std::vector<Cluster_edge>& edges, int n, const std::string& element) const
  {
    for(std::size_t i = 0; i < edges.size(); ++i) {
      in_range(edges[i].source, n, element + " edge " + std::to_string(i), "source");
      in_range(edges[i].target, n, element + " edge " + std::to_string(i), "target");
    }
  }

  // A space either is unlearned (empty) or describes exactly `n` points.
  void check_space(const Shape_space& s, int n, const std::string& element) const
  {
    const std::string where = element + " shape space";
    if(s.mean.rows() == 0 && s.modes.size() == 0 && s.instance_motions.empty()) return;
    if(s.mean.rows() != n)
      fail(where, "mean of " + std::to_string(s.mean.rows()) + " points for " + std::to_string(n));
    const Eigen::Index d = s.modes.cols();
    if(d > 0 && s.modes.rows() != 3 * Eigen::Index(n))
      fail(where, "modes of " + std::to_string(s.modes.rows()) + " rows for " + std::to_string(3 * n));
    if(s.sigmas.size() != d)
      fail(where, std::to_string(s.sigmas.size()) + " standard deviations for " + std::to_string(d) + " modes");
    if(s.instance_coordinates.size() > 0 &&
       (s.instance_coordinates.rows() != d || s.instance_coordinates.cols() != Eigen::Index(s.instance_motions.size())))
      fail(where, "instance coordinates of size " + std::to_string(s.instance_coordinates.rows()) + " x " +
                    std::to_string(s.instance_coordinates.cols()) + " for " + std::to_string(d) + " modes and " +
                    std::to_string(s.instance_motions.size()) + " instances");
    if(!s.instance_residuals.empty() && s.instance_residuals.size() != s.instance_motions.size())
      fail(where, std::to_string(s.instance_residuals.size()) + " residuals for " +
                    std::to_string(s.instance_motions.size()) + " instances");
  }

  void coordinates_fit(const Eigen::VectorXd& c, const Shape_space& s, const std::string& where) const
  {
    if(c.size() != 0 && c.size() != s.number_of_modes())
      fail(where, std::to_string(c.size()) + " shape coordinates for a space of " +
                    std::to_string(s.number_of_modes()) + " modes");
  }

  void in_range(int value, int size, const std::string& element, const std::string& what) const
  {
    if(value < 0 || value >= size)
      fail(element, what + " " + std::to_string(value) + " is out of range (" + std::to_string(size) + ")");
  }

  [[noreturn]] void fail(const std::string& element, const std::string& problem) const
  {
    throw Input_error(source_, element, "inconsistent model: " + problem);
  }

  const Morphable_part_model& m_;
  const std::vector<Labeled_mesh>& example_meshes_;
  std::string source_;
};

} // namespace

std::string serialize_model(const Morphable_part_model& model)
{
  const std::string payload = payload_of(model);
  Writer w;
  w.bytes.assign(model_magic, sizeof model_magic);
  w.u32(model_file_version);
  w.u64(payload.size());
  w.bytes += payload;
  w.u32(crc32(payload.data(), payload.size()));
  return std::move(w.bytes);
}

Morphable_part_model deserialize_model(const std::string& bytes, const std::string& source)
{
  const std::size_t magic_bytes = std::min(bytes.size(), sizeof model_magic);
  if(bytes.empty() || std::memcmp(bytes.data(), model_magic, magic_bytes) != 0)
    throw Input_error(source, "", "not a CGAL-MPM model file");
  if(bytes.size() < header_size + trailer_size)
    throw Input_error(source, "", "damaged model file (truncated: " + std::to_string(bytes.size()) + " bytes)");

  Reader header(bytes.data() + sizeof model_magic, header_size - sizeof model_magic, source);
  const std::uint32_t version = header.u32();
  if(version != model_file_version)
    throw Input_error(source, "", "model format version " + std::to_string(version) +
                                    ", this build reads version " + std::to_string(model_file_version));
  const std::uint64_t length = header.u64();
  const std::uint64_t available = bytes.size() - header_size - trailer_size;
  if(length > available)
    throw Input_error(source, "", "damaged model file (truncated: the payload has " + std::to_string(available) +
                                    " of " + std::to_string(length) + " bytes)");
  if(length < available)
    throw Input_error(source, "", "damaged model file (length mismatch: " + std::to_string(available - length) +
                                    " bytes after the payload)");
  const char* payload = bytes.data() + header_size;
  Reader trailer(payload + length, trailer_size, source);
  if(trailer.u32() != crc32(payload, std::size_t(length)))
    throw Input_error(source, "", "damaged model file (checksum mismatch)");

  Reader reader(payload, std::size_t(length), source);
  std::vector<Labeled_mesh> example_meshes;
  Morphable_part_model model = model_of(reader, example_meshes);
  Model_checker(model, example_meshes, source).check();
  for(std::size_t e = 0; e < model.examples.size(); ++e) {
    Training_example& example = model.examples[e];
    try {
      example = make_training_example(example.name, example_meshes[e], std::move(example.graph));
    } catch(const Input_error& error) {
      throw Input_error(source, example_element(int(e), example.name) + " " + error.element(),
                        "inconsistent model: " + error.problem());
    }
  }
  model.update_grammar();
  return model;
}

void save_model(const Morphable_part_model& model, const std::string& path)
{
  const std::string bytes = serialize_model(model);
  internal::write_file_atomically(path, [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); },
                                  true);
}

Morphable_part_model load_model(const std::string& path)
{
  return deserialize_model(internal::read_file(path), path);
}

} // namespace MPM
} // namespace CGAL
