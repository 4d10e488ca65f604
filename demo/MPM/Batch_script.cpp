// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Batch_script.h"

#include "Main_window.h"
#include <CGAL/MPM/internal/Bounding_box.h>

#include <QApplication>
#include <QImage>
#include <QMouseEvent>
#include <QSet>
#include <QWidget>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <set>
#include <string>
#include <vector>

namespace mpm_demo {

namespace {

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

// Share of the pixels in which two images differ (1 when their sizes do).
double differing_share(const QImage& a, const QImage& b)
{
  if(a.size() != b.size()) return 1.;
  long long count = 0;
  for(int y = 0; y < a.height(); ++y)
    for(int x = 0; x < a.width(); ++x) count += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
  return double(count) / (double(a.width()) * a.height());
}

double number(const std::string& s)
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

int integer(const std::string& s)
{
  const double v = number(s);
  if(v != std::floor(v) || std::abs(v) > 1e9) throw Script_error("'" + s + "' is not an integer");
  return int(v);
}

// A script line: the command's name, then its arguments.
using Words = std::vector<std::string>;

// A command of the script language: how many arguments it takes, the form
// named in the error when their number is wrong, and what it does.
struct Command
{
  std::size_t min_args = 0, max_args = 0;
  std::string usage;
  std::function<void(const Words&)> run;
};

constexpr std::size_t any_number = std::numeric_limits<std::size_t>::max();

// Forms shared by commands that were one branch of the interpreter: their
// errors name all of them, as before.
const char* const part_edit_usage = "insert|remove|remove-branch|duplicate PART";
const char* const overlay_usage = "seams|sites on|off";

class Batch_runner
{
public:
  Batch_runner(Session& session, Main_window& window, const std::string& script)
    : session_(session), window_(window), script_(script)
  {
    add_model_commands();
    add_cutting_commands();
    add_handle_commands();
    add_edit_commands();
    add_graph_commands();
    add_view_commands();
    add_output_commands();
  }

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
      Words w;
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
  void add(const std::string& name, std::size_t min_args, std::size_t max_args, const std::string& usage,
           std::function<void(const Words&)> run)
  {
    commands_[name] = Command{min_args, max_args, usage, std::move(run)};
  }

  void execute(const Words& w)
  {
    std::cout << "> ";
    for(const std::string& s : w) std::cout << s << " ";
    std::cout << "\n";
    const auto it = commands_.find(w[0]);
    if(it == commands_.end())
      throw Script_error("unknown command '" + w[0] + "' (see doc/MPM/Demo.md for the list)");
    const Command& c = it->second;
    const std::size_t args = w.size() - 1;
    if(args < c.min_args || args > c.max_args) throw Script_error("expected '" + c.usage + "'");
    c.run(w);
  }

  void add_model_commands()
  {
    add("synth", 1, 3, "synth FAMILY [VERTICES [SEED]]", [this](const Words& w) {
      session_.load_synthetic(w[1], w.size() > 2 ? integer(w[2]) : default_synthetic_vertices,
                              w.size() > 3 ? unsigned(integer(w[3])) : 1u);
      report_model();
    });
    add("load", 2, 3, "load MESH LABELS [ANNOTATION]", [this](const Words& w) {
      session_.load_labeled_mesh(w[1], w[2], w.size() > 3 ? w[3] : "");
      report_model();
    });
    add("model", 1, 1, "model FILE.mpm", [this](const Words& w) {
      session_.load_model(w[1]);
      report_model();
    });
  }

