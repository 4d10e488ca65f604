// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The synthetic hand's true seams as the cuts a user would click, for the
// suites that cut it.
#ifndef MPM_TEST_HAND_CUTS_H
#define MPM_TEST_HAND_CUTS_H

#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace mpm_test {

using namespace CGAL::MPM;

// The loop of mesh edges between the faces labelled `a` and those labelled
// `b`, as vertices in order around it.
inline std::vector<int> seam_loop(const Labeled_mesh& m, int a, int b)
{
  std::map<std::pair<int, int>, std::set<int>> labels_of_edge;
  for(std::size_t f = 0; f < m.mesh.triangles.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const int u = m.mesh.triangles[f][k], v = m.mesh.triangles[f][(k + 1) % 3];
      labels_of_edge[{std::min(u, v), std::max(u, v)}].insert(m.face_labels[f]);
    }
  std::map<int, std::vector<int>> next;
  for(const auto& [edge, labels] : labels_of_edge)
    if(labels == std::set<int>{a, b}) {
      next[edge.first].push_back(edge.second);
      next[edge.second].push_back(edge.first);
    }
  std::vector<int> loop;
  if(next.empty()) return loop;
  int previous = -1, v = next.begin()->first;
  do {
    loop.push_back(v);
    const int w = next[v][0] == previous ? next[v][1] : next[v][0];
    previous = v;
    v = w;
  } while(v != loop.front() && loop.size() <= next.size());
  return loop;
}

// The `nth` vertex all of whose faces carry `label`.
inline int inner_vertex(const Labeled_mesh& m, int label, int nth = 0)
{
  std::vector<int> state(std::size_t(m.mesh.number_of_vertices()), 0); // 1: only `label` so far, 2: other label seen
  for(std::size_t f = 0; f < m.mesh.triangles.size(); ++f)
    for(int v : m.mesh.triangles[f]) state[std::size_t(v)] = m.face_labels[f] == label && state[std::size_t(v)] != 2 ? 1 : 2;
  for(std::size_t v = 0; v < state.size(); ++v)
    if(state[v] == 1 && nth-- == 0) return int(v);
  return -1;
}

// Every k-th vertex of the loop: the sparse points a user would click.
inline std::vector<int> sparse(const std::vector<int>& loop, int points)
{
  std::vector<int> r;
  for(int i = 0; i < points; ++i) r.push_back(loop[std::size_t(i) * loop.size() / std::size_t(points)]);
  return r;
}

// The hand's true seams as cuts (four points each) and one seed per true part.
inline Cut_specification hand_cuts(const Synthetic_model& hand)
{
  Cut_specification spec;
  spec.source = "hand cuts";
  for(const Synthetic_connection& c : hand.connections) {
    Cut_line cut;
    cut.vertices = sparse(seam_loop(hand.mesh, c.first, c.second), 4);
    cut.name = std::to_string(c.first) + "-" + std::to_string(c.second);
    spec.cuts.push_back(cut);
  }
  for(const Synthetic_instance& i : hand.instances) spec.parts.push_back({i.label, inner_vertex(hand.mesh, i.label)});
  return spec;
}

} // namespace mpm_test

#endif
