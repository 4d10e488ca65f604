// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Viewer.h"

#include <CGAL/MPM/Part_colors.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <QMouseEvent>

#include <cmath>
#include <chrono>
#include <limits>

namespace mpm_demo {

using CGAL::qglviewer::Vec;

// The AABB tree over the MPM mesh as drawn, rebuilt when a frame moved it.
class Picking_tree
{
public:
  using K = CGAL::Simple_cartesian<double>;
  using Triangles = std::vector<K::Triangle_3>;
  using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

  Picking_tree(const Point_matrix& p, const std::vector<CGAL::MPM::Triangle>& triangles)
  {
    const auto point = [&p](int v) { return K::Point_3(p(v, 0), p(v, 1), p(v, 2)); };
    triangles_.reserve(triangles.size());
    for(const CGAL::MPM::Triangle& t : triangles) triangles_.emplace_back(point(t[0]), point(t[1]), point(t[2]));
    tree_.insert(triangles_.cbegin(), triangles_.cend());
    tree_.build();
  }

  /// First face hit by the ray and the hit point; face -1 when none.
  std::pair<int, K::Point_3> first_hit(const K::Point_3& origin, const K::Vector_3& direction) const
  {
    if(triangles_.empty()) return {-1, origin};
    const auto hit = tree_.first_intersection(K::Ray_3(origin, direction));
    if(!hit) return {-1, origin};
    const K::Point_3* point = boost::get<K::Point_3>(&hit->first);
    const int face = int(hit->second - triangles_.cbegin());
    return {face, point ? *point : triangles_[face].vertex(0)};
  }

private:
  Triangles triangles_;
  Tree tree_;
};

namespace {

const char* const vertex_shader = R"(#version 150
in highp vec3 vertex;
in highp vec3 color;
uniform highp mat4 mvp_matrix;
uniform highp mat4 mv_matrix;
uniform highp vec3 offset;
uniform highp float point_size;
out highp vec3 f_position;
out highp vec3 f_color;
void main(void)
{
  vec4 p = vec4(vertex + offset, 1.0);
  f_position = (mv_matrix * p).xyz;
  f_color = color;
  gl_PointSize = point_size;
  gl_Position = mvp_matrix * p;
}
)";

// A head light, two-sided (open parts show their inside). Faces are flat:
// the normal is that of the face's plane, from the screen-space derivatives
// of the position, so a frame uploads positions only.
const char* const fragment_shader = R"(#version 150
in highp vec3 f_position;
in highp vec3 f_color;
uniform bool lighting;
uniform bool round_points;
out highp vec4 out_color;
void main(void)
{
  if(round_points && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  if(!lighting) { out_color = vec4(f_color, 1.0); return; }
  vec3 n = normalize(cross(dFdx(f_position), dFdy(f_position)));
  vec3 l = normalize(-f_position);
  float diffuse = abs(dot(n, l));
  float specular = pow(max(dot(reflect(-l, n * sign(dot(n, l))), l), 0.0), 32.0);
  out_color = vec4(f_color * (0.35 + 0.65 * diffuse) + vec3(0.15 * specular), 1.0);
}
)";

QColor handle_color(0, 0, 0);
QColor dragged_color(230, 20, 20);

} // namespace

Viewer::Viewer(Session& session, QWidget* parent) : CGAL::QGLViewer(parent), session_(session)
{
  connect(&session_, &Session::scene_changed, this, &Viewer::on_scene_changed);
  connect(&session_, &Session::positions_changed, this, &Viewer::on_positions_changed);
  connect(this, &QOpenGLWidget::frameSwapped, this, &Viewer::on_frame_swapped);
}

// A QOpenGLWidget's paint goes to the screen only when its window composes
// it with the other widgets and swaps: under Mesa's software rasterizer
// that took about 6 ms of a frame on the 7,178-vertex PSB hand_181, after the paint.
void Viewer::on_frame_swapped()
{
  if(painted_ms_ < 0.) return;
  if(session_.frame_awaits_display() && session_.last_frame().serial == painted_serial_) session_.frame_shown(painted_ms_);
  painted_ms_ = -1.;
}

