// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_DEFORMATION_METHOD_H
#define CGAL_MPM_DEFORMATION_METHOD_H

#include <CGAL/MPM/Editing/Arap_deformation.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// One deformation method behind the handle API, so MPM and its baselines
/// run on the same inputs (`mpm compare`, the quality benchmarks).
/// `deform()` always starts from the rest positions, so its result depends
/// on the handles only, not on earlier calls.
class Deformation_method
{
public:
  virtual ~Deformation_method() = default;
  /// Short name (`mpm`, `arap`, `arap-sre`, `laplacian`, `tps`, `pca`).
  virtual std::string name() const = 0;
  /// Sets the handles; throws `Input_error` for invalid ones (out of range,
  /// repeated, non-finite, none).
  virtual void set_handles(const Handle_set& handles) = 0;
  /// The deformed positions, n x 3 in the mesh's vertex order.
  virtual Point_matrix deform() = 0;
  /// Iterations of the last `deform()`, or -1 for a direct method.
  virtual int iterations() const { return -1; }
};

/// \ingroup PkgMPMRef
/// Settings of the methods made by `make_deformation_method()`.
struct Deformation_method_options
{
  /// MPM solver options (its `handle_weight` is also Laplacian editing's).
  Embedding_options mpm;
  /// ARAP: iteration cap and tolerance of `Arap_deformation::deform()`.
  int arap_max_iterations = 1000;
  double arap_tolerance = 1e-6; ///< ARAP: largest vertex move, relative to the bounding-box diagonal, that stops
  /// Called by the iterative methods (MPM, ARAP) after each iteration with
  /// its number (from 1): progress for a long run. Empty: not called.
  std::function<void(int iteration)> iteration_callback;
  /// Checked by the iterative methods before each iteration: raised,
  /// `deform()` throws `Operation_cancelled`. It also stands for
  /// `mpm.cancel` when that is null.
  Cancellation_flag cancel = nullptr;
};

/// \ingroup PkgMPMRef
/// The method names `make_deformation_method()` knows, in presentation order:
/// `mpm`, `arap`, `arap-sre`, `laplacian`, `tps`, `pca`.
std::vector<std::string> deformation_method_names();

/// \ingroup PkgMPMRef
/// Makes method `name` for training example `example` of `model`:
/// - `mpm`: `Embedding_solver` on `make_deformation_problem()`, solved to convergence;
/// - `arap`, `arap-sre`: `Arap_deformation` (original, SRE). CGAL's ARAP
///   cannot place a connected component without handles; the adapter pins
///   one vertex of each such component (nearest its centroid) at its rest
///   position, so the component stays at rest as MPM's anchor keeps it;
/// - `laplacian`: `Laplacian_editing` with the MPM handle weight;
/// - `tps`: `Thin_plate_spline_deformation`;
/// - `pca`: `Shape_space_fit`.
/// Throws `Input_error` for an unknown name (listing the valid ones) or a
/// missing example.
std::unique_ptr<Deformation_method> make_deformation_method(
  const std::string& name, const Morphable_part_model& model, int example = 0,
  const Deformation_method_options& options = Deformation_method_options());

/// \ingroup PkgMPMRef
/// Root mean square of the handle residuals `|positions(v_h) - y_h|`.
double handle_rms_residual(const Point_matrix& positions, const Handle_set& handles);

} // namespace MPM
} // namespace CGAL

#endif
