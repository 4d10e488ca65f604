// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Main_window.h"
#include "Part_type_table.h"

#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QVBoxLayout>

#include <cmath>

namespace mpm_demo {

namespace {

QPushButton* button(const QString& text, QWidget* parent, const std::function<void()>& action)
{
  QPushButton* b = new QPushButton(text, parent);
  QObject::connect(b, &QPushButton::clicked, parent, action);
  return b;
}

} // namespace

Main_window::Main_window(Session& session) : session_(session)
{
  setWindowTitle("CGAL-MPM demo: morphable part models");
  viewer_ = new Viewer(session_, this);
  QWidget* panel = new QWidget(this);
  QVBoxLayout* column = new QVBoxLayout(panel);

  // Model
  QGroupBox* model_box = new QGroupBox("Model", panel);
  QVBoxLayout* model_layout = new QVBoxLayout(model_box);
  source_label_ = new QLabel(model_box);
  source_label_->setWordWrap(true);
  model_layout->addWidget(source_label_);
  QHBoxLayout* synth_row = new QHBoxLayout;
  family_ = new QComboBox(model_box);
  for(CGAL::MPM::Synthetic_family f : CGAL::MPM::all_synthetic_families())
    family_->addItem(QString::fromStdString(CGAL::MPM::family_name(f)));
  synth_row->addWidget(family_);
  synth_row->addWidget(button("Synthesize", model_box, [this] {
    guarded([this] { session_.load_synthetic(family_->currentText().toStdString(), default_synthetic_vertices, 1); });
  }));
  model_layout->addLayout(synth_row);
  model_layout->addWidget(button("Open mesh + labels + annotation...", model_box, [this] { open_mesh(); }));
  model_layout->addWidget(button("Open model (.mpm)...", model_box, [this] { open_model(); }));
  column->addWidget(model_box);

  // A mesh nobody has segmented: cuts, part types, learning.
  QGroupBox* cut_box = new QGroupBox("Cut a mesh into parts", panel);
  QVBoxLayout* cut_layout = new QVBoxLayout(cut_box);
  cut_layout->addWidget(button("Open a mesh to cut...", cut_box, [this] { open_raw_mesh(); }));
  cut_layout->addWidget(new QLabel("Shift+click next to a joint: cut there<br>Alt+click a cut: remove it", cut_box));
  QHBoxLayout* propose_row = new QHBoxLayout;
  QDoubleSpinBox* sensitivity = new QDoubleSpinBox(cut_box);
  sensitivity->setRange(0., 1.);
  sensitivity->setSingleStep(0.1);
  sensitivity->setValue(0.5);
  sensitivity->setToolTip("sensitivity: 0 cuts limbs off the body only, higher proposes more joints along them");
  propose_row->addWidget(button("Propose joints", cut_box, [this, sensitivity] {
    guarded([this, sensitivity] {
      const int limbs = session_.propose_cuts(sensitivity->value());
      statusBar()->showMessage(QString("%1 cuts proposed on %2 limbs; Shift+click adds one, Alt+click removes one")
                                 .arg(session_.cutting()->cuts().size())
                                 .arg(limbs));
    });
  }));
  propose_row->addWidget(sensitivity);
  cut_layout->addLayout(propose_row);
  QHBoxLayout* learn_row = new QHBoxLayout;
  learn_row->addWidget(button("Part types...", cut_box, [this] { guarded([this] { edit_part_types(this, session_); }); }));
  learn_row->addWidget(button("Learn", cut_box, [this] { guarded([this] { session_.learn_from_cuts(); }); }));
  cut_layout->addLayout(learn_row);
  column->addWidget(cut_box);

  // Handles
  QGroupBox* handle_box = new QGroupBox("Handles", panel);
  QVBoxLayout* handle_layout = new QVBoxLayout(handle_box);
  QLabel* hint = new QLabel("Shift+click: add/remove a handle<br>Ctrl+drag a handle: move it<br>"
                            "Ctrl+Shift+drag: join it to the last handle's group<br>Alt+click: select a part",
                            handle_box);
  handle_layout->addWidget(hint);
  QHBoxLayout* handle_row = new QHBoxLayout;
  handle_row->addWidget(button("1 per part", handle_box, [this] { guarded([this] { session_.set_handles_per_part(1); }); }));
  handle_row->addWidget(button("2 per part", handle_box, [this] { guarded([this] { session_.set_handles_per_part(2); }); }));
  handle_row->addWidget(button("Clear", handle_box, [this] { guarded([this] { session_.clear_handles(); }); }));
  handle_layout->addLayout(handle_row);
  handle_layout->addWidget(button("Reset to the input", handle_box, [this] { guarded([this] { session_.reset(); }); }));
  column->addWidget(handle_box);

  // Edits
  QGroupBox* edit_box = new QGroupBox("Edit", panel);
  QFormLayout* form = new QFormLayout(edit_box);
  mode_ = new QComboBox(edit_box);
  mode_->addItems({"deform", "symmetrize", "caricature"});
  connect(mode_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int i) {
    if(!syncing_) guarded([this, i] { session_.set_mode(Edit_mode(i)); });
  });
  form->addRow("Mode", mode_);
  // Caricature factor -1..3 by 0.1; relative symmetrization sigma 0.001..1
  // on a log scale; coupling weight 0..10.
  caricature_ = add_slider(
    form, "Caricature factor", -10, 30, [](int v) { return v / 10.; },
    [](double f) { return int(std::lround(f * 10.)); }, 'f', 1,
    [this](double f) { session_.set_caricature_factor(f); });
  symmetry_ = add_slider(
    form, "Symmetrize (relative sigma)", 0, 30, [](int v) { return std::pow(10., -3. + v / 10.); },
    [](double s) { return int(std::lround((std::log10(s) + 3.) * 10.)); }, 'g', 2,
    [this](double s) { session_.set_symmetry_sigma(s); });
  coupling_ = add_slider(
    form, "Coupled coordinates", 0, 40, [](int v) { return v / 4.; },
    [](double w) { return int(std::lround(w * 4.)); }, 'f', 2, [this](double w) { session_.set_coupling(w); });
  arap_ = new QCheckBox("ARAP (CGAL) side by side", edit_box);
  connect(arap_, &QCheckBox::toggled, this, [this](bool on) {
    if(syncing_) return;
    guarded([this, on] { session_.set_arap(on); });
    viewer_->frame_scene();
  });
  form->addRow(arap_);
  column->addWidget(edit_box);

