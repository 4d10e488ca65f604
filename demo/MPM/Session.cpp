// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Session.h"

#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Editing/Arap_deformation.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Editing/Limb_bending.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>
#include <CGAL/MPM/Part_colors.h>
#include <CGAL/MPM/Assembly/Free_site_capping.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <QEventLoop>
#include <QTimer>

#include <boost/graph/breadth_first_search.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <unordered_map>

namespace mpm_demo {

namespace MPM = CGAL::MPM;

namespace {

// Records the docking by which a breadth-first search reaches each node.
class Reached_by_recorder : public boost::default_bfs_visitor
{
public:
  explicit Reached_by_recorder(std::vector<int>& reached_by) : reached_by_(&reached_by) {}

  template <class Edge, class Graph>
  void tree_edge(const Edge& e, const Graph& g) const
  {
    (*reached_by_)[boost::target(e, g)] = g[e];
  }

private:
  std::vector<int>* reached_by_; // a pointer: Boost.Graph copies its visitor
};

// Mesh edges between faces of different parts.
std::vector<std::array<int, 2>> seam_edges_of(const MPM::Indexed_mesh& mesh, const std::vector<int>& face_parts)
{
  std::vector<std::array<int, 2>> seams;
  std::unordered_map<std::uint64_t, int> part_of_edge;
  const auto key = [](int a, int b) { return (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b)); };
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const int a = mesh.triangles[f][c], b = mesh.triangles[f][(c + 1) % 3];
      const auto [it, inserted] = part_of_edge.emplace(key(a, b), face_parts[f]);
      if(!inserted && it->second != face_parts[f]) seams.push_back({{a, b}});
    }
  return seams;
}

} // namespace

// ---------------------------------------------------------------------------
// Session

Session::Session(QObject* parent) : QObject(parent)
{
  qRegisterMetaType<mpm_demo::Solve_frame>("mpm_demo::Solve_frame");
  connect(&thread_, &Solver_thread::frame_ready, this, &Session::on_frame, Qt::QueuedConnection);
  thread_.start();
}

Session::~Session() { thread_.finish(); }

void Session::load_synthetic(const std::string& family, int vertices, unsigned seed)
{
  MPM::Synthetic_options options;
  options.vertices = vertices;
  options.seed = seed;
  const MPM::Synthetic_model synthetic = MPM::make_synthetic_model(MPM::parse_family(family), options);
  adopt_model(MPM::learn_morphable_part_model(synthetic.mesh, synthetic.annotation),
              QString("synthetic %1 (%2 vertices)")
                .arg(QString::fromStdString(family))
                .arg(synthetic.mesh.mesh.number_of_vertices()),
              MPM::family_name(synthetic.family));
}

void Session::load_labeled_mesh(const std::string& mesh, const std::string& labels, const std::string& annotation)
{
  const MPM::Labeled_mesh labeled = MPM::read_labeled_mesh(mesh, labels);
  MPM::validate_labeled_mesh(labeled);
  // Without an annotation a real segmentation gets the types `mpm learn` proposes.
  MPM::Annotation a;
  if(!annotation.empty()) a = MPM::read_annotation(annotation);
  else if(MPM::part_types_need_proposing({labeled})) a = MPM::propose_part_types(labeled).annotation;
  adopt_model(MPM::learn_morphable_part_model(labeled, a), QString::fromStdString(mesh));
}

void Session::load_model(const std::string& path)
{
  adopt_model(MPM::load_model(path), QString::fromStdString(path));
}

void Session::open_raw_mesh(const std::string& path)
{
  cutting_ = std::make_unique<Raw_mesh_cutting>(path);
  has_model_ = false;
  problem_.reset();
  source_ = QString::fromStdString(path);
  family_.clear();
  show_cutting();
}

void Session::show_cutting()
{
  rest_ = cutting_->mesh();
  face_nodes_ = cutting_->labels();
  face_types_ = face_nodes_;
  seam_edges_ = seam_edges_of(rest_, face_nodes_);
  docking_vertices_.clear();
  start_new_scene();
}

