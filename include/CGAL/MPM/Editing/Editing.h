// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_EDITING_H
#define CGAL_MPM_EDITING_H

#include <CGAL/MPM/Solver/Embedding_problem.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <Eigen/Core>

#include <map>
#include <string>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Free-form deformation of training example `example`: every cluster (part
/// instance and pair geometry) keeps its learned modes and deviations, but
/// its target shape at zero coordinates is the instance's own rest shape
/// ("exchange the means"), so the input is the energy's minimum and handles
/// pull within the learned space. Throws `Input_error` for an example index
/// out of range.
Embedding_problem make_deformation_problem(const Morphable_part_model& model, int example = 0);

/// \ingroup PkgMPMRef
/// Makes `mesh` (a new pose of training example `example`: the same
/// triangles, other positions) the example's rest state: each instance's and
/// each pair geometry's coordinates and placement are refitted to it, so that
/// the editing problems start from that pose. Throws `Input_error` naming
/// `mesh_name` when the vertex count or a triangle differs from the
/// example's, or a coordinate is not finite; `model` is unchanged then.
void set_example_pose(Morphable_part_model& model, int example, const Indexed_mesh& mesh,
                      const std::string& mesh_name);

/// \ingroup PkgMPMRef
/// Options of partial symmetrization.
struct Symmetrization_options
{
  /// Isotropic standard deviation of every mode, relative to the type's
  /// largest learned one: small values pull all instances to the same shape.
  double relative_sigma = 0.01;
  /// Per part type name, the point of its subspace all instances move to
  /// (its coordinates); types not listed use their mean.
  std::map<std::string, Eigen::VectorXd> type_coordinates;
};

/// \ingroup PkgMPMRef
/// Partial symmetrization of example `example`: every instance of a type
/// (and every pair geometry of a rule) is attracted to the same shape, the
/// type's mean or a user-chosen point of its subspace, with a small
/// isotropic variance. The global structure (placement of parts) is kept.
Embedding_problem make_symmetrization_problem(const Morphable_part_model& model, int example = 0,
                                              const Symmetrization_options& options = Symmetrization_options());

/// \ingroup PkgMPMRef
/// Caricature (factor > 1) or anti-shape (factor < 0) of example `example`:
/// each instance's coordinates are scaled away from its type's mean by
/// `factor` (within the subspace); the part of its shape outside the
/// subspace is kept. Where that would turn a face of the part inside out
/// (a bent segment whose bend is doubled), the deviation is scaled as local
/// deformations instead (rotation angles and stretches of every vertex's
/// neighbourhood, integrated back), so that the segment bends further
/// instead of folding. Factor 1 is the deformation problem itself.
Embedding_problem make_caricature_problem(const Morphable_part_model& model, double factor, int example = 0);

/// \ingroup PkgMPMRef
/// An edit's result (`positions`, n x 3, over the triangles of `rest`, the
/// mesh before the edit) with the folds it made taken out: faces whose
/// normal points against the rest's once the rotation of their
/// neighbourhood is taken out (so a bent joint is no fold) are reshaped,
/// with a ring or two around them, as rigidly as possible (CGAL's ARAP)
/// between the result's positions around them. The solver's energy does not
/// forbid such folds: a drag that pushes a segment against its neighbour
/// can leave a few rings inside the seam turned over. `held` vertices (the
/// handles) do not move; nothing moves when there is no fold. The
/// editing commands of `mpm` apply it unless given `--keep-folds`.
Point_matrix unfold_faces(const Indexed_mesh& rest, const Point_matrix& positions, const std::vector<int>& held = {});

/// \ingroup PkgMPMRef
/// Options of an edit: `deform()`, `symmetrize()` and `caricature()`.
struct Edit_options
{
  int example = 0;          ///< training example to edit
  Embedding_options solver; ///< options of the embedding solver
  /// Take the folds the solver made out of the result (`unfold_faces()`);
  /// false writes the solver's positions as they are.
  bool unfold = true;
  /// Names the handles (their file) in error messages.
  std::string handles_source = "handles";
};

/// \ingroup PkgMPMRef
/// What an edit did. The edited shape itself is written into the user's
/// mesh, through its vertex point map, by `deform()`, `symmetrize()` and
/// `caricature()`.
struct Edit_result
{
  Solve_report report; ///< what the solver did
  /// Faces the solver turned inside out within their part, and as many
  /// after the folds were taken out (`inverted_faces()`).
  int inverted_faces_solved = 0;
  int inverted_faces_written = 0; ///< see `inverted_faces_solved`
  double setup_ms = 0.;  ///< solver construction, handles and factorization
  double solve_ms = 0.;  ///< solver iterations
  double unfold_ms = 0.; ///< `unfold_faces()`
};

} // namespace MPM
} // namespace CGAL

#endif