  // A mesh nobody has segmented: cut it (clicks or proposed joints), show
  // and edit the proposed part types, learn.
  void add_cutting_commands()
  {
    add("open", 1, 1, "open MESH", [this](const Words& w) {
      session_.open_raw_mesh(w[1]);
      std::cout << "  " << w[1] << ": " << session_.rest().number_of_vertices() << " vertices, to be cut\n";
    });
    add("cut-at", 1, 1, "cut-at VERTEX", [this](const Words& w) {
      const CGAL::MPM::Joint_cut& cut = session_.add_cut(integer(w[1]));
      std::cout << "  cut of " << cut.path.size() - 1 << " edges, length " << cut.length << "\n";
      report_cutting();
    });
    add("uncut", 1, 1, "uncut VERTEX", [this](const Words& w) {
      const int removed = session_.remove_cut_near(integer(w[1]));
      std::cout << "  removed the cut clicked at vertex " << removed << "\n";
      report_cutting();
    });
    add("cut-auto", 0, 1, "cut-auto [SENSITIVITY]", [this](const Words& w) {
      const int limbs = session_.propose_cuts(w.size() > 1 ? number(w[1]) : 0.5);
      std::cout << "  " << limbs << " limbs\n";
      report_cutting();
    });
    add("types", 0, 0, "types", [this](const Words&) {
      if(!session_.cutting()) throw Script_error("no mesh is being cut (use 'open MESH')");
      for(const CGAL::MPM::Segment_proposal& s : session_.cutting()->part_types().segments)
        std::cout << "  label " << s.label << ": " << s.faces << " faces, " << s.seam_loops << " seams, depth "
                  << s.depth << ", type " << s.type << "\n";
    });
    add("set-type", 2, 2, "set-type LABEL TYPE", [this](const Words& w) { session_.set_part_type(integer(w[1]), w[2]); });
    add("learn", 0, 0, "learn", [this](const Words&) {
      session_.learn_from_cuts();
      report_model();
    });
  }

  void report_cutting()
  {
    const Raw_mesh_cutting& c = *session_.cutting();
    std::cout << "  " << c.cuts().size() << " cuts, "
              << std::set<int>(c.labels().begin(), c.labels().end()).size() << " parts\n";
  }

  void add_handle_commands()
  {
    add("handles", 1, 2, "handles per-part N | handles farthest N | handles bend-limbs MOVE | handles clear", [this](const Words& w) {
      if(w[1] == "per-part" && w.size() == 3) session_.set_handles_per_part(integer(w[2]));
      else if(w[1] == "farthest" && w.size() == 3) session_.set_handles_farthest(integer(w[2]));
      else if(w[1] == "bend-limbs" && w.size() == 3) session_.set_handles_bending_limbs(number(w[2]));
      else if(w[1] == "clear" && w.size() == 2) session_.clear_handles();
      else throw Script_error("expected 'handles per-part N', 'handles farthest N', 'handles bend-limbs MOVE' or 'handles clear'");
      std::cout << "  " << session_.handle_vertices().size() << " handles\n";
    });
    add("handle", 2, 2, "handle add VERTEX | handle remove HANDLE", [this](const Words& w) {
      if(w[1] == "add") session_.add_handle(integer(w[2]));
      else if(w[1] == "remove") session_.remove_handle(integer(w[2]));
      else throw Script_error("expected 'handle add VERTEX' or 'handle remove HANDLE'");
    });
    add("group", 2, any_number, "group HANDLE HANDLE...", [this](const Words& w) {
      std::vector<int> handles;
      for(std::size_t i = 1; i < w.size(); ++i) handles.push_back(integer(w[i]));
      session_.group_handles(handles);
    });
    add("drag", 4, 4, "drag HANDLE DX DY DZ", [this](const Words& w) {
      const double diagonal = CGAL::MPM::internal::bounding_box_diagonal(session_.rest().points);
      session_.drag_handle(integer(w[1]), diagonal * Eigen::RowVector3d(number(w[2]), number(w[3]), number(w[4])));
      report();
    });
    add("profile-drag", 1, 1, "profile-drag FRAMES", [this](const Words& w) { profile_drag(integer(w[1])); });
    add("click", 3, 3, "click X Y shift|alt", [this](const Words& w) { click(w); });
    add("mouse-drag", 3, 4, "mouse-drag HANDLE DX DY [STEPS]", [this](const Words& w) { mouse_drag(w); });
  }

  void add_edit_commands()
  {
    add("deform", 0, 0, "deform", [this](const Words&) {
      session_.set_mode(Edit_mode::deform);
      report();
    });
    add("symmetrize", 0, 1, "symmetrize [RELATIVE-SIGMA]", [this](const Words& w) {
      session_.set_symmetry_sigma(w.size() > 1 ? number(w[1]) : session_.symmetry_sigma());
      report();
    });
    add("caricature", 1, 1, "caricature FACTOR", [this](const Words& w) {
      session_.set_caricature_factor(number(w[1]));
      report();
    });
    add("coupling", 1, 1, "coupling WEIGHT", [this](const Words& w) {
      session_.set_coupling(number(w[1]));
      report();
    });
    add("arap", 1, 1, "arap on|off", [this](const Words& w) {
      if(w[1] != "on" && w[1] != "off") throw Script_error("expected 'arap on' or 'arap off'");
      session_.set_arap(w[1] == "on");
      report();
      window_.viewer().frame_scene();
    });
    add("reset", 0, 0, "reset", [this](const Words&) {
      session_.reset();
      report();
    });
  }