Viewer::~Viewer()
{
  makeCurrent();
  for(Mesh_buffers& m : meshes_)
  {
    m.corners.destroy();
    m.colors.destroy();
  }
  scratch_positions_.destroy();
  scratch_colors_.destroy();
  vao_.destroy();
  doneCurrent();
}

void Viewer::init()
{
  setBackgroundColor(Qt::white);
  setAxisIsDrawn(false);
  program_.addShaderFromSourceCode(QOpenGLShader::Vertex, vertex_shader);
  program_.addShaderFromSourceCode(QOpenGLShader::Fragment, fragment_shader);
  if(!program_.link())
  {
    Q_EMIT message("OpenGL: the shaders did not link: " + program_.log());
    return;
  }
  vao_.create();
  for(Mesh_buffers& m : meshes_)
  {
    m.corners.create();
    m.colors.create();
  }
  scratch_positions_.create();
  scratch_colors_.create();
  gl_ready_ = true;
  frame_scene();
}

void Viewer::on_scene_changed()
{
  selected_part_ = -1;
  dragged_handle_ = -1;
  tree_dirty_ = true;
  for(Mesh_buffers& m : meshes_) m.corners_dirty = m.colors_dirty = true;
  const Point_matrix& rest = session_.rest().points;
  if(rest.rows() == 0) return update();
  const Eigen::RowVector3d lo = rest.colwise().minCoeff(), hi = rest.colwise().maxCoeff();
  if(rest.rows() == framed_vertices_ && lo == framed_lo_ && hi == framed_hi_) return update();
  framed_vertices_ = rest.rows();
  framed_lo_ = lo;
  framed_hi_ = hi;
  frame_scene();
}

void Viewer::on_positions_changed()
{
  tree_dirty_ = true;
  for(Mesh_buffers& m : meshes_) m.corners_dirty = true;
  update();
}

bool Viewer::split() const { return session_.arap() && session_.arap_positions().rows() > 0; }

Vec Viewer::split_offset() const
{
  if(!session_.arap()) return Vec(0, 0, 0);
  const Point_matrix& p = session_.rest().points;
  if(p.rows() == 0) return Vec(0, 0, 0);
  const double diameter = CGAL::MPM::internal::bounding_box_diagonal(p);
  return camera()->rightVector() * (0.55 * diameter);
}

void Viewer::frame_scene()
{
  const Point_matrix& p = session_.positions().rows() > 0 ? session_.positions() : session_.rest().points;
  if(p.rows() == 0) return;
  const Eigen::RowVector3d lo = p.colwise().minCoeff(), hi = p.colwise().maxCoeff();
  const Eigen::RowVector3d centre = 0.5 * (lo + hi);
  const double diameter = (hi - lo).norm();
  // Depth range: the mesh, and the ARAP copy beside it.
  setSceneCenter(Vec(centre(0), centre(1), centre(2)));
  setSceneRadius(0.5 * diameter * (session_.arap() ? 2.2 : 1.));
  // Frame the extent seen from the camera (wider when ARAP is beside MPM)
  // rather than the bounding sphere, which leaves wide margins.
  const Vec right = camera()->rightVector(), up = camera()->upVector();
  const Eigen::RowVector3d r(right.x, right.y, right.z), u(up.x, up.y, up.z);
  const double half_width = ((p.rowwise() - centre) * r.transpose()).cwiseAbs().maxCoeff() +
                            (session_.arap() ? 0.55 * diameter : 0.);
  const double half_height = ((p.rowwise() - centre) * u.transpose()).cwiseAbs().maxCoeff();
  const double aspect = height() > 0 ? double(width()) / height() : 1.;
  camera()->setScreenWidthAndHeight(width(), height());
  camera()->fitSphere(sceneCenter(), 1.1 * std::max(half_height, half_width / std::max(aspect, 1e-3)));
  // Perspective enlarges what is near the camera: step back until a sample
  // of the points (both copies when split) is inside the picture.
  const Eigen::RowVector3d shift = (session_.arap() ? 0.55 * diameter : 0.) * r;
  const Eigen::Index step = std::max<Eigen::Index>(1, p.rows() / 2000);
  for(int attempt = 0; attempt < 30; ++attempt)
  {
    camera()->computeModelViewMatrix(); // projectedCoordinatesOf() reads cached matrices
    camera()->computeProjectionMatrix();
    double extent = 0.;
    for(Eigen::Index i = 0; i < p.rows(); i += step)
      for(int side = -1; side <= 1; side += 2)
      {
        const Eigen::RowVector3d x = p.row(i) + side * shift;
        const Vec s = camera()->projectedCoordinatesOf(Vec(x(0), x(1), x(2)));
        extent = std::max({extent, std::abs(2. * s.x / width() - 1.), std::abs(2. * s.y / height() - 1.)});
      }
    if(extent <= 0.92) break;
    camera()->setPosition(sceneCenter() + (camera()->position() - sceneCenter()) * 1.08);
  }
  update();
}

