// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_LIMB_BENDING_H
#define CGAL_MPM_LIMB_BENDING_H

#include <CGAL/MPM/Model/Morphable_part_model.h>
#include <CGAL/MPM/Solver/Handle_set.h>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Handles that bend every limb of training example `example` about its
/// attachment to the root (the part with the most vertices): one handle
/// per tip (a part with one docking), at its vertex farthest from the
/// attachment (the centre of the seam between the root and the limb's
/// first segment), turned about that centre by the angle that moves it by
/// `relative_move` times the bounding-box diagonal, and the root held where
/// it rests away from its seams (its vertices farther along its edges from
/// every seam than the seams' mean radius), so that the limbs can turn at
/// their attachment. A limb reaches its handle by bending at
/// its joints, without stretching: the drag that tests whether a model's
/// joints bend and its segments keep their length
/// (`bench/quality_real_meshes`). Throws `Input_error` for a missing
/// example or a move that is not positive and finite.
Handle_set limb_bending_handles(const Morphable_part_model& model, int example = 0, double relative_move = 0.1);

} // namespace MPM
} // namespace CGAL

#endif