void Session::start_new_scene()
{
  // Handles name vertices of the old mesh; the next request carries none.
  handle_vertices_.clear();
  handle_groups_.clear();
  handle_offsets_.resize(0, 3);
  frame_ = Solve_frame();
  frame_.positions = rest_.points;
  frame_.serial = serial_;
  Q_EMIT scene_changed();
}

const MPM::Joint_cut& Session::add_cut(int vertex)
{
  const MPM::Joint_cut& cut = require_cutting("cut").add_cut(vertex);
  show_cutting();
  return cut;
}

int Session::remove_cut_near(int vertex)
{
  const int removed = require_cutting("cut").remove_cut_near(vertex);
  show_cutting();
  return removed;
}

int Session::propose_cuts(double sensitivity)
{
  const int limbs = require_cutting("cut").propose(sensitivity);
  show_cutting();
  return limbs;
}

void Session::set_part_type(int label, const std::string& type)
{
  require_cutting("part type").set_part_type(label, type);
}

void Session::learn_from_cuts()
{
  require_cutting("learn");
  if(cutting_->cuts().empty()) throw MPM::Input_error(cutting_->path(), "cuts", "none yet: cut the mesh first");
  const MPM::Labeled_mesh labeled = cutting_->labeled_mesh();
  MPM::validate_labeled_mesh(labeled);
  adopt_model(MPM::learn_morphable_part_model(labeled, cutting_->part_types().annotation),
              QString::fromStdString(cutting_->path()));
}

Raw_mesh_cutting& Session::require_cutting(const std::string& what)
{
  if(!cutting_) throw MPM::Input_error("demo", what, "open a mesh to cut first");
  return *cutting_;
}

void Session::require_model(const std::string& what) const
{
  if(!has_model_) throw MPM::Input_error("demo", what, "needs a model: open or learn one first");
}

void Session::adopt_model(MPM::Morphable_part_model&& model, const QString& source, const std::string& family)
{
  if(model.examples.empty()) throw MPM::Input_error(source.toStdString(), "model", "has no training example");
  cutting_.reset();
  // Derived repetition and bridging rules let the grammar lengthen and
  // shorten chains (a finger).
  MPM::add_repetition_rules(model);
  MPM::add_bridging_rules(model);
  model_ = std::move(model);
  has_model_ = true;
  source_ = source;
  family_ = family;
  edit_graph_ = MPM::part_graph_of_example(model_, 0);
  graph_edited_ = false;
  mode_ = Edit_mode::deform;
  rest_ = MPM::Indexed_mesh(); // a new scene in any case
  rebuild();
}

const MPM::Part_graph& Session::shown_graph() const
{
  return graph_edited_ ? assembly_.graph : model_.examples.front().graph;
}

