// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Synthetic_builders.h>

#include <cmath>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// m lattice cells per leg hole side; `density` scales the rings along the legs.
Limbed_model_spec spider_spec(int m, double density)
{
  const double degree = std::acos(-1.) / 180.;
  Limbed_model_spec spec = limbed_model_spec("body", m, density);
  const int border = spec.border(), gap = spec.gap();
  const int nz = 4 * m + 3 * gap + 2 * border, ny = m + 2 * border;
  const int nx = static_cast<int>(std::lround(0.7 * nz));
  spec.cells = Eigen::Vector3i(nx, ny, nz);
  // Four legs on each side (+x and -x faces); each leg bends in a vertical
  // plane: bending axis -z on the +x side, +z on the -x side, so a positive
  // bend turns the leg down on both sides.
  for(int side = 0; side < 2; ++side)
    for(int k = 0; k < 4; ++k)
    {
      Limb_hole hole;
      hole.normal_axis = 0;
      hole.normal_sign = side == 0 ? 1 : -1;
      hole.bend_axis = 2;
      hole.bend_sign = side == 0 ? -1 : 1;
      hole.center = Eigen::Vector3d(side == 0 ? nx : 0, 0.5 * ny, border + 0.5 * m + k * (m + gap));
      spec.holes.push_back(hole);
    }
  // Lengths in leg radii; the coxa lifts the leg, the knee drops it.
  spec.chain = {{"coxa", 1.5, 0.2, 0.05, 0.05, -35. * degree, 12. * degree},
                {"femur", 6.0, 0.8, 0.05, 0.05, 65. * degree, 12. * degree},
                {"tibia", 5.5, 0.7, 0.05, 0.05, 25. * degree, 12. * degree},
                {"tarsus", 4.0, 0.6, 0.04, 0.04, 0., 0.}};
  return spec;
}

} // namespace

// A body (single instance) and eight legs of four segments each (coxa,
// femur, tibia, tarsus; tarsus capped), one watertight mesh: the legs dock
// to the body and to each other by boundary docking (see make_limbed_model()).
Synthetic_model make_spider(const Synthetic_options& options)
{
  const int target = options.vertices > 0 ? options.vertices : 66453;
  const Limbed_model_spec best = limbed_spec_for_vertex_count(target, spider_spec);
  return make_limbed_model(best, Synthetic_family::spider, options);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
