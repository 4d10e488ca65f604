// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Synthetic models learned once per test run and shared by the suites that
// edit them, with the small geometric helpers those suites compare with.
#ifndef CGAL_MPM_TEST_LEARNED_MODELS_H
#define CGAL_MPM_TEST_LEARNED_MODELS_H

#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include "Point_distances.h"

#include <map>
#include <utility>
#include <vector>

namespace mpm_test {

struct Learned
{
  CGAL::MPM::Synthetic_model truth;
  CGAL::MPM::Morphable_part_model model;
};

// The family at about `vertices` vertices and the model learned from it.
inline const Learned& learned(CGAL::MPM::Synthetic_family family, int vertices)
{
  static std::map<std::pair<CGAL::MPM::Synthetic_family, int>, Learned> cache;
  const auto key = std::make_pair(family, vertices);
  auto it = cache.find(key);
  if(it == cache.end())
  {
    CGAL::MPM::Synthetic_options o;
    o.vertices = vertices;
    Learned l;
    l.truth = CGAL::MPM::make_synthetic_model(family, o);
    l.model = CGAL::MPM::learn_morphable_part_model(l.truth.mesh, l.truth.annotation);
    it = cache.emplace(key, std::move(l)).first;
  }
  return it->second;
}

// The synthetic hand at 3,000 vertices, the size most tests use, made once;
// without a model, for the tests that need only its shape and parts.
inline const CGAL::MPM::Synthetic_model& small_hand()
{
  static const CGAL::MPM::Synthetic_model hand = [] {
    CGAL::MPM::Synthetic_options o;
    o.vertices = 3000;
    return CGAL::MPM::make_synthetic_model(CGAL::MPM::Synthetic_family::hand, o);
  }();
  return hand;
}

// The model learned from that hand.
inline const CGAL::MPM::Morphable_part_model& small_hand_model()
{
  return learned(CGAL::MPM::Synthetic_family::hand, 3000).model;
}

inline CGAL::MPM::Point_matrix rows(const CGAL::MPM::Point_matrix& p, const std::vector<int>& vertices)
{
  CGAL::MPM::Point_matrix r(vertices.size(), 3);
  for(std::size_t i = 0; i < vertices.size(); ++i) r.row(i) = p.row(vertices[i]);
  return r;
}

} // namespace mpm_test

#endif
