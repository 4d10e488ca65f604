// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The part types proposed for a mesh the user cut, as a table the user
// edits before learning.
#ifndef MPM_DEMO_PART_TYPE_TABLE_H
#define MPM_DEMO_PART_TYPE_TABLE_H

class QWidget;

namespace mpm_demo {

class Session;

/// Shows the proposed part type of each segment of the mesh being cut (its
/// faces, seams, depth from the root and why it was split off) with the type
/// editable; on OK gives the edited types to the session. Returns whether
/// the user accepted.
bool edit_part_types(QWidget* parent, Session& session);

} // namespace mpm_demo

#endif
