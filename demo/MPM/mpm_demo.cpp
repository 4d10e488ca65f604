// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mpm_demo: interactive editing with a morphable part model, and a batch
// mode (`mpm_demo --batch SCRIPT`) that runs the same edits from a script
// and writes screenshots, for tests and the manual's figures.
#include "Main_window.h"
#include <CGAL/MPM/internal/Bounding_box.h>

#include <CGAL/Qt/init_ogl_context.h>

#include <QApplication>
#include <QImage>
#include <QMouseEvent>
#include <QSet>
#include <QStatusBar>
#include <QWidget>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpm_demo {

namespace {

const char* const usage_text =
  "usage: mpm_demo [--synth FAMILY] [--vertices N] [--seed N]\n"
  "                [--model FILE.mpm | --mesh MESH [--labels SEG|components] [--annotation A.json]]\n"
  "                [--batch SCRIPT] [--size WxH] [--help]\n"
  "Without a source it opens the synthetic hand. --batch runs SCRIPT (doc/MPM/Demo.md)\n"
  "without interaction and exits: 0 when every command succeeded, 1 on the first\n"
  "error (named by its line), 2 for a bad command line.\n";

// The solver must answer a batch request within this time.
constexpr int batch_timeout_ms = 120000;

struct Script_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Image_stats
{
  int distinct_colors = 0;
  double foreground = 0.; // fraction of pixels that differ from the corner pixel (the background)
};

Image_stats image_stats(const QImage& image)
{
  Image_stats s;
  if(image.isNull() || image.width() == 0 || image.height() == 0) return s;
  const QRgb background = image.pixel(0, 0);
  QSet<QRgb> colors;
  long long foreground = 0;
  for(int y = 0; y < image.height(); ++y)
    for(int x = 0; x < image.width(); ++x)
    {
      const QRgb c = image.pixel(x, y);
      if(colors.size() < 100000) colors.insert(c);
      foreground += c != background ? 1 : 0;
    }
  s.distinct_colors = colors.size();
  s.foreground = double(foreground) / (double(image.width()) * image.height());
  return s;
}

// A picture shows something when it has shading (many colours) and an
// object covering a visible share of it.
constexpr int min_distinct_colors = 32;
constexpr double min_foreground = 0.02;
// Two pictures differ when this share of their pixels does.
constexpr double min_differing = 0.002;

QImage read_image(const std::string& path)
{
  QImage image(QString::fromStdString(path));
  if(image.isNull()) throw Script_error("cannot read the image '" + path + "'");
  return image.convertToFormat(QImage::Format_RGB32);
}

void check_not_blank(const QImage& image, const std::string& name)
{
  const Image_stats s = image_stats(image);
  if(s.distinct_colors < min_distinct_colors || s.foreground < min_foreground)
    throw Script_error("the image '" + name + "' looks blank: " + std::to_string(s.distinct_colors) +
                       " distinct colours, " + std::to_string(int(100. * s.foreground)) + "% non-background pixels");
}

class Batch_runner
{
public:
  Batch_runner(Session& session, Main_window& window, const std::string& script)
    : session_(session), window_(window), script_(script)
  {}

  int run()
  {
    std::ifstream in(script_);
    if(!in)
    {
      std::cerr << "mpm_demo: cannot read the script '" << script_ << "'\n";
      return 1;
    }
    std::string line;
    int number = 0;
    while(std::getline(in, line))
    {
      ++number;
      std::istringstream words(line);
      std::vector<std::string> w;
      for(std::string word; words >> word;)
      {
        if(word[0] == '#') break;
        w.push_back(word);
      }
      if(w.empty()) continue;
      try
      {
        execute(w);
        window_.sync_controls(); // the panel shows what the script set
      }
      catch(const std::exception& e)
      {
        std::cerr << script_ << ":" << number << ": " << w[0] << ": " << e.what() << "\n";
        return 1;
      }
    }
    return 0;
  }

private:
  static void arity(const std::vector<std::string>& w, std::size_t lo, std::size_t hi, const char* form)
  {
    if(w.size() < lo + 1 || w.size() > hi + 1) throw Script_error(std::string("expected '") + form + "'");
  }

  static double number(const std::string& s)
  {
    std::size_t end = 0;
    double v = 0.;
    try
    {
      v = std::stod(s, &end);
    }
    catch(const std::exception&)
    {
      end = 0;
    }
    if(end != s.size() || !std::isfinite(v)) throw Script_error("'" + s + "' is not a number");
    return v;
  }