void Session::rebuild()
{
  require_model("an edit");
  MPM::Embedding_problem problem;
  if(!graph_edited_)
  {
    switch(mode_)
    {
    case Edit_mode::deform: problem = MPM::make_deformation_problem(model_, 0); break;
    case Edit_mode::symmetrize:
    {
      MPM::Symmetrization_options options;
      options.relative_sigma = symmetry_sigma_;
      problem = MPM::make_symmetrization_problem(model_, 0, options);
      break;
    }
    case Edit_mode::caricature: problem = MPM::make_caricature_problem(model_, caricature_factor_, 0); break;
    }
    const MPM::Training_example& example = model_.examples.front();
    const MPM::Labeled_mesh rest = MPM::to_labeled_mesh(example);
    std::map<int, int> node_of_label;
    for(std::size_t n = 0; n < example.graph.nodes.size(); ++n) node_of_label[example.graph.nodes[n].label] = int(n);
    std::vector<int> face_nodes(rest.face_labels.size(), -1);
    for(std::size_t f = 0; f < face_nodes.size(); ++f)
    {
      const auto it = node_of_label.find(rest.face_labels[f]);
      if(it != node_of_label.end()) face_nodes[f] = it->second;
    }
    set_scene(rest.mesh, example.graph, std::move(face_nodes));
  }
  else
  {
    // An assembly is edited through its parts' coordinates: the type means
    // (symmetrize) or coordinates scaled away from them (caricature).
    MPM::Part_graph graph = edit_graph_;
    if(mode_ != Edit_mode::deform) MPM::scale_coordinates(graph, mode_ == Edit_mode::symmetrize ? 0. : caricature_factor_);
    MPM::Assembly_options options;
    options.solver.coupling_weight = coupling_;
    MPM::Assembly assembly = MPM::assemble(model_, graph, options);
    // A removed branch's hole is closed, and the cap is edited with its part.
    MPM::cap_free_sites(model_, assembly);
    problem = assembly.problem;
    problem.mesh.points = assembly.mesh.points; // start from the embedding
    assembly_ = std::move(assembly);
    set_scene(assembly_.mesh, assembly_.graph, assembly_.face_nodes);
  }
  problem_ = std::make_shared<const MPM::Embedding_problem>(std::move(problem));
  post(true);
}

void Session::set_scene(const MPM::Indexed_mesh& rest, const MPM::Part_graph& graph, std::vector<int> face_nodes)
{
  const bool same_connectivity = rest.triangles == rest_.triangles && rest.points.rows() == rest_.points.rows();
  rest_ = rest;
  face_nodes_ = std::move(face_nodes);
  face_types_.assign(face_nodes_.size(), -1);
  for(std::size_t f = 0; f < face_nodes_.size(); ++f)
    if(face_nodes_[f] >= 0) face_types_[f] = graph.nodes[face_nodes_[f]].type;

  seam_edges_ = seam_edges_of(rest_, face_nodes_);

  docking_vertices_.clear();
  for(const MPM::Part_node& node : graph.nodes)
    for(const MPM::Docking_site& site : model_.types[node.type].sites)
      for(int local : site.vertices)
        if(local < int(node.vertices.size())) docking_vertices_.push_back(node.vertices[local]);
  std::sort(docking_vertices_.begin(), docking_vertices_.end());
  docking_vertices_.erase(std::unique(docking_vertices_.begin(), docking_vertices_.end()), docking_vertices_.end());

  if(!same_connectivity) start_new_scene();
}

void Session::post(bool restart)
{
  if(!problem_) return;
  Solve_request r;
  r.serial = ++serial_;
  r.problem = problem_;
  r.options.coupling_weight = coupling_;
  r.handle_vertices = handle_vertices_;
  r.handle_targets = handle_targets();
  r.arap = arap_;
  r.restart = restart;
  r.unfold = mode_ != Edit_mode::deform;
  r.posted = std::chrono::steady_clock::now();
  thread_.post(std::move(r));
}

void Session::on_frame(const Solve_frame& frame)
{
  // A frame of a request older than the current scene has other vertices.
  if(frame.positions.rows() != 0 && frame.positions.rows() != rest_.points.rows()) return;
  if(frame.arap_positions.rows() != 0 && frame.arap_positions.rows() != rest_.points.rows()) return;
  Point_matrix previous = std::move(frame_.positions);
  frame_ = frame;
  if(frame_.positions.rows() == 0)
    frame_.positions = previous.rows() == rest_.points.rows() ? std::move(previous) : rest_.points;
  Q_EMIT positions_changed();
}

void Session::frame_shown(double paint_ms)
{
  if(!frame_awaits_display()) return;
  frame_.shown_ms = milliseconds_since(frame_.posted);
  frame_.paint_ms = paint_ms;
  display_ms_ = frame_.shown_ms;
  Q_EMIT frame_displayed();
}