  void add_graph_commands()
  {
    add("insert", 1, 1, part_edit_usage, [this](const Words& w) {
      const int added = session_.insert_segment(integer(w[1]));
      std::cout << "  new part " << added << "\n";
      report();
    });
    add("remove", 1, 1, part_edit_usage, [this](const Words& w) {
      session_.remove_segment(integer(w[1]));
      report();
    });
    add("remove-branch", 1, 1, part_edit_usage, [this](const Words& w) {
      session_.remove_branch(integer(w[1]));
      report();
    });
    add("duplicate", 1, 1, part_edit_usage, [this](const Words& w) {
      const int copy = session_.duplicate_branch(integer(w[1]));
      std::cout << "  copy at part " << copy << "\n";
      report();
    });
    add("reset-graph", 0, 0, "reset-graph", [this](const Words&) {
      session_.reset_graph();
      report();
    });
    add("parts", 0, 0, "parts", [this](const Words&) {
      for(const std::string& line : session_.describe_parts()) std::cout << "  " << line << "\n";
    });
  }

  void add_view_commands()
  {
    add("select", 1, 1, "select PART", [this](const Words& w) { window_.viewer().select_part(integer(w[1])); });
    add("view", 2, 2, "view AZIMUTH ELEVATION",
        [this](const Words& w) { window_.viewer().set_view(number(w[1]), number(w[2])); });
    add("size", 2, 2, "size WIDTH HEIGHT", [this](const Words& w) {
      const int width = integer(w[1]), height = integer(w[2]); // a bad width is named first
      set_viewer_size(width, height);
    });
    add("window-size", 2, 2, "window-size WIDTH HEIGHT", [this](const Words& w) {
      const int width = integer(w[1]), height = integer(w[2]);
      set_window_size(width, height);
    });
    add("seams", 1, 1, overlay_usage, [this](const Words& w) { window_.viewer().show_seams = w[1] == "on"; });
    add("sites", 1, 1, overlay_usage, [this](const Words& w) { window_.viewer().show_docking_sites = w[1] == "on"; });
    add("wait", 0, 0, "wait", [this](const Words&) { report(); });
    add("echo", 0, any_number, "echo TEXT", [](const Words& w) {
      for(std::size_t i = 1; i < w.size(); ++i) std::cout << (i > 1 ? " " : "  ") << w[i];
      std::cout << "\n";
    });
  }

  void add_output_commands()
  {
    add("screenshot", 1, 1, "screenshot FILE.png", [this](const Words& w) { screenshot(w[1]); });
    add("screenshot-window", 1, 1, "screenshot-window FILE.png", [this](const Words& w) {
      settle();
      if(!window_.grab().save(QString::fromStdString(w[1])))
        throw Script_error("cannot write the screenshot '" + w[1] + "'");
      std::cout << "  wrote " << w[1] << "\n";
    });
    add("save-mesh", 1, 2, "save-mesh FILE [arap]", [this](const Words& w) {
      if(w.size() == 3 && w[2] != "arap") throw Script_error("expected 'save-mesh FILE [arap]'");
      settle();
      session_.save_mesh(w[1], w.size() == 3);
    });
    add("save-model", 1, 1, "save-model FILE", [this](const Words& w) { session_.save_model(w[1]); });
    add("save-handles", 1, 1, "save-handles FILE", [this](const Words& w) { session_.save_handles(w[1]); });
    add("check-image", 1, 1, "check-image FILE.png", [](const Words& w) {
      check_not_blank(read_image(w[1]), w[1]);
      std::cout << "  not blank\n";
    });
    add("compare-images", 2, 2, "compare-images A.png B.png", [](const Words& w) { compare_images(w[1], w[2]); });
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

  void report_model()
  {
    const Point_matrix& p = session_.rest().points;
    std::cout << "  " << session_.source_name().toStdString() << ": " << p.rows() << " vertices, "
              << session_.rest().number_of_faces() << " faces, " << session_.shown_graph().nodes.size() << " parts, "
              << session_.model().types.size() << " part types, " << session_.model().rules.size() << " rules\n";
    report();
  }

  // Drags handle 0 back and forth (0.2% of the diagonal per frame, turning
  // every 10 frames), each frame solved and on the screen before the next,
  // and prints the mean solver frame and the mean time from the drag to the
  // window's swap that showed it.
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
      if(!session_.wait_until_shown(batch_timeout_ms))
        throw Script_error("frame " + std::to_string(i) + " was not shown (is the window on a display?)");
      const Solve_frame& f = session_.last_frame();
      solver_ms += f.ms;
      shown_ms += f.shown_ms;
      paint_ms += f.paint_ms;
    }
    std::cout << "  " << frames << " frames of " << p.rows() << " vertices: solver " << solver_ms / frames
              << " ms, on the screen " << shown_ms / frames << " ms after the drag (display adds "
              << (shown_ms - solver_ms) / frames << " ms, of which the paint " << paint_ms / frames << " ms)\n";
  }

