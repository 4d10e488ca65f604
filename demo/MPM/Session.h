// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The demo's state: a learned model, the part graph being shown (a training
// example or an assembly edited from the grammar), the handles, the edit
// mode, and a solver thread that embeds the latest request while the window
// stays responsive. Everything is computed by the library's public API.
#ifndef MPM_DEMO_SESSION_H
#define MPM_DEMO_SESSION_H

#include "Raw_mesh_cutting.h"
#include "Solver_thread.h"

#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <QMutex>
#include <QObject>
#include <QString>
#include <QThread>
#include <QWaitCondition>

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mpm_demo {

using CGAL::MPM::Point_matrix;

/// Vertices of a synthetic model when not given: learning takes about a
/// second and dragging stays fluid on a laptop.
constexpr int default_synthetic_vertices = 3000;

/// What the embedding pulls the shape toward.
enum class Edit_mode
{
  deform,     ///< free-form deformation within the learned spaces
  symmetrize, ///< every instance of a type toward the same shape
  caricature  ///< instances scaled away from their type's mean
};

/// The model and everything the viewer and the batch script act on.
class Session : public QObject
{
  Q_OBJECT
public:
  explicit Session(QObject* parent = nullptr);
  ~Session() override;

  /// \name Sources (each throws `Input_error` on bad input and leaves the session unchanged)
  /// @{
  void load_synthetic(const std::string& family, int vertices, unsigned seed);
  void load_labeled_mesh(const std::string& mesh, const std::string& labels, const std::string& annotation);
  void load_model(const std::string& path);
  /// @}
  bool has_model() const { return has_model_; }

  /// \name Starting from a mesh nobody has segmented (no model until `learn_from_cuts()`)
  /// @{
  /// Shows the mesh uncut, ready for cuts; throws `Input_error` naming the file.
  void open_raw_mesh(const std::string& path);
  /// The mesh being cut, or null when a model is shown.
  Raw_mesh_cutting* cutting() { return cutting_.get(); }
  const Raw_mesh_cutting* cutting() const { return cutting_.get(); }
  /// Adds the cut around the limb at `vertex` (one click per joint).
  const CGAL::MPM::Joint_cut& add_cut(int vertex);
  /// Removes the cut nearest `vertex`; returns the vertex it was clicked at, or -1.
  int remove_cut_near(int vertex);
  /// Replaces the cuts with proposed joints; returns the number of limbs.
  int propose_cuts(double sensitivity);
  /// Gives segment `label` of the cut mesh the part type `type`.
  void set_part_type(int label, const std::string& type);
  /// Learns a model from the cut mesh and its part types, and shows it.
  void learn_from_cuts();
  /// @}
  const QString& source_name() const { return source_; }
  /// The synthetic family shown (its command-line name), or empty.
  const std::string& synthetic_family() const { return family_; }
  const CGAL::MPM::Morphable_part_model& model() const { return model_; }

  /// \name What is shown
  /// @{
  /// Connectivity and rest positions of the current problem.
  const CGAL::MPM::Indexed_mesh& rest() const { return rest_; }
  const Point_matrix& positions() const { return frame_.positions; }
  const Point_matrix& arap_positions() const { return frame_.arap_positions; }
  const std::vector<int>& face_types() const { return face_types_; }
  const std::vector<int>& face_nodes() const { return face_nodes_; }
  /// Mesh edges between faces of different parts.
  const std::vector<std::array<int, 2>>& seam_edges() const { return seam_edges_; }
  /// Vertices of the docking sites of all parts.
  const std::vector<int>& docking_vertices() const { return docking_vertices_; }
  /// The part graph shown (its nodes' vertices index `rest()`).
  const CGAL::MPM::Part_graph& shown_graph() const;
  bool graph_edited() const { return graph_edited_; }
  const Solve_frame& last_frame() const { return frame_; }
  /// Whether the last frame came from a request and no paint has shown it yet.
  bool frame_awaits_display() const
  { return frame_.shown_ms < 0. && frame_.posted != std::chrono::steady_clock::time_point(); }
  /// From the request to the screen for the last frame shown (negative
  /// before the first): the last frame's own until the screen shows it.
  double display_ms() const { return display_ms_; }
  /// Called by the viewer when the window has swapped the paint (of
  /// `paint_ms`) of the last frame to the screen: records the display
  /// latency and emits `frame_displayed()`.
  void frame_shown(double paint_ms);
  /// @}

  /// \name Handles (indices into the handle list; a group moves together)
  /// @{
  const std::vector<int>& handle_vertices() const { return handle_vertices_; }
  const std::vector<int>& handle_groups() const { return handle_groups_; }
  Point_matrix handle_targets() const;
  int handle_of_vertex(int vertex) const;
  void add_handle(int vertex);
  void remove_handle(int index);
  void group_handles(const std::vector<int>& indices);
  void set_handles_per_part(int per_part);
  void set_handles_farthest(int count);
  /// A handle on every limb's tip turned about the limb's attachment to the
  /// root by `move` times the diagonal, the root held away from its seams
  /// (`limb_bending_handles()`); the training example only, not an edited graph.
  void set_handles_bending_limbs(double move);
  void clear_handles();
  /// Moves handle `index` and every handle of its group by `delta`.
  void drag_handle(int index, const Eigen::RowVector3d& delta);
  /// @}

  /// \name Edits
  /// @{
  Edit_mode mode() const { return mode_; }
  double caricature_factor() const { return caricature_factor_; }
  double symmetry_sigma() const { return symmetry_sigma_; }
  double coupling() const { return coupling_; }
  bool arap() const { return arap_; }
  void set_mode(Edit_mode mode);
  void set_caricature_factor(double factor);
  void set_symmetry_sigma(double relative_sigma);
  void set_coupling(double weight);
  void set_arap(bool on);
  /// Handle offsets to zero and the solver back to the rest positions.
  void reset();
  /// @}

  /// \name Part-graph editing (the grammar's rules plus derived repetition rules)
  /// @{
  /// The node from which `node`'s branch hangs: its neighbour toward the root.
  int parent_edge(int node) const;
  /// Inserts a segment into the docking between `node` and its neighbour toward the root; returns the new node.
  int insert_segment(int node);
  void remove_segment(int node);
  /// Removes `node` and everything hanging from it (seen from the root).
  void remove_branch(int node);
  /// Copies the branch at `node` onto the root, or else the first part with a
  /// free site the grammar allows; returns the copy.
  int duplicate_branch(int node);
  /// Back to the training example's part graph.
  void reset_graph();
  /// One line per part: node, type, neighbours.
  std::vector<std::string> describe_parts() const;
  /// @}

  /// \name Saving (the results as currently shown)
  /// @{
  void save_mesh(const std::string& path, bool arap_result = false) const;
  void save_model(const std::string& path) const;
  void save_handles(const std::string& path) const;
  /// @}

  /// Processes events until the solver has answered the latest request or
  /// `timeout_ms` passed. Returns false on timeout.
  bool wait_until_solved(int timeout_ms);
  /// Processes events until the last frame is on the screen or `timeout_ms`
  /// passed. Returns false on timeout.
  bool wait_until_shown(int timeout_ms);

Q_SIGNALS:
  /// The connectivity or the colours changed (new model, new part graph).
  void scene_changed();
  /// A new solver frame arrived.
  void positions_changed();
  /// The last frame is on the screen (its `shown_ms` is set).
  void frame_displayed();

private:
  void adopt_model(CGAL::MPM::Morphable_part_model&& model, const QString& source, const std::string& family = "");
  /// Shows the mesh being cut, coloured by its regions.
  void show_cutting();
  /// No handles, the rest positions shown, `scene_changed()` emitted.
  void start_new_scene();
  void require_model(const std::string& what) const;
  /// The mesh being cut; throws `Input_error` naming `what` when there is none.
  Raw_mesh_cutting& require_cutting(const std::string& what);
  void rebuild();
  /// Shows `graph` assembled; when that fails, keeps the graph shown before and rethrows.
  void show_edited_graph(CGAL::MPM::Part_graph&& graph);
  void set_scene(const CGAL::MPM::Indexed_mesh& rest, const CGAL::MPM::Part_graph& graph,
                 std::vector<int> face_nodes);
  /// Handles from the library's choosers, each in its own group.
  void replace_handles(const CGAL::MPM::Handle_set& handles);
  void post(bool restart = false);
  void on_frame(const Solve_frame& frame);
  int root() const;

  CGAL::MPM::Morphable_part_model model_;
  bool has_model_ = false;
  QString source_;
  std::string family_;
  CGAL::MPM::Part_graph edit_graph_;  ///< the graph being edited (no vertices once edited)
  bool graph_edited_ = false;
  CGAL::MPM::Assembly assembly_;      ///< the embedded edited graph
  CGAL::MPM::Indexed_mesh rest_;
  std::vector<int> face_types_, face_nodes_;
  std::vector<std::array<int, 2>> seam_edges_;
  std::vector<int> docking_vertices_;
  std::vector<int> handle_vertices_, handle_groups_;
  Point_matrix handle_offsets_;       ///< target minus rest position, per handle
  Edit_mode mode_ = Edit_mode::deform;
  double caricature_factor_ = 1.5;
  double symmetry_sigma_ = 0.01;
  double coupling_ = 0.;
  bool arap_ = false;
  std::shared_ptr<const CGAL::MPM::Embedding_problem> problem_;
  std::uint64_t serial_ = 0;
  Solve_frame frame_;
  Solver_thread thread_;
  std::unique_ptr<Raw_mesh_cutting> cutting_;
  double display_ms_ = -1.;
};

} // namespace mpm_demo

#endif
