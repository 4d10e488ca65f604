// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The 3D view: parts coloured by type, seams, docking sites and handles on
// CGAL's QGLViewer; ray picking of vertices and parts with CGAL's AABB tree;
// handles dragged in the screen plane; ARAP's result beside MPM's.
#ifndef MPM_DEMO_VIEWER_H
#define MPM_DEMO_VIEWER_H

#include "Session.h"

#include <CGAL/Qt/qglviewer.h>

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>

#include <cstdint>
#include <memory>
#include <vector>

namespace mpm_demo {

class Picking_tree;

class Viewer : public CGAL::QGLViewer
{
  Q_OBJECT
public:
  explicit Viewer(Session& session, QWidget* parent = nullptr);
  ~Viewer() override;

  /// Looks at the scene from `azimuth` degrees around the up axis (y) and
  /// `elevation` degrees above the horizontal, framing it whole.
  void set_view(double azimuth, double elevation);
  /// Frames the whole scene (both meshes when ARAP is shown).
  void frame_scene();
  int selected_part() const { return selected_part_; }
  void select_part(int node);
  /// Where handle `index`'s target is drawn, in widget pixels.
  QPoint handle_pixel(int index) const;
  bool show_seams = true;
  bool show_docking_sites = true;

Q_SIGNALS:
  void part_selected(int node);
  void message(const QString& text);

protected:
  void init() override;
  void draw() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  QString helpString() const override;

private:
  void on_scene_changed();
  void on_positions_changed();
  void on_frame_swapped();
  /// Vertex and face of the MPM mesh under a pixel; {-1, -1} when none.
  std::pair<int, int> pick(const QPoint& pixel);
  /// On a mesh being cut: Shift+click adds the cut at `vertex`, Alt+click removes the nearest.
  void cut_click(int vertex, bool remove);
  /// Handle whose target is drawn within a few pixels of `pixel`, or -1.
  int handle_near(const QPoint& pixel) const;
  /// World offset of the MPM mesh (left) and of the ARAP mesh (right).
  CGAL::qglviewer::Vec split_offset() const;
  bool split() const;
  /// A drawn mesh's buffers: three corners per face (positions, and colours
  /// by part type), filled again only when the positions or colours changed.
  struct Mesh_buffers
  {
    QOpenGLBuffer corners{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer colors{QOpenGLBuffer::VertexBuffer};
    bool corners_dirty = true;
    bool colors_dirty = true;
  };
  void upload(Mesh_buffers& mesh, const Point_matrix& positions, bool highlight);
  void draw_mesh(Mesh_buffers& mesh, const Point_matrix& positions, const CGAL::qglviewer::Vec& offset,
                 bool highlight);
  /// Binds `xyz` and `colors` (one RGB per point) as the vertex attributes
  /// of a small drawing (lines, points).
  void bind_scratch(const std::vector<float>& xyz, const std::vector<float>& colors);
  void draw_points(const std::vector<float>& xyz, const QColor& color, float size);

  Session& session_;
  QOpenGLShaderProgram program_;
  QOpenGLVertexArrayObject vao_;
  Mesh_buffers meshes_[2]; // MPM's mesh, ARAP's beside it
  QOpenGLBuffer scratch_positions_, scratch_colors_;
  std::vector<float> scratch_;
  /// The rest mesh the view was last framed on, as its vertex count and
  /// bounding box: a scene change that keeps it (new labels after a cut
  /// click, a new edit mode) keeps the user's view.
  Eigen::Index framed_vertices_ = -1;
  Eigen::RowVector3d framed_lo_ = Eigen::RowVector3d::Zero(), framed_hi_ = Eigen::RowVector3d::Zero();
  bool gl_ready_ = false;
  /// The frame painted and waiting for the window's swap, and its paint time
  /// (negative when none waits).
  std::uint64_t painted_serial_ = 0;
  double painted_ms_ = -1.;
  std::unique_ptr<Picking_tree> tree_;
  bool tree_dirty_ = true;
  int selected_part_ = -1;
  int dragged_handle_ = -1;
  double drag_depth_ = 0.;
  CGAL::qglviewer::Vec drag_point_;
};

} // namespace mpm_demo

#endif
