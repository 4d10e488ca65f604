// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_MESSAGE_TEXT_H
#define CGAL_MPM_INTERNAL_MESSAGE_TEXT_H

// How error messages name things, one way everywhere.

#include <CGAL/MPM/Model/Morphable_part_model.h>

#include <cstdio>
#include <string>

namespace CGAL {
namespace MPM {
namespace internal {

// A name in quotes.
inline std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// A fraction as a percentage, two significant digits (`2.9%`).
inline std::string percent(double fraction)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.2g%%", 100. * fraction);
  return text;
}

// A docking site: its part type's name and its index (`"palm" site 2`).
inline std::string site_text(const Morphable_part_model& model, const Site_ref& s)
{
  return quoted(model.types[s.type].name) + " site " + std::to_string(s.site);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