// Sleeps in an event loop (the solver thread has the cores) until `done()`
// holds, checked whenever `session` emits `signal`, or the time-out.
template <class Signal, class Done>
bool wait_for(Session& session, Signal signal, const Done& done, int timeout_ms)
{
  if(done()) return true;
  QEventLoop loop;
  QTimer::singleShot(timeout_ms, &loop, &QEventLoop::quit);
  const QMetaObject::Connection c = QObject::connect(&session, signal, &loop, [&done, &loop] {
    if(done()) loop.quit();
  });
  loop.exec();
  QObject::disconnect(c);
  return done();
}

bool Session::wait_until_solved(int timeout_ms)
{
  return wait_for(*this, &Session::positions_changed,
                  [this] { return frame_.serial >= serial_ && frame_.final; }, timeout_ms);
}

bool Session::wait_until_shown(int timeout_ms)
{
  return wait_for(*this, &Session::frame_displayed, [this] { return !frame_awaits_display(); }, timeout_ms);
}

// ---------------------------------------------------------------------------
// Handles

Point_matrix Session::handle_targets() const
{
  Point_matrix t(handle_vertices_.size(), 3);
  for(std::size_t i = 0; i < handle_vertices_.size(); ++i)
    t.row(i) = rest_.points.row(handle_vertices_[i]) + handle_offsets_.row(i);
  return t;
}

int Session::handle_of_vertex(int vertex) const
{
  const auto it = std::find(handle_vertices_.begin(), handle_vertices_.end(), vertex);
  return it == handle_vertices_.end() ? -1 : int(it - handle_vertices_.begin());
}

void Session::add_handle(int vertex)
{
  if(vertex < 0 || vertex >= rest_.number_of_vertices())
    throw MPM::Input_error("handles", "vertex " + std::to_string(vertex),
                           "is out of range (the mesh has " + std::to_string(rest_.number_of_vertices()) +
                             " vertices)");
  if(handle_of_vertex(vertex) >= 0) return;
  const int group = handle_groups_.empty() ? 0 : *std::max_element(handle_groups_.begin(), handle_groups_.end()) + 1;
  handle_vertices_.push_back(vertex);
  handle_groups_.push_back(group);
  // The new handle holds the vertex where it is shown now.
  handle_offsets_.conservativeResize(handle_vertices_.size(), 3);
  handle_offsets_.row(handle_offsets_.rows() - 1) = positions().row(vertex) - rest_.points.row(vertex);
  post();
}

void Session::remove_handle(int index)
{
  if(index < 0 || index >= int(handle_vertices_.size()))
    throw MPM::Input_error("handles", "handle " + std::to_string(index), "does not exist");
  handle_vertices_.erase(handle_vertices_.begin() + index);
  handle_groups_.erase(handle_groups_.begin() + index);
  Point_matrix offsets(handle_vertices_.size(), 3);
  for(int i = 0, j = 0; i < handle_offsets_.rows(); ++i)
    if(i != index) offsets.row(j++) = handle_offsets_.row(i);
  handle_offsets_ = offsets;
  post();
}

void Session::group_handles(const std::vector<int>& indices)
{
  for(int i : indices)
    if(i < 0 || i >= int(handle_vertices_.size()))
      throw MPM::Input_error("handles", "handle " + std::to_string(i), "does not exist");
  for(int i : indices) handle_groups_[i] = handle_groups_[indices.front()];
}

void Session::set_handles_per_part(int per_part)
{
  MPM::Labeled_mesh labeled;
  labeled.mesh = rest_;
  labeled.face_labels = face_nodes_;
  labeled.source = source_.toStdString();
  replace_handles(MPM::handles_per_part(labeled, per_part, positions()));
}

void Session::set_handles_farthest(int count)
{
  replace_handles(MPM::farthest_point_handles(rest_, count, positions()));
}

void Session::set_handles_bending_limbs(double move)
{
  if(!has_model_) throw MPM::Input_error("demo", "limb bending", "load a model first");
  if(graph_edited_) throw MPM::Input_error("demo", "limb bending", "applies to the training example, not an edited graph");
  replace_handles(MPM::limb_bending_handles(model_, 0, move));
}