  static int integer(const std::string& s)
  {
    const double v = number(s);
    if(v != std::floor(v) || std::abs(v) > 1e9) throw Script_error("'" + s + "' is not an integer");
    return int(v);
  }

  void send_mouse(QEvent::Type type, const QPoint& at, Qt::KeyboardModifiers modifiers)
  {
    const Qt::MouseButton button = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
    const Qt::MouseButtons held = type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::LeftButton;
    QMouseEvent event(type, QPointF(at), button, held, modifiers);
    QApplication::sendEvent(&window_.viewer(), &event);
    QApplication::processEvents();
  }

  // Waits for the solver's answer to everything posted so far.
  void settle()
  {
    if(!session_.wait_until_solved(batch_timeout_ms)) throw Script_error("the solver did not answer in time");
    const Solve_frame& f = session_.last_frame();
    if(!f.error.isEmpty()) throw Script_error("the solver failed: " + f.error.toStdString());
    window_.viewer().update();
    QApplication::processEvents();
  }

  void report()
  {
    settle();
    std::cout << "  " << window_.solver_status().toStdString() << "\n";
  }

  // Drags handle 0 back and forth (0.2% of the diagonal per frame, turning
  // every 10 frames), each frame solved and painted before the next, and
  // prints the mean solver frame and the mean time from the drag to the end
  // of the paint that showed it.
  void profile_drag(int frames)
  {
    if(frames < 1) throw Script_error("profile-drag needs at least one frame");
    if(session_.handle_vertices().empty()) throw Script_error("profile-drag needs a handle (add one first)");
    const Point_matrix& p = session_.rest().points;
    const double diagonal = CGAL::MPM::internal::bounding_box_diagonal(p);
    const Eigen::RowVector3d step = 0.002 * diagonal * Eigen::RowVector3d(1., 1., 1.).normalized();
    double solver_ms = 0., shown_ms = 0., paint_ms = 0.;
    for(int i = 0; i < frames; ++i)
    {
      session_.drag_handle(0, ((i / 10) % 2 == 0 ? 1. : -1.) * step);
      settle();
      if(session_.frame_awaits_display()) window_.viewer().repaint();
      const Solve_frame& f = session_.last_frame();
      if(f.shown_ms < 0.) throw Script_error("frame " + std::to_string(i) + " was not shown");
      solver_ms += f.ms;
      shown_ms += f.shown_ms;
      paint_ms += f.paint_ms;
    }
    std::cout << "  " << frames << " frames of " << p.rows() << " vertices: solver " << solver_ms / frames
              << " ms, shown " << shown_ms / frames << " ms after the drag (display adds "
              << (shown_ms - solver_ms) / frames << " ms, of which the paint " << paint_ms / frames << " ms)\n";
  }

  void report_model()
  {
    const Point_matrix& p = session_.rest().points;
    std::cout << "  " << session_.source_name().toStdString() << ": " << p.rows() << " vertices, "
              << session_.rest().number_of_faces() << " faces, " << session_.shown_graph().nodes.size() << " parts, "
              << session_.model().types.size() << " part types, " << session_.model().rules.size() << " rules\n";
    report();
  }