void Viewer::set_view(double azimuth, double elevation)
{
  const double a = azimuth * CGAL_PI / 180., e = elevation * CGAL_PI / 180.;
  const Vec from_centre(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
  camera()->setViewDirection(-from_centre);
  camera()->setUpVector(Vec(0, 1, 0), false);
  camera()->setViewDirection(-from_centre);
  frame_scene();
}

void Viewer::select_part(int node)
{
  selected_part_ = node;
  meshes_[0].colors_dirty = true;
  update();
}

namespace {

// Fills `buffer` with `data`, reallocating only when the size changed.
void fill(QOpenGLBuffer& buffer, const std::vector<float>& data)
{
  const int bytes = int(data.size() * sizeof(float));
  buffer.bind();
  if(buffer.size() == bytes) buffer.write(0, data.data(), bytes);
  else buffer.allocate(data.data(), bytes);
  buffer.release();
}

} // namespace

void Viewer::upload(Mesh_buffers& mesh, const Point_matrix& p, bool highlight)
{
  const std::vector<CGAL::MPM::Triangle>& triangles = session_.rest().triangles;
  if(mesh.corners_dirty)
  {
    scratch_.resize(triangles.size() * 9);
    float* out = scratch_.data();
    for(const CGAL::MPM::Triangle& t : triangles)
      for(int v : t)
        for(int d = 0; d < 3; ++d) *out++ = float(p(v, d));
    fill(mesh.corners, scratch_);
    mesh.corners_dirty = false;
  }
  if(mesh.colors_dirty)
  {
    const std::vector<int>& types = session_.face_types();
    const std::vector<int>& nodes = session_.face_nodes();
    scratch_.resize(triangles.size() * 9);
    float* out = scratch_.data();
    for(std::size_t f = 0; f < triangles.size(); ++f)
    {
      const CGAL::MPM::Rgb_color c = CGAL::MPM::part_type_color(types[f]);
      const float boost = highlight && nodes[f] == selected_part_ ? 0.45f : 0.f;
      for(int k = 0; k < 3; ++k)
        for(int d = 0; d < 3; ++d) *out++ = float(c[d]) / 255.f * (1.f - boost) + boost;
    }
    fill(mesh.colors, scratch_);
    mesh.colors_dirty = false;
  }
}

void Viewer::draw_mesh(Mesh_buffers& mesh, const Point_matrix& p, const Vec& offset, bool highlight)
{
  upload(mesh, p, highlight);
  vao_.bind();
  mesh.corners.bind();
  program_.enableAttributeArray("vertex");
  program_.setAttributeBuffer("vertex", GL_FLOAT, 0, 3);
  mesh.colors.bind();
  program_.enableAttributeArray("color");
  program_.setAttributeBuffer("color", GL_FLOAT, 0, 3);
  mesh.colors.release();
  program_.setUniformValue("offset", QVector3D(float(offset.x), float(offset.y), float(offset.z)));
  program_.setUniformValue("lighting", true);
  program_.setUniformValue("point_size", 1.f);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(session_.rest().triangles.size() * 3));

  // Seams as dark lines, slightly in front of the surface.
  if(show_seams && !session_.seam_edges().empty())
  {
    std::vector<float> lines, line_colors;
    for(const std::array<int, 2>& e : session_.seam_edges())
      for(int v : e)
        for(int d = 0; d < 3; ++d)
        {
          lines.push_back(float(p(v, d)));
          line_colors.push_back(0.1f);
        }
    bind_scratch(lines, line_colors);
    program_.setUniformValue("lighting", false);
    glDepthFunc(GL_LEQUAL);
    glDrawArrays(GL_LINES, 0, GLsizei(lines.size() / 3));
    glDepthFunc(GL_LESS);
  }
  vao_.release();
}