void Session::replace_handles(const MPM::Handle_set& h)
{
  handle_vertices_ = h.vertices;
  handle_groups_.resize(h.vertices.size());
  for(std::size_t i = 0; i < handle_groups_.size(); ++i) handle_groups_[i] = int(i);
  handle_offsets_ = h.targets;
  for(int i = 0; i < h.size(); ++i) handle_offsets_.row(i) -= rest_.points.row(h.vertices[i]);
  post();
}

void Session::clear_handles()
{
  handle_vertices_.clear();
  handle_groups_.clear();
  handle_offsets_.resize(0, 3);
  post();
}

void Session::drag_handle(int index, const Eigen::RowVector3d& delta)
{
  if(index < 0 || index >= int(handle_vertices_.size()))
    throw MPM::Input_error("handles", "handle " + std::to_string(index),
                           "does not exist (there are " + std::to_string(handle_vertices_.size()) + " handles)");
  if(!delta.allFinite()) throw MPM::Input_error("drag", "offset", "is not finite");
  for(std::size_t j = 0; j < handle_vertices_.size(); ++j)
    if(handle_groups_[j] == handle_groups_[index]) handle_offsets_.row(j) += delta;
  post();
}

// ---------------------------------------------------------------------------
// Edits

void Session::set_mode(Edit_mode mode)
{
  mode_ = mode;
  rebuild();
}

void Session::set_caricature_factor(double factor)
{
  if(!std::isfinite(factor)) throw MPM::Input_error("caricature", "factor", "is not finite");
  caricature_factor_ = factor;
  mode_ = Edit_mode::caricature;
  rebuild();
}

void Session::set_symmetry_sigma(double relative_sigma)
{
  if(!(relative_sigma > 0.) || !std::isfinite(relative_sigma))
    throw MPM::Input_error("symmetrize", "relative sigma", "must be positive and finite");
  symmetry_sigma_ = relative_sigma;
  mode_ = Edit_mode::symmetrize;
  rebuild();
}

void Session::set_coupling(double weight)
{
  if(!(weight >= 0.) || !std::isfinite(weight))
    throw MPM::Input_error("coupling", "weight", "must be zero or positive and finite");
  coupling_ = weight;
  if(graph_edited_) rebuild();
  else post();
}

void Session::set_arap(bool on)
{
  arap_ = on;
  post();
}

void Session::reset()
{
  handle_offsets_.setZero();
  frame_.positions = rest_.points;
  frame_.arap_positions.resize(0, 3);
  post(true);
  Q_EMIT positions_changed();
}

// ---------------------------------------------------------------------------
// Part graph

int Session::root() const { return MPM::root_node(edit_graph_); }

int Session::parent_edge(int node) const
{
  const int n = int(edit_graph_.nodes.size());
  if(node < 0 || node >= n)
    throw MPM::Input_error("part graph", "part " + std::to_string(node),
                           "does not exist (there are " + std::to_string(n) + " parts)");
  // Breadth-first from the root: the edge each node was reached by.
  std::vector<int> reached_by(n, -1);
  boost::breadth_first_search(MPM::adjacency_graph(edit_graph_), std::size_t(root()),
                              boost::visitor(Reached_by_recorder(reached_by)));
  if(reached_by[node] < 0)
    throw MPM::Input_error("part graph", "part " + std::to_string(node),
                           "is the root or not connected to it: pick a part that hangs from another one");
  return reached_by[node];
}

void Session::show_edited_graph(MPM::Part_graph&& graph)
{
  // An assembly that fails leaves the graph shown before, not the failed one.
  MPM::Part_graph previous = std::move(edit_graph_);
  const bool was_edited = graph_edited_;
  edit_graph_ = std::move(graph);
  graph_edited_ = true;
  try
  {
    rebuild();
  }
  catch(...)
  {
    edit_graph_ = std::move(previous);
    graph_edited_ = was_edited;
    throw;
  }
}