  // Part graph
  QGroupBox* graph_box = new QGroupBox("Part graph (from the grammar)", panel);
  QVBoxLayout* graph_layout = new QVBoxLayout(graph_box);
  part_label_ = new QLabel("Alt+click a part to select it", graph_box);
  part_label_->setWordWrap(true);
  graph_layout->addWidget(part_label_);
  graph_layout->addWidget(button("Insert a segment above it", graph_box, [this] {
    guarded([this] { session_.insert_segment(viewer_->selected_part()); });
  }));
  graph_layout->addWidget(button("Remove this segment", graph_box, [this] {
    guarded([this] { session_.remove_segment(viewer_->selected_part()); });
  }));
  graph_layout->addWidget(button("Remove it and its branch", graph_box, [this] {
    guarded([this] { session_.remove_branch(viewer_->selected_part()); });
  }));
  graph_layout->addWidget(button("Duplicate its branch (onto a free site)", graph_box, [this] {
    guarded([this] { session_.duplicate_branch(viewer_->selected_part()); });
  }));
  graph_layout->addWidget(button("Back to the training example", graph_box, [this] { guarded([this] { session_.reset_graph(); }); }));
  column->addWidget(graph_box);

  // Saving
  QGroupBox* save_box = new QGroupBox("Save", panel);
  QVBoxLayout* save_layout = new QVBoxLayout(save_box);
  save_layout->addWidget(button("Mesh (PLY with part colours)...", save_box, [this] {
    const QString f = choose_save_file("Save the mesh", "Meshes (*.ply *.off *.obj)", "ply");
    if(!f.isEmpty()) guarded([this, f] { session_.save_mesh(f.toStdString()); });
  }));
  save_layout->addWidget(button("ARAP mesh...", save_box, [this] {
    const QString f = choose_save_file("Save the ARAP mesh", "Meshes (*.ply *.off *.obj)", "ply");
    if(!f.isEmpty()) guarded([this, f] { session_.save_mesh(f.toStdString(), true); });
  }));
  save_layout->addWidget(button("Model (.mpm)...", save_box, [this] {
    const QString f = choose_save_file("Save the model", "Models (*.mpm)", "mpm");
    if(!f.isEmpty()) guarded([this, f] { session_.save_model(f.toStdString()); });
  }));
  save_layout->addWidget(button("Handles (.json)...", save_box, [this] {
    const QString f = choose_save_file("Save the handles", "Handles (*.json)", "json");
    if(!f.isEmpty()) guarded([this, f] { session_.save_handles(f.toStdString()); });
  }));
  save_layout->addWidget(button("Screenshot (.png)...", save_box, [this] { take_screenshot(); }));
  column->addWidget(save_box);
  column->addStretch(1);