  // The interactive path: a synthetic mouse click on the viewer, Shift to
  // pick a handle, Alt to select a part.
  void click(const Words& w)
  {
    if(w[3] != "shift" && w[3] != "alt") throw Script_error("expected 'click X Y shift' or 'click X Y alt'");
    const std::size_t before = session_.handle_vertices().size();
    const std::size_t cuts_before = session_.cutting() ? session_.cutting()->cuts().size() : 0;
    const QPoint at(integer(w[1]), integer(w[2]));
    send_mouse(QEvent::MouseButtonPress, at, w[3] == "shift" ? Qt::ShiftModifier : Qt::AltModifier);
    send_mouse(QEvent::MouseButtonRelease, at, w[3] == "shift" ? Qt::ShiftModifier : Qt::AltModifier);
    if(session_.cutting())
    {
      // On a mesh being cut, Shift+click adds a cut and Alt+click removes one.
      if(session_.cutting()->cuts().size() == cuts_before)
        throw Script_error(w[3] == "shift" ? "no cut was made at the pixel" : "no cut was removed");
      report_cutting();
    }
    else if(w[3] == "shift")
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

  // Ctrl+drag of a handle in small mouse moves, each posted to the solver
  // thread as the window would; only the latest target counts.
  void mouse_drag(const Words& w)
  {
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

  void set_viewer_size(int width, int height)
  {
    if(width < 64 || height < 64 || width > 4096 || height > 4096)
      throw Script_error("the size must be between 64 and 4096 pixels");
    window_.viewer().setFixedSize(width, height);
    window_.adjustSize();
    QApplication::processEvents();
  }

  // The window as a user sees it (the viewer takes the room left).
  void set_window_size(int width, int height)
  {
    if(width < 320 || height < 240 || width > 4096 || height > 4096)
      throw Script_error("the window size must be between 320x240 and 4096x4096 pixels");
    window_.viewer().setMinimumSize(0, 0);
    window_.viewer().setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
    window_.resize(width, height);
    QApplication::processEvents();
    window_.viewer().frame_scene();
  }

  void screenshot(const std::string& path)
  {
    settle();
    const QImage image = window_.viewer().grabFramebuffer();
    if(image.isNull() || !image.save(QString::fromStdString(path)))
      throw Script_error("cannot write the screenshot '" + path + "'");
    const Image_stats s = image_stats(image.convertToFormat(QImage::Format_RGB32));
    std::cout << "  wrote " << path << " (" << image.width() << "x" << image.height() << ", " << s.distinct_colors
              << " colours, " << int(100. * s.foreground + 0.5) << "% foreground)\n";
  }

  static void compare_images(const std::string& first, const std::string& second)
  {
    const QImage a = read_image(first), b = read_image(second);
    check_not_blank(a, first);
    check_not_blank(b, second);
    const double differing = differing_share(a, b);
    if(differing < min_differing)
      throw Script_error("'" + first + "' and '" + second + "' are the same picture (" +
                         std::to_string(100. * differing) + "% of the pixels differ)");
    std::cout << "  " << 100. * differing << "% of the pixels differ\n";
  }

  Session& session_;
  Main_window& window_;
  std::string script_;
  std::map<std::string, Command> commands_;
};

} // namespace

int run_batch_script(Session& session, Main_window& window, const std::string& script)
{
  Batch_runner runner(session, window, script);
  return runner.run();
}

} // namespace mpm_demo