void Viewer::bind_scratch(const std::vector<float>& xyz, const std::vector<float>& colors)
{
  fill(scratch_positions_, xyz);
  fill(scratch_colors_, colors);
  scratch_positions_.bind();
  program_.enableAttributeArray("vertex");
  program_.setAttributeBuffer("vertex", GL_FLOAT, 0, 3);
  scratch_colors_.bind();
  program_.enableAttributeArray("color");
  program_.setAttributeBuffer("color", GL_FLOAT, 0, 3);
  scratch_colors_.release();
}

void Viewer::draw_points(const std::vector<float>& xyz, const QColor& color, float size)
{
  if(xyz.empty()) return;
  std::vector<float> colors;
  colors.reserve(xyz.size());
  for(std::size_t i = 0; i < xyz.size() / 3; ++i)
  {
    colors.push_back(float(color.redF()));
    colors.push_back(float(color.greenF()));
    colors.push_back(float(color.blueF()));
  }
  vao_.bind();
  bind_scratch(xyz, colors);
  program_.setUniformValue("offset", QVector3D(0, 0, 0));
  program_.setUniformValue("lighting", false);
  program_.setUniformValue("point_size", size);
  program_.setUniformValue("round_points", true);
  glDrawArrays(GL_POINTS, 0, GLsizei(xyz.size() / 3));
  program_.setUniformValue("round_points", false);
  vao_.release();
}

void Viewer::draw()
{
  if(!gl_ready_ || session_.rest().points.rows() == 0) return;
  const auto start = std::chrono::steady_clock::now();
  const Point_matrix& p = session_.positions();
  if(p.rows() != session_.rest().points.rows()) return;

  glEnable(GL_DEPTH_TEST);
  glEnable(GL_PROGRAM_POINT_SIZE);
  QMatrix4x4 mvp, mv;
  double m[16];
  camera()->getModelViewProjectionMatrix(m);
  for(int i = 0; i < 16; ++i) mvp.data()[i] = float(m[i]);
  camera()->getModelViewMatrix(m);
  for(int i = 0; i < 16; ++i) mv.data()[i] = float(m[i]);
  program_.bind();
  program_.setUniformValue("round_points", false);
  program_.setUniformValue("mvp_matrix", mvp);
  program_.setUniformValue("mv_matrix", mv);

  const Vec shift = split() ? split_offset() : Vec(0, 0, 0);
  draw_mesh(meshes_[0], p, -shift, true);
  if(split()) draw_mesh(meshes_[1], session_.arap_positions(), shift, false);

  std::vector<float> sites, handles, dragged;
  const auto push = [&](std::vector<float>& out, const Eigen::RowVector3d& x) {
    for(int d = 0; d < 3; ++d) out.push_back(float(x(d) - shift[d]));
  };
  if(show_docking_sites)
    for(int v : session_.docking_vertices()) push(sites, p.row(v));
  const Point_matrix targets = session_.handle_targets();
  const std::vector<int>& groups = session_.handle_groups();
  for(int i = 0; i < targets.rows(); ++i)
    push(dragged_handle_ >= 0 && groups[i] == groups[dragged_handle_] ? dragged : handles, targets.row(i));
  if(split()) // the same handles pull the ARAP mesh
    for(int i = 0; i < targets.rows(); ++i) push(handles, targets.row(i) + 2. * Eigen::RowVector3d(shift.x, shift.y, shift.z));
  glDisable(GL_DEPTH_TEST);
  draw_points(handles, handle_color, 9.f);
  draw_points(dragged, dragged_color, 11.f);
  glEnable(GL_DEPTH_TEST);
  draw_points(sites, QColor(255, 255, 255), 2.f);
  program_.release();
  if(session_.frame_awaits_display())
  {
    // The first paint of a new frame: the GL finishes it here so that the
    // paint's time is its own; the frame is shown when the window's
    // composition has swapped it to the screen (on_frame_swapped()).
    glFinish();
    painted_serial_ = session_.last_frame().serial;
    painted_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }

  if(split())
  {
    // Labels over each half.
    const Point_matrix& r = session_.rest().points;
    const Eigen::RowVector3d top = 0.5 * (r.colwise().minCoeff() + r.colwise().maxCoeff());
    for(int side = 0; side < 2; ++side)
    {
      const Vec at = camera()->projectedCoordinatesOf(Vec(top(0), top(1), top(2)) + (side ? shift : -shift));
      drawText(std::max(4, int(at.x) - 40), 20, side ? "ARAP (CGAL)" : "MPM");
    }
  }
}

