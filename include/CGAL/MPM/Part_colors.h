// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_PART_COLORS_H
#define CGAL_MPM_PART_COLORS_H

#include <array>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// An RGB colour, 0..255 per channel.
using Rgb_color = std::array<unsigned char, 3>;

/// \ingroup PkgMPMRef
/// The colour of part type `type` in pictures and coloured PLY files: the
/// Tableau 10 palette (distinct hues that stay tellable apart under
/// shading), repeating after ten types; dark grey for a negative type (a
/// face of no known part). One palette for the tool and the demo, so that a
/// screenshot and a saved mesh agree.
inline Rgb_color part_type_color(int type)
{
  constexpr std::array<Rgb_color, 10> palette = {{
    {{78, 121, 167}}, {{242, 142, 43}}, {{225, 87, 89}},  {{118, 183, 178}}, {{89, 161, 79}},
    {{237, 201, 72}}, {{176, 122, 161}}, {{255, 157, 167}}, {{156, 117, 95}}, {{186, 176, 172}},
  }};
  if(type < 0) return {{64, 64, 64}};
  return palette[static_cast<unsigned>(type) % palette.size()];
}

} // namespace MPM
} // namespace CGAL

#endif