  QScrollArea* scroll = new QScrollArea(this);
  scroll->setWidget(panel);
  scroll->setWidgetResizable(true);
  scroll->setMinimumWidth(panel->sizeHint().width() + 24);
  QSplitter* splitter = new QSplitter(this);
  splitter->addWidget(viewer_);
  splitter->addWidget(scroll);
  splitter->setStretchFactor(0, 1);
  setCentralWidget(splitter);

  QMenu* file = menuBar()->addMenu("&File");
  file->addAction("Open mesh...", this, [this] { open_mesh(); });
  file->addAction("Open a mesh to cut...", this, [this] { open_raw_mesh(); });
  file->addAction("Open model...", this, [this] { open_model(); });
  file->addAction("Screenshot...", this, [this] { take_screenshot(); });
  file->addSeparator();
  file->addAction("Quit", qApp, &QApplication::quit, QKeySequence::Quit);
  QMenu* help = menuBar()->addMenu("&Help");
  help->addAction("Controls", viewer_, &Viewer::help);

  solver_label_ = new QLabel(this);
  statusBar()->addPermanentWidget(solver_label_);
  connect(&session_, &Session::positions_changed, this, &Main_window::on_frame);
  // A change of the status bar is one more composition of the window (6 ms
  // under Mesa's software rasterizer, on the solver's cores): a drag's
  // frames show the latency of the frame before, and the last frame's is
  // shown once the drag pauses.
  status_refresh_.setSingleShot(true);
  status_refresh_.setInterval(250);
  connect(&status_refresh_, &QTimer::timeout, this, &Main_window::on_frame);
  connect(&session_, &Session::frame_displayed, &status_refresh_, qOverload<>(&QTimer::start));
  connect(&session_, &Session::scene_changed, this, [this] {
    sync_controls();
    on_part_selected(-1);
    if(session_.cutting())
      statusBar()->showMessage("Shift+click next to a joint: cut there | Alt+click: remove a cut | "
                               "Propose joints: cut it all | Learn: make the model");
    else if(session_.handle_vertices().empty())
      statusBar()->showMessage("Shift+click: add a handle | Ctrl+drag a handle: deform | "
                               "Alt+click: select a part | drag: rotate");
    on_frame();
  });
  connect(viewer_, &Viewer::message, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
  connect(viewer_, &Viewer::part_selected, this, &Main_window::on_part_selected);
  sync_controls();
}

void Main_window::Value_slider::show(double value) const
{
  slider->setValue(position_of(value));
  label->setText(QString::number(value, format, precision));
}

Main_window::Value_slider Main_window::add_slider(QFormLayout* form, const QString& name, int lo, int hi,
                                                  std::function<double(int)> value_of,
                                                  std::function<int(double)> position_of, char format,
                                                  int precision, std::function<void(double)> apply)
{
  Value_slider s;
  s.slider = new QSlider(Qt::Horizontal, form->parentWidget());
  s.slider->setRange(lo, hi);
  s.slider->setTracking(false); // one edit per release, not per pixel
  s.label = new QLabel(form->parentWidget());
  s.value_of = std::move(value_of);
  s.position_of = std::move(position_of);
  s.format = format;
  s.precision = precision;
  connect(s.slider, &QSlider::valueChanged, this, [this, s, apply](int v) {
    const double value = s.value_of(v);
    s.label->setText(QString::number(value, s.format, s.precision));
    if(!syncing_) guarded([&apply, value] { apply(value); });
  });
  form->addRow(name, s.slider);
  form->addRow("", s.label);
  return s;
}

void Main_window::guarded(const std::function<void()>& action)
{
  try
  {
    QApplication::setOverrideCursor(Qt::WaitCursor);
    action();
    QApplication::restoreOverrideCursor();
  }
  catch(const std::exception& e)
  {
    QApplication::restoreOverrideCursor();
    statusBar()->showMessage(QString("Error: ") + e.what(), 15000);
  }
  sync_controls();
}

void Main_window::sync_controls()
{
  syncing_ = true;
  if(const Raw_mesh_cutting* cutting = session_.cutting())
    source_label_->setText(QString("%1: %2 cuts (no model yet: learn)")
                             .arg(session_.source_name())
                             .arg(cutting->cuts().size()));
  else
    source_label_->setText(session_.has_model() ? session_.source_name() +
                                                    (session_.graph_edited() ? " (edited part graph)" : "")
                                                : "no model");
  const int family = family_->findText(QString::fromStdString(session_.synthetic_family()));
  if(family >= 0) family_->setCurrentIndex(family);
  mode_->setCurrentIndex(int(session_.mode()));
  caricature_.show(session_.caricature_factor());
  symmetry_.show(session_.symmetry_sigma());
  coupling_.show(session_.coupling());
  arap_->setChecked(session_.arap());
  syncing_ = false;
}

QString Main_window::solver_status() const
{
  const Solve_frame& f = session_.last_frame();
  if(!f.error.isEmpty()) return "solver: " + f.error;
  QString s = QString("MPM: %1 iterations%2, energy %3, solver %4 ms/frame")
                .arg(f.iterations)
                .arg(f.converged ? "" : " (cap)")
                .arg(f.energy, 0, 'g', 4)
                .arg(f.ms, 0, 'f', 1);
  if(session_.display_ms() >= 0.) s += QString(", on the screen %1 ms after the move").arg(session_.display_ms(), 0, 'f', 1);
  if(session_.arap())
    s += f.arap_error.isEmpty() ? QString(" | ARAP: %1 iterations, %2 ms").arg(f.arap_iterations).arg(f.arap_ms, 0, 'f', 1)
                                : " | ARAP: " + f.arap_error;
  return s;
}

void Main_window::on_frame()
{
  solver_label_->setText(session_.has_model() ? solver_status() : QString("no model: nothing to solve"));
}

void Main_window::on_part_selected(int node)
{
  if(!session_.has_model() || node < 0 || node >= int(session_.shown_graph().nodes.size()))
  {
    part_label_->setText("Alt+click a part to select it");
    return;
  }
  const CGAL::MPM::Part_graph& g = session_.shown_graph();
  part_label_->setText(QString("Part %1: %2")
                         .arg(node)
                         .arg(QString::fromStdString(session_.model().types[g.nodes[node].type].name)));
}

QString Main_window::choose_save_file(const QString& title, const QString& filter, const QString& suffix)
{
  QFileDialog dialog(this, title, QString(), filter);
  dialog.setAcceptMode(QFileDialog::AcceptSave);
  dialog.setDefaultSuffix(suffix);
  return dialog.exec() == QDialog::Accepted ? dialog.selectedFiles().value(0) : QString();
}

void Main_window::open_mesh()
{
  const QString mesh = QFileDialog::getOpenFileName(this, "Open a mesh", QString(), "Meshes (*.off *.obj *.ply *.stl)");
  if(mesh.isEmpty()) return;
  const QFileInfo info(mesh);
  const QString guess = info.path() + "/" + info.completeBaseName();
  QString labels = QFileDialog::getOpenFileName(this, "Its part labels (.seg; cancel: one part per component)",
                                                guess + ".seg", "Labels (*.seg)");
  if(labels.isEmpty()) labels = "components";
  const QString annotation = QFileDialog::getOpenFileName(
    this, "Its annotation (.json; cancel: types proposed from the segmentation, or parts grouped by connectivity)", guess + ".json", "Annotations (*.json)");
  guarded([&] { session_.load_labeled_mesh(mesh.toStdString(), labels.toStdString(), annotation.toStdString()); });
}

void Main_window::open_raw_mesh()
{
  const QString mesh = QFileDialog::getOpenFileName(this, "Open a closed mesh to cut into parts", QString(),
                                                    "Meshes (*.off *.obj *.ply *.stl)");
  if(!mesh.isEmpty()) guarded([&] { session_.open_raw_mesh(mesh.toStdString()); });
}

void Main_window::open_model()
{
  const QString path = QFileDialog::getOpenFileName(this, "Open a model", QString(), "Models (*.mpm);;All files (*)");
  if(!path.isEmpty()) guarded([&] { session_.load_model(path.toStdString()); });
}

void Main_window::take_screenshot()
{
  const QString f = choose_save_file("Save a screenshot", "Images (*.png)", "png");
  if(f.isEmpty()) return;
  if(!viewer_->grabFramebuffer().save(f)) statusBar()->showMessage("Could not write " + f, 8000);
}

} // namespace mpm_demo