std::pair<int, int> Viewer::pick(const QPoint& pixel)
{
  const Point_matrix& p = session_.positions();
  if(p.rows() == 0) return {-1, -1};
  if(tree_dirty_ || !tree_)
  {
    tree_ = std::make_unique<Picking_tree>(p, session_.rest().triangles);
    tree_dirty_ = false;
  }
  Vec origin, direction;
  camera()->convertClickToLine(pixel, origin, direction);
  origin = origin + (split() ? split_offset() : Vec(0, 0, 0));
  using K = Picking_tree::K;
  const auto [face, hit] = tree_->first_hit(K::Point_3(origin.x, origin.y, origin.z),
                                            K::Vector_3(direction.x, direction.y, direction.z));
  if(face < 0) return {-1, -1};
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for(int v : session_.rest().triangles[face])
  {
    const double d = (p.row(v) - Eigen::RowVector3d(hit.x(), hit.y(), hit.z())).squaredNorm();
    if(d < best_distance)
    {
      best_distance = d;
      best = v;
    }
  }
  return {best, face};
}

QPoint Viewer::handle_pixel(int index) const
{
  const Point_matrix targets = session_.handle_targets();
  if(index < 0 || index >= targets.rows()) return QPoint(-1, -1);
  const Vec shift = split() ? split_offset() : Vec(0, 0, 0);
  const Vec s = camera()->projectedCoordinatesOf(Vec(targets(index, 0), targets(index, 1), targets(index, 2)) - shift);
  return QPoint(int(std::lround(s.x)), int(std::lround(s.y)));
}

int Viewer::handle_near(const QPoint& pixel) const
{
  const Point_matrix targets = session_.handle_targets();
  const Vec shift = split() ? split_offset() : Vec(0, 0, 0);
  int best = -1;
  double best_distance = 12. * 12.; // pixels
  for(int i = 0; i < targets.rows(); ++i)
  {
    const Vec s = camera()->projectedCoordinatesOf(Vec(targets(i, 0), targets(i, 1), targets(i, 2)) - shift);
    const double d = (s.x - pixel.x()) * (s.x - pixel.x()) + (s.y - pixel.y()) * (s.y - pixel.y());
    if(d < best_distance)
    {
      best_distance = d;
      best = i;
    }
  }
  return best;
}

void Viewer::cut_click(int vertex, bool remove)
{
  if(remove)
  {
    const int removed = session_.remove_cut_near(vertex);
    Q_EMIT message(removed < 0 ? QString("No cut to remove") : QString("Removed the cut clicked at vertex %1").arg(removed));
    return;
  }
  const CGAL::MPM::Joint_cut& cut = session_.add_cut(vertex);
  Q_EMIT message(QString("Cut at vertex %1: %2 edges, length %3; Alt+click it to remove it")
                   .arg(vertex)
                   .arg(cut.path.size() - 1)
                   .arg(cut.length, 0, 'g', 4));
}

