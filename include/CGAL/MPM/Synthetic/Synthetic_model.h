// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_SYNTHETIC_MODEL_H
#define CGAL_MPM_SYNTHETIC_MODEL_H

#include <CGAL/MPM/Indexed_mesh.h>
#include <CGAL/MPM/Model/Model_parameters.h>

#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// The built-in families of part-structured models with known variation.
enum class Synthetic_family
{
  hexa_grid, ///< hexagonal tiles that bend, boundary docking
  facade,    ///< a wall with windows as separate components, generalized docking
  hand,      ///< a palm and five fingers of three segments, boundary docking
  spider,    ///< a body and eight legs of several segments
  spine      ///< separate vertebrae, generalized docking
};

/// \ingroup PkgMPMRef
/// Options of a synthetic model.
struct Synthetic_options
{
  unsigned seed = 1;      ///< seeds the training model's latent parameters
  int vertices = 0;       ///< approximate vertex count; 0: the family's default (the paper's scale)
  bool held_out_pose = false; ///< draw a held-out pose (latents from `pose_seed`, not centred)
  unsigned pose_seed = 0; ///< seed of the held-out pose's latent parameters
};

/// \ingroup PkgMPMRef
/// Ground truth of one part type.
struct Synthetic_type
{
  std::string name;    ///< type name, as in the annotation
  int modes = 0;       ///< number of latent parameters that vary its shape
  bool linear = false; ///< instances are rigid placements of mean + linear combination of modes
};

/// \ingroup PkgMPMRef
/// Ground truth of one instance.
struct Synthetic_instance
{
  int label = -1;            ///< face label of the instance
  std::string type;          ///< its part type
  std::vector<int> vertices; ///< mesh vertex of each local vertex: the true correspondence
  std::vector<double> latent; ///< latent parameters of its shape
};

/// \ingroup PkgMPMRef
/// A docking the generator built between two instances (by label).
struct Synthetic_connection
{
  int first = -1;        ///< label of one part
  int second = -1;       ///< label of the other
  bool boundary = true;  ///< shared seam (true) or generalized docking (false)
};

/// \ingroup PkgMPMRef
/// A synthetic model with its ground truth. Within a type, every instance's
/// faces appear in the same local order with the same corner order, so the
/// first-appearance numbering of each part's vertices (the convention
/// `learn_morphable_part_model()` uses) is the true correspondence.
struct Synthetic_model
{
  Synthetic_family family = Synthetic_family::hand; ///< which family
  Synthetic_options options;          ///< how it was made
  Labeled_mesh mesh;                  ///< mesh and per-face labels
  Annotation annotation;              ///< part types per label and model parameters
  std::vector<Synthetic_type> types;  ///< ground truth per type
  std::vector<Synthetic_instance> instances;     ///< ground truth per instance
  std::vector<Synthetic_connection> connections; ///< the generator's dockings
  int expected_rules = 0; ///< distinct docking rules the grammar must hold

  /// Vertex positions of a held-out pose: the same structure and
  /// connectivity, new latent parameters drawn from `pose_seed`.
  Point_matrix draw_pose(unsigned pose_seed) const;
};

/// \ingroup PkgMPMRef
/// Builds a synthetic model. Deterministic for given options.
Synthetic_model make_synthetic_model(Synthetic_family family,
                                     const Synthetic_options& options = Synthetic_options());

/// \ingroup PkgMPMRef
/// The family's command-line name (`hexa-grid`, `facade`, `hand`, `spider`, `spine`).
std::string family_name(Synthetic_family family);

/// \ingroup PkgMPMRef
/// Parses a family name; throws `Input_error` listing the valid names.
Synthetic_family parse_family(const std::string& name);

/// \ingroup PkgMPMRef
/// All families, in declaration order.
std::vector<Synthetic_family> all_synthetic_families();

} // namespace MPM
} // namespace CGAL

#endif