int Session::insert_segment(int node)
{
  MPM::Part_graph graph = edit_graph_;
  const int added = MPM::insert_segment(model_, graph, parent_edge(node));
  MPM::choose_segment_shape(model_, graph, added);
  show_edited_graph(std::move(graph));
  return added;
}

void Session::remove_segment(int node)
{
  MPM::Part_graph graph = edit_graph_;
  MPM::remove_segment(model_, graph, node);
  show_edited_graph(std::move(graph));
}

void Session::remove_branch(int node)
{
  MPM::Part_graph graph = edit_graph_;
  MPM::remove_branch(model_, graph, node, MPM::root_node(graph));
  show_edited_graph(std::move(graph));
}

int Session::duplicate_branch(int node)
{
  const int r = MPM::root_node(edit_graph_);
  const std::vector<int> branch = MPM::branch_nodes(edit_graph_, node, r);
  // Onto the root if it has room, else onto the first part outside the
  // branch with a free site that a rule docks to the branch's site.
  std::vector<int> targets{r};
  for(int n = 0; n < int(edit_graph_.nodes.size()); ++n)
    if(n != r && std::find(branch.begin(), branch.end(), n) == branch.end()) targets.push_back(n);
  std::string first_error;
  for(int target : targets)
  {
    MPM::Part_graph graph = edit_graph_;
    try
    {
      const int copy = MPM::duplicate_branch(model_, graph, node, r, target);
      show_edited_graph(std::move(graph));
      return copy;
    }
    catch(const MPM::Input_error& e)
    {
      if(first_error.empty()) first_error = e.what();
    }
  }
  throw MPM::Input_error("part graph", "part " + std::to_string(node),
                         "no part has a free site for a copy of its branch (onto the root: " + first_error + ")");
}

void Session::reset_graph()
{
  edit_graph_ = MPM::part_graph_of_example(model_, 0);
  graph_edited_ = false;
  rebuild();
}

std::vector<std::string> Session::describe_parts() const
{
  std::vector<std::string> lines;
  const MPM::Part_adjacency_graph g = MPM::adjacency_graph(edit_graph_);
  for(std::size_t n = 0; n < edit_graph_.nodes.size(); ++n)
  {
    std::string line = "part " + std::to_string(n) + ": " + model_.types[edit_graph_.nodes[n].type].name + ", docked to";
    for(auto [m, end] = boost::adjacent_vertices(n, g); m != end; ++m) line += " " + std::to_string(*m);
    if(int(n) == root()) line += " (root)";
    lines.push_back(line);
  }
  return lines;
}

// ---------------------------------------------------------------------------
// Saving

void Session::save_mesh(const std::string& path, bool arap_result) const
{
  const Point_matrix& p = arap_result ? arap_positions() : positions();
  if(p.rows() != rest_.points.rows())
    throw MPM::Input_error(path, "mesh", arap_result ? "there is no ARAP result to save (turn ARAP on, add handles)"
                                                     : "there is no result to save");
  MPM::Indexed_mesh mesh;
  mesh.points = p;
  mesh.triangles = rest_.triangles;
  Eigen::Matrix<unsigned char, Eigen::Dynamic, 3> colors(mesh.number_of_faces(), 3);
  for(int f = 0; f < colors.rows(); ++f)
  {
    const MPM::Rgb_color c = MPM::part_type_color(face_types_[f]);
    colors.row(f) << c[0], c[1], c[2];
  }
  MPM::write_mesh_file(mesh, path, &colors);
}

void Session::save_model(const std::string& path) const
{
  require_model("saving a model");
  MPM::save_model(model_, path);
}

void Session::save_handles(const std::string& path) const
{
  MPM::Handle_set h;
  h.vertices = handle_vertices_;
  h.targets = handle_targets();
  MPM::write_handles(h, path);
}

} // namespace mpm_demo