void Viewer::mousePressEvent(QMouseEvent* event)
{
  const Qt::KeyboardModifiers m = event->modifiers();
  if(event->button() != Qt::LeftButton || !(m & (Qt::ShiftModifier | Qt::ControlModifier | Qt::AltModifier)))
  {
    CGAL::QGLViewer::mousePressEvent(event);
    return;
  }
  try
  {
    if(m & Qt::ControlModifier)
    {
      // Ctrl: drag the handle under the cursor (Ctrl+Shift: also join it to
      // the group of the last handle dragged).
      const int h = handle_near(event->pos());
      if(h < 0)
      {
        Q_EMIT message("Ctrl+drag starts on a handle (a black dot); Shift+click adds handles");
        return;
      }
      if((m & Qt::ShiftModifier) && dragged_handle_ >= 0 && dragged_handle_ != h)
        session_.group_handles({dragged_handle_, h});
      dragged_handle_ = h;
      const Point_matrix targets = session_.handle_targets();
      const Vec shift = split() ? split_offset() : Vec(0, 0, 0);
      drag_point_ = Vec(targets(h, 0), targets(h, 1), targets(h, 2)) - shift;
      drag_depth_ = camera()->projectedCoordinatesOf(drag_point_).z;
      update();
      return;
    }
    const auto [vertex, face] = pick(event->pos());
    if(vertex < 0) return;
    if(session_.cutting())
    {
      cut_click(vertex, m & Qt::AltModifier);
      return;
    }
    if(m & Qt::AltModifier)
    {
      select_part(session_.face_nodes()[face]);
      Q_EMIT part_selected(selected_part_);
      return;
    }
    // Shift: toggle a handle at the picked vertex.
    const int existing = session_.handle_of_vertex(vertex);
    if(existing >= 0)
    {
      session_.remove_handle(existing);
      dragged_handle_ = -1;
      Q_EMIT message(QString("Removed the handle at vertex %1").arg(vertex));
    }
    else
    {
      session_.add_handle(vertex);
      dragged_handle_ = session_.handle_of_vertex(vertex);
      Q_EMIT message(QString("Handle %1 at vertex %2: Ctrl+drag it").arg(dragged_handle_).arg(vertex));
    }
    update();
  }
  catch(const std::exception& e)
  {
    Q_EMIT message(QString::fromStdString(e.what()));
  }
}

void Viewer::mouseMoveEvent(QMouseEvent* event)
{
  if(dragged_handle_ < 0 || !(event->buttons() & Qt::LeftButton) || !(event->modifiers() & Qt::ControlModifier))
  {
    CGAL::QGLViewer::mouseMoveEvent(event);
    return;
  }
  // Moves in the plane through the handle parallel to the screen; each
  // move is posted, the solver thread keeps only the latest.
  const Vec to = camera()->unprojectedCoordinatesOf(Vec(event->pos().x(), event->pos().y(), drag_depth_));
  const Vec delta = to - drag_point_;
  drag_point_ = to;
  try
  {
    session_.drag_handle(dragged_handle_, Eigen::RowVector3d(delta.x, delta.y, delta.z));
  }
  catch(const std::exception& e)
  {
    Q_EMIT message(QString::fromStdString(e.what()));
  }
  update();
}

QString Viewer::helpString() const
{
  return "<h2>MPM demo</h2>"
         "<p><b>Shift+click</b> a vertex: add a handle there (again: remove it).<br>"
         "<b>Ctrl+drag</b> a handle (black dot): move it and its group; the solver follows live.<br>"
         "<b>Ctrl+Shift+drag</b> a handle: join it to the group of the last handle dragged.<br>"
         "<b>Alt+click</b> a part: select it for part-graph editing.<br>"
         "On a mesh opened to be cut: <b>Shift+click</b> next to a joint adds the cut around the limb there, "
         "<b>Alt+click</b> removes the nearest cut.<br>"
         "Left drag: rotate, right drag: pan, wheel: zoom.</p>";
}

} // namespace mpm_demo
