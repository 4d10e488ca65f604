// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The window: the viewer, a panel of controls for loading, handles, edits,
// part-graph editing and saving, and a status bar with the solver's
// iterations, energy and time per frame.
#ifndef MPM_DEMO_MAIN_WINDOW_H
#define MPM_DEMO_MAIN_WINDOW_H

#include "Session.h"
#include "Viewer.h"

#include <QMainWindow>
#include <QTimer>

#include <functional>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QSlider;

namespace mpm_demo {

class Main_window : public QMainWindow
{
  Q_OBJECT
public:
  explicit Main_window(Session& session);
  Viewer& viewer() { return *viewer_; }
  /// The status bar's solver line for the last frame.
  QString solver_status() const;
  /// Brings the controls in line with the session (after a batch command).
  void sync_controls();

private:
  /// Runs `action`, showing an error in the status bar instead of throwing.
  void guarded(const std::function<void()>& action);
  QString choose_save_file(const QString& title, const QString& filter, const QString& suffix);
  void open_mesh();
  void open_raw_mesh();
  void open_model();
  void on_frame();
  void on_part_selected(int node);
  void take_screenshot();

  Session& session_;
  Viewer* viewer_ = nullptr;
  QLabel* source_label_ = nullptr;
  QComboBox* family_ = nullptr;
  QComboBox* mode_ = nullptr;
  /// A slider over a real value, with the value printed under it.
  struct Value_slider
  {
    QSlider* slider = nullptr;
    QLabel* label = nullptr;
    std::function<double(int)> value_of;  ///< slider position -> value
    std::function<int(double)> position_of; ///< value -> slider position
    char format = 'f';
    int precision = 2;
    void show(double value) const;
  };
  Value_slider add_slider(QFormLayout* form, const QString& name, int lo, int hi,
                          std::function<double(int)> value_of, std::function<int(double)> position_of, char format,
                          int precision, std::function<void(double)> apply);
  Value_slider caricature_, symmetry_, coupling_;
  QCheckBox* arap_ = nullptr;
  QLabel* part_label_ = nullptr;
  QLabel* solver_label_ = nullptr;
  QTimer status_refresh_; // shows the last frame's latency once a drag pauses
  bool syncing_ = false;
};

} // namespace mpm_demo

#endif
