// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one implementation of an edit, from the problem to the positions the
// editing functions write into the user's mesh (and `mpm` into its file).
#ifndef CGAL_MPM_INTERNAL_EDIT_SOLVING_H
#define CGAL_MPM_INTERNAL_EDIT_SOLVING_H

#include <CGAL/MPM/Editing/Editing.h>

namespace CGAL {
namespace MPM {
namespace internal {

// An edit solved: the example's triangles at the edited positions, and
// what the edit did.
struct Solved_edit
{
  Indexed_mesh mesh;
  Edit_result result;
};

// Solves `problem` (one of the editing problems of example
// `options.example`) with `handles` (vertices of the example's mesh and
// their targets) to convergence and takes out the folds. Throws
// `Input_error` for an example out of range, a handle vertex out of range
// or a handle target more than 100 bounding-box diagonals away (naming the
// handle), and `Computation_error` when the solver gives non-finite
// positions or moves a vertex that far.
Solved_edit solve_edit(const Morphable_part_model& model, const Embedding_problem& problem,
                       const Handle_set& handles = Handle_set(), const Edit_options& options = Edit_options());

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