  void execute(const std::vector<std::string>& w)
  {
    const std::string& c = w[0];
    std::cout << "> ";
    for(const std::string& s : w) std::cout << s << " ";
    std::cout << "\n";
    if(c == "synth")
    {
      arity(w, 1, 3, "synth FAMILY [VERTICES [SEED]]");
      session_.load_synthetic(w[1], w.size() > 2 ? integer(w[2]) : default_synthetic_vertices, w.size() > 3 ? unsigned(integer(w[3])) : 1u);
      report_model();
    }
    else if(c == "load")
    {
      arity(w, 2, 3, "load MESH LABELS [ANNOTATION]");
      session_.load_labeled_mesh(w[1], w[2], w.size() > 3 ? w[3] : "");
      report_model();
    }
    else if(c == "model")
    {
      arity(w, 1, 1, "model FILE.mpm");
      session_.load_model(w[1]);
      report_model();
    }
    else if(c == "handles")
    {
      arity(w, 1, 2, "handles per-part N | handles farthest N | handles clear");
      if(w[1] == "per-part" && w.size() == 3) session_.set_handles_per_part(integer(w[2]));
      else if(w[1] == "farthest" && w.size() == 3) session_.set_handles_farthest(integer(w[2]));
      else if(w[1] == "clear" && w.size() == 2) session_.clear_handles();
      else throw Script_error("expected 'handles per-part N', 'handles farthest N' or 'handles clear'");
      std::cout << "  " << session_.handle_vertices().size() << " handles\n";
    }
    else if(c == "handle")
    {
      arity(w, 2, 2, "handle add VERTEX | handle remove HANDLE");
      if(w[1] == "add") session_.add_handle(integer(w[2]));
      else if(w[1] == "remove") session_.remove_handle(integer(w[2]));
      else throw Script_error("expected 'handle add VERTEX' or 'handle remove HANDLE'");
    }
    else if(c == "group")
    {
      if(w.size() < 3) throw Script_error("expected 'group HANDLE HANDLE...'");
      std::vector<int> handles;
      for(std::size_t i = 1; i < w.size(); ++i) handles.push_back(integer(w[i]));
      session_.group_handles(handles);
    }
    else if(c == "drag")
    {
      arity(w, 4, 4, "drag HANDLE DX DY DZ");
      const Point_matrix& p = session_.rest().points;
      const double diagonal = CGAL::MPM::internal::bounding_box_diagonal(p);
      session_.drag_handle(integer(w[1]), diagonal * Eigen::RowVector3d(number(w[2]), number(w[3]), number(w[4])));
      report();
    }
    else if(c == "profile-drag")
    {
      arity(w, 1, 1, "profile-drag FRAMES");
      profile_drag(integer(w[1]));
    }
    else if(c == "deform" || c == "symmetrize" || c == "caricature")
    {
      if(c == "deform")
      {
        arity(w, 0, 0, "deform");
        session_.set_mode(Edit_mode::deform);
      }
      else if(c == "symmetrize")
      {
        arity(w, 0, 1, "symmetrize [RELATIVE-SIGMA]");
        session_.set_symmetry_sigma(w.size() > 1 ? number(w[1]) : session_.symmetry_sigma());
      }
      else
      {
        arity(w, 1, 1, "caricature FACTOR");
        session_.set_caricature_factor(number(w[1]));
      }
      report();
    }
    else if(c == "coupling")
    {
      arity(w, 1, 1, "coupling WEIGHT");
      session_.set_coupling(number(w[1]));
      report();
    }
    else if(c == "arap")
    {
      arity(w, 1, 1, "arap on|off");
      if(w[1] != "on" && w[1] != "off") throw Script_error("expected 'arap on' or 'arap off'");
      session_.set_arap(w[1] == "on");
      report();
      window_.viewer().frame_scene();
    }
    else if(c == "reset")
    {
      arity(w, 0, 0, "reset");
      session_.reset();
      report();
    }
    else if(c == "insert" || c == "remove" || c == "remove-branch" || c == "duplicate")
    {
      arity(w, 1, 1, "insert|remove|remove-branch|duplicate PART");
      const int part = integer(w[1]);
      if(c == "insert")
      {
        const int added = session_.insert_segment(part);
        std::cout << "  new part " << added << "\n";
      }
      else if(c == "remove") session_.remove_segment(part);
      else if(c == "remove-branch") session_.remove_branch(part);
      else
      {
        const int copy = session_.duplicate_branch(part);
        std::cout << "  copy at part " << copy << "\n";
      }
      report();
    }
    else if(c == "reset-graph")
    {
      arity(w, 0, 0, "reset-graph");
      session_.reset_graph();
      report();
    }
    else if(c == "parts")
    {
      arity(w, 0, 0, "parts");
      for(const std::string& line : session_.describe_parts()) std::cout << "  " << line << "\n";
    }
    else if(c == "click")
    {
      // The interactive path: a synthetic mouse click on the viewer.
      arity(w, 3, 3, "click X Y shift|alt");
      if(w[3] != "shift" && w[3] != "alt") throw Script_error("expected 'click X Y shift' or 'click X Y alt'");
      const std::size_t before = session_.handle_vertices().size();
      const QPoint at(integer(w[1]), integer(w[2]));
      send_mouse(QEvent::MouseButtonPress, at, w[3] == "shift" ? Qt::ShiftModifier : Qt::AltModifier);
      send_mouse(QEvent::MouseButtonRelease, at, w[3] == "shift" ? Qt::ShiftModifier : Qt::AltModifier);
      if(w[3] == "shift")
      {
        if(session_.handle_vertices().size() == before) throw Script_error("no vertex under the pixel");
        std::cout << "  " << session_.handle_vertices().size() << " handles\n";
      }
      else
      {
        if(window_.viewer().selected_part() < 0) throw Script_error("no part under the pixel");
        std::cout << "  selected part " << window_.viewer().selected_part() << "\n";
      }
    }
    else if(c == "mouse-drag")
    {
      // Ctrl+drag of a handle in small mouse moves, each posted to the
      // solver thread as the window would; only the latest target counts.
      arity(w, 3, 4, "mouse-drag HANDLE DX DY [STEPS]");
      const int steps = w.size() > 4 ? integer(w[4]) : 20;
      if(steps < 1) throw Script_error("STEPS must be at least 1");
      settle();
      const QPoint from = window_.viewer().handle_pixel(integer(w[1]));
      if(from.x() < 0) throw Script_error("handle " + w[1] + " does not exist");
      const QPoint by(integer(w[2]), integer(w[3]));
      send_mouse(QEvent::MouseButtonPress, from, Qt::ControlModifier);
      for(int i = 1; i <= steps; ++i) send_mouse(QEvent::MouseMove, from + by * i / steps, Qt::ControlModifier);
      send_mouse(QEvent::MouseButtonRelease, from + by, Qt::ControlModifier);
      report();
    }
    else if(c == "window-size")
    {
      // The window as a user sees it (the viewer takes the room left).
      arity(w, 2, 2, "window-size WIDTH HEIGHT");
      const int width = integer(w[1]), height = integer(w[2]);
      if(width < 320 || height < 240 || width > 4096 || height > 4096)
        throw Script_error("the window size must be between 320x240 and 4096x4096 pixels");
      window_.viewer().setMinimumSize(0, 0);
      window_.viewer().setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
      window_.resize(width, height);
      QApplication::processEvents();
      window_.viewer().frame_scene();
    }
    else if(c == "screenshot-window")
    {
      arity(w, 1, 1, "screenshot-window FILE.png");
      settle();
      if(!window_.grab().save(QString::fromStdString(w[1])))
        throw Script_error("cannot write the screenshot '" + w[1] + "'");
      std::cout << "  wrote " << w[1] << "\n";
    }
    else if(c == "select")
    {
      arity(w, 1, 1, "select PART");
      window_.viewer().select_part(integer(w[1]));
    }
    else if(c == "view")
    {
      arity(w, 2, 2, "view AZIMUTH ELEVATION");
      window_.viewer().set_view(number(w[1]), number(w[2]));
    }
    else if(c == "size")
    {
      arity(w, 2, 2, "size WIDTH HEIGHT");
      const int width = integer(w[1]), height = integer(w[2]);
      if(width < 64 || height < 64 || width > 4096 || height > 4096)
        throw Script_error("the size must be between 64 and 4096 pixels");
      window_.viewer().setFixedSize(width, height);
      window_.adjustSize();
      QApplication::processEvents();
    }
    else if(c == "seams" || c == "sites")
    {
      arity(w, 1, 1, "seams|sites on|off");
      (c == "seams" ? window_.viewer().show_seams : window_.viewer().show_docking_sites) = w[1] == "on";
    }
    else if(c == "wait")
    {
      arity(w, 0, 0, "wait");
      report();
    }
    else if(c == "screenshot")
    {
      arity(w, 1, 1, "screenshot FILE.png");
      settle();
      const QImage image = window_.viewer().grabFramebuffer();
      if(image.isNull() || !image.save(QString::fromStdString(w[1])))
        throw Script_error("cannot write the screenshot '" + w[1] + "'");
      const Image_stats s = image_stats(image.convertToFormat(QImage::Format_RGB32));
      std::cout << "  wrote " << w[1] << " (" << image.width() << "x" << image.height() << ", "
                << s.distinct_colors << " colours, " << int(100. * s.foreground + 0.5) << "% foreground)\n";
    }
    else if(c == "save-mesh")
    {
      arity(w, 1, 2, "save-mesh FILE [arap]");
      if(w.size() == 3 && w[2] != "arap") throw Script_error("expected 'save-mesh FILE [arap]'");
      settle();
      session_.save_mesh(w[1], w.size() == 3);
    }
    else if(c == "save-model")
    {
      arity(w, 1, 1, "save-model FILE");
      session_.save_model(w[1]);
    }
    else if(c == "save-handles")
    {
      arity(w, 1, 1, "save-handles FILE");
      session_.save_handles(w[1]);
    }
    else if(c == "check-image")
    {
      arity(w, 1, 1, "check-image FILE.png");
      check_not_blank(read_image(w[1]), w[1]);
      std::cout << "  not blank\n";
    }
    else if(c == "compare-images")
    {
      arity(w, 2, 2, "compare-images A.png B.png");
      const QImage a = read_image(w[1]), b = read_image(w[2]);
      check_not_blank(a, w[1]);
      check_not_blank(b, w[2]);
      double differing = 1.;
      if(a.size() == b.size())
      {
        long long count = 0;
        for(int y = 0; y < a.height(); ++y)
          for(int x = 0; x < a.width(); ++x) count += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
        differing = double(count) / (double(a.width()) * a.height());
      }
      if(differing < min_differing)
        throw Script_error("'" + w[1] + "' and '" + w[2] + "' are the same picture (" +
                           std::to_string(100. * differing) + "% of the pixels differ)");
      std::cout << "  " << 100. * differing << "% of the pixels differ\n";
    }
    else if(c == "echo")
    {
      for(std::size_t i = 1; i < w.size(); ++i) std::cout << (i > 1 ? " " : "  ") << w[i];
      std::cout << "\n";
    }
    else
      throw Script_error("unknown command '" + c + "' (see doc/MPM/Demo.md for the list)");
  }

