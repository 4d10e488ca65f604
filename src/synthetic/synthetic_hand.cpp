// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Synthetic_builders.h>

#include <cmath>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// m lattice cells per finger hole side; `density` scales the rings along the
// fingers, for a finer fit of the vertex count than m alone gives.
Limbed_model_spec hand_spec(int m, double density)
{
  const double degree = std::acos(-1.) / 180.;
  Limbed_model_spec spec = limbed_model_spec("palm", m, density);
  const int border = spec.border(), gap = spec.gap();
  const int nx = 4 * m + 3 * gap + 2 * border, nz = m + 2 * border;
  const int ny = static_cast<int>(std::lround(0.8 * nx));
  spec.cells = Eigen::Vector3i(nx, ny, nz);
  // Four fingers on the top face (+y) bending toward +z, the thumb on the
  // +x side, low, bending up (+y).
  for(int f = 0; f < 4; ++f)
  {
    Limb_hole hole;
    hole.normal_axis = 1;
    hole.bend_axis = 0;
    hole.center = Eigen::Vector3d(border + 0.5 * m + f * (m + gap), ny, 0.5 * nz);
    spec.holes.push_back(hole);
  }
  Limb_hole thumb;
  thumb.normal_axis = 0;
  thumb.bend_axis = 2;
  thumb.center = Eigen::Vector3d(nx, border + 0.5 * m + (ny - 2 * border - m) / 4, 0.5 * nz);
  spec.holes.push_back(thumb);
  // Lengths in finger radii; bends vary by +-12 degrees around moderate means.
  spec.chain = {{"proximal", 4.5, 0.6, 0.08, 0.06, 15. * degree, 12. * degree},
                {"middle", 2.8, 0.4, 0.06, 0.05, 12. * degree, 12. * degree},
                {"distal", 1.6, 0.3, 0.05, 0.04, 0., 0.}};
  return spec;
}

} // namespace

// A palm (single instance) and five fingers of three segments each
// (proximal, middle, distal; distal capped), one watertight mesh with
// boundary docking (see make_limbed_model()).
Synthetic_model make_hand(const Synthetic_options& options)
{
  const int target = options.vertices > 0 ? options.vertices : 23000;
  const Limbed_model_spec best = limbed_spec_for_vertex_count(target, hand_spec);
  return make_limbed_model(best, Synthetic_family::hand, options);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
