// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The demo's solver thread: embeds the latest request (MPM, and CGAL's ARAP
// beside it) off the UI thread, so that the window stays responsive while
// the mouse moves faster than the solver.
#ifndef MPM_DEMO_SOLVER_THREAD_H
#define MPM_DEMO_SOLVER_THREAD_H

#include <CGAL/MPM/Solver/Embedding_solver.h>

#include <QMutex>
#include <QString>
#include <QThread>
#include <QWaitCondition>

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace mpm_demo {

using CGAL::MPM::Point_matrix;

/// Milliseconds from `start` to now.
inline double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// One job for the solver thread. Only the latest posted request is solved:
/// mouse moves that arrive while the solver is busy replace each other.
struct Solve_request
{
  std::uint64_t serial = 0;
  std::shared_ptr<const CGAL::MPM::Embedding_problem> problem; ///< a new pointer rebuilds the solver
  CGAL::MPM::Embedding_options options;
  std::vector<int> handle_vertices;
  Point_matrix handle_targets;
  bool arap = false;    ///< also deform with CGAL's ARAP on the same handles
  bool restart = false; ///< start from the rest positions (reset)
  /// Take the folds out of the result (`unfold_faces()`), as `mpm` does for
  /// what it writes; not for drags, whose frames it would slow down.
  bool unfold = false;
  /// When the request was made (the mouse move), for the display latency.
  std::chrono::steady_clock::time_point posted;
};

/// What the solver thread reports for one request.
struct Solve_frame
{
  std::uint64_t serial = 0;
  Point_matrix positions;      ///< MPM result
  Point_matrix arap_positions; ///< ARAP result; empty when off or impossible
  int iterations = 0;
  bool converged = false;
  double energy = 0.;
  /// MPM's frame in the solver thread: new handle targets, `solve()` and the
  /// positions, as `mpm_bench`'s frame measures it.
  double ms = 0.;
  int arap_iterations = 0;
  double arap_ms = 0.;
  QString error;               ///< the MPM solve failed (positions are the previous ones)
  QString arap_error;          ///< why there is no ARAP result
  bool final = true;           ///< the last frame of its request (ARAP may send several)
  std::chrono::steady_clock::time_point posted; ///< when its request was made
  /// From the request to the end of the paint that showed the frame (the
  /// viewer sets it, `Session::frame_shown()`); negative until shown.
  double shown_ms = -1.;
  /// The paint that showed it: building the arrays, drawing, the GL's finish.
  double paint_ms = 0.;
};

/// Runs `Embedding_solver::solve()` (reduced global step, warm started) and
/// `Arap_deformation::deform()` off the UI thread.
class Solver_thread : public QThread
{
  Q_OBJECT
public:
  explicit Solver_thread(QObject* parent = nullptr);
  ~Solver_thread() override;
  /// Replaces the pending request (latest target wins) and wakes the thread.
  void post(Solve_request request);
  /// Asks the thread to finish and waits for it.
  void finish();

Q_SIGNALS:
  void frame_ready(const mpm_demo::Solve_frame& frame);

protected:
  void run() override;

private:
  QMutex mutex_;
  QWaitCondition wake_;
  Solve_request pending_;
  bool has_pending_ = false;
  bool stop_ = false;
};

} // namespace mpm_demo

#endif
