// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_ARAP_DEFORMATION_H
#define CGAL_MPM_ARAP_DEFORMATION_H

#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Indexed_mesh.h>

#include <functional>
#include <memory>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// The as-rigid-as-possible energies of `CGAL::Surface_mesh_deformation`.
enum class Arap_variant
{
  original,                ///< `CGAL::ORIGINAL_ARAP`: one rotation per vertex, fitted on its spokes
  spokes_and_rims,         ///< `CGAL::SPOKES_AND_RIMS`: rotations fitted on spokes and rims
  smooth_rotation_enhanced ///< `CGAL::SRE_ARAP`: original ARAP plus smoothness of neighbouring rotations
};

/// \ingroup PkgMPMRef
/// As-rigid-as-possible deformation of a whole mesh by handles: the baseline
/// MPM is measured against. It runs `CGAL::Surface_mesh_deformation` on a
/// `Surface_mesh` copy of the input, with every vertex that lies in a
/// triangle as region of interest and the handles as control vertices;
/// vertices in no triangle stay where they are unless they are handles.
///
/// The factorization depends on the handle vertices only: `set_handles()`
/// with the same vertices and new targets (dragging) reuses it.
///
/// CGAL's types stay in the compiled library, so including this header does
/// not compile the deformation templates.
class Arap_deformation
{
public:
  /// Copies `mesh`. Throws `Input_error` naming the face when a triangle
  /// cannot be added to a `Surface_mesh` (non-manifold edge or vertex,
  /// inconsistent orientation, repeated corner).
  explicit Arap_deformation(const Indexed_mesh& mesh, Arap_variant variant = Arap_variant::original);
  ~Arap_deformation();
  /// Movable, not copyable.
  Arap_deformation(Arap_deformation&&) noexcept;
  /// Movable, not copyable.
  Arap_deformation& operator=(Arap_deformation&&) noexcept;

  /// Sets the handles. Throws `Input_error` when they are invalid for the
  /// mesh (see `validate_handles()`) or a connected component of the mesh
  /// has no handle: ARAP cannot place a free piece, and its matrix would
  /// be singular.
  void set_handles(const Handle_set& handles);

  /// Assembles and factors the system if the handle vertices changed since
  /// the last factorization (`deform()` calls it as needed; call it to time
  /// or to fail early). Throws `Computation_error` when the factorization
  /// fails, and `Input_error` when no handles are set.
  void preprocess();

  /// Runs local/global iterations from the current positions until
  /// `max_iterations` are done or an iteration moves no vertex by more than
  /// `tolerance` times the bounding-box diagonal (`tolerance <= 0`: run all).
  /// CGAL's own energy-based stopping test is not used because CGAL does
  /// not report how many iterations it ran. Returns the number of
  /// iterations run. Throws `Computation_error` when positions become
  /// non-finite (degenerate triangles).
  /// `after_iteration`, when given, is called with each iteration's number
  /// (from 1): progress, or a cancellation check that throws.
  int deform(int max_iterations, double tolerance, const std::function<void(int iteration)>& after_iteration = {});

  /// Exactly one local/global iteration (solve with the current rotations,
  /// then fit the rotations), for timing.
  void deform_one_iteration();

  /// Current positions, n x 3, in the input's vertex order.
  Point_matrix positions() const;

  /// Back to the input positions and identity rotations; handles are kept.
  void reset();

private:
  class Implementation;
  std::unique_ptr<Implementation> implementation_;
};

} // namespace MPM
} // namespace CGAL

#endif