  Session& session_;
  Main_window& window_;
  std::string script_;
};

} // namespace

} // namespace mpm_demo

int main(int argc, char** argv)
{
  using namespace mpm_demo;
  CGAL::Qt::init_ogl_context(4, 3);
  QApplication app(argc, argv);
  app.setApplicationName("mpm_demo");

  std::string batch, family = "hand", model, mesh, labels = "components", annotation;
  int vertices = default_synthetic_vertices, width = 0, height = 0;
  unsigned seed = 1;
  const QStringList args = app.arguments();
  try
  {
    for(int i = 1; i < args.size(); ++i)
    {
      const std::string a = args[i].toStdString();
      const auto value = [&]() -> std::string {
        if(i + 1 >= args.size()) throw std::invalid_argument("option " + a + " needs a value");
        return args[++i].toStdString();
      };
      if(a == "--help" || a == "-h")
      {
        std::cout << usage_text;
        return 0;
      }
      else if(a == "--batch") batch = value();
      else if(a == "--synth") family = value();
      else if(a == "--vertices") vertices = std::stoi(value());
      else if(a == "--seed") seed = unsigned(std::stoul(value()));
      else if(a == "--model") model = value();
      else if(a == "--mesh") mesh = value();
      else if(a == "--labels") labels = value();
      else if(a == "--annotation") annotation = value();
      else if(a == "--size")
      {
        const std::string s = value();
        const std::size_t x = s.find('x');
        if(x == std::string::npos) throw std::invalid_argument("--size takes WIDTHxHEIGHT");
        width = std::stoi(s.substr(0, x));
        height = std::stoi(s.substr(x + 1));
      }
      else throw std::invalid_argument("unknown option '" + a + "'");
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "mpm_demo: " << e.what() << "\n" << usage_text;
    return 2;
  }

  Session session;
  Main_window window(session);
  if(batch.empty() && width == 0) window.resize(1280, 800);
  if(!batch.empty() && width == 0)
  {
    width = 640;
    height = 480;
  }
  if(width > 0) window.viewer().setFixedSize(width, height);
  window.show();
  QApplication::processEvents();

  // A batch script loads its own model; otherwise start with something to drag.
  try
  {
    if(!model.empty()) session.load_model(model);
    else if(!mesh.empty()) session.load_labeled_mesh(mesh, labels, annotation);
    else if(batch.empty()) session.load_synthetic(family, vertices, seed);
  }
  catch(const std::exception& e)
  {
    if(!batch.empty())
    {
      std::cerr << "mpm_demo: " << e.what() << "\n";
      return 1;
    }
    window.statusBar()->showMessage(QString("Error: ") + e.what());
  }

  if(!batch.empty())
  {
    Batch_runner runner(session, window, batch);
    return runner.run();
  }
  window.viewer().set_view(0., 20.);
  return app.exec();
}
