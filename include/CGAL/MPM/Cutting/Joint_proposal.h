// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_JOINT_PROPOSAL_H
#define CGAL_MPM_JOINT_PROPOSAL_H

#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Indexed_mesh.h>

#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Options of `cut_at_proposed_joints()`.
struct Joint_proposal_options
{
  /// Between 0 and 1: how readily a narrowing, a crease or a bend along a
  /// limb is taken for a joint. Higher proposes more joints; 0 proposes only
  /// where the limbs leave the body.
  double sensitivity = 0.5;
  /// A branch of the curve skeleton shorter than this many limb radii is a
  /// bump, not a limb. Must be finite and > 0.
  double minimum_limb_length = 2.;
  /// Shortest segment along a limb, in limb radii: joints closer than this
  /// to each other or to the limb's tip are not proposed. Must be finite and > 0.
  double minimum_segment_length = 1.5;
  /// How each proposed joint is cut, as for one click per joint
  /// (`skip_unfound` is always on: a proposal that cannot be cut is dropped).
  Joint_cutting_options cutting;
};

/// \ingroup PkgMPMRef
/// One joint proposed by `cut_at_proposed_joints()`; `Vertex` as for
/// `Basic_skipped_click`.
template <class Vertex>
struct Basic_proposed_joint
{
  Vertex vertex{};       ///< the vertex clicked for it
  int limb = -1;         ///< the limb it is on (0, 1, ...), or -1 for the body's own axis
  bool at_base = false;  ///< where the limb leaves the body
  double strength = 0.;  ///< how clearly it shows, narrowing and bend together (1: just at the sensitivity's threshold; 0 at a base)
  bool by_analogy = false; ///< placed like the joints found on similar limbs, where nothing showed on this one
};

/// \ingroup PkgMPMRef
/// A joint proposed on the indexed mesh.
using Proposed_joint = Basic_proposed_joint<int>;

/// \ingroup PkgMPMRef
/// The proposed joints and the cuts at them: `Cutting` is a
/// `Joint_cutting_result` on the indexed mesh (`Joint_proposal`), the
/// `Joint_cuts` of the vertex descriptors on the user's face graph.
template <class Vertex, class Cutting>
struct Basic_joint_proposal
{
  std::vector<Basic_proposed_joint<Vertex>> joints; ///< proposed joints, limb by limb from the body outwards
  int limbs = 0;                                    ///< limbs found
  Cutting cutting; ///< `cut_at_vertices()` at the proposed joints' vertices
};

/// \ingroup PkgMPMRef
/// The proposed joints and the indexed mesh cut at them.
using Joint_proposal = Basic_joint_proposal<int, Joint_cutting_result>;

/// \ingroup PkgMPMRef
/// Joints proposed automatically: cuts a closed, connected mesh into a body
/// and limb segments with no click. The branches of CGAL's mean curvature
/// flow curve skeleton that are long against their radius are limbs (shorter
/// ones are pruned as bumps); along each limb, sections across its axis are
/// ranked by their crease-weighted length (lower where the limb narrows and
/// where the surface is concave), the limb's base is the best section where
/// sections first close around the limb alone, and further joints are where
/// a section stands out from its surroundings, or the limb's axis bends, by
/// more than the sensitivity allows, at least
/// `minimum_segment_length` limb radii apart. Limbs that look alike (radius
/// and length within a factor 1.5) are cut alike: a joint found at about the
/// same fraction of the length on at least two of them and a third of them
/// is added to the others (`Proposed_joint::by_analogy`). The body's own
/// axis is cut only at a pronounced waist. Each proposal is then cut as one
/// click (`cut_at_vertices()`).
///
/// Throws `Input_error` naming the mesh for options out of range, a mesh with
/// holes or several components, or one whose skeleton cannot be computed.
Joint_proposal cut_at_proposed_joints(const Indexed_mesh& mesh,
                                      const Joint_proposal_options& options = Joint_proposal_options(),
                                      const std::string& mesh_source = "mesh");

} // namespace MPM
} // namespace CGAL

#endif
