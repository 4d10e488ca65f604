// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/internal/Seam_stitching.h>
#include <CGAL/MPM/internal/Training_parts.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <CGAL/Kd_tree.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;

// Boundary dockings with merged seams between a rebuilt part and its seam
// neighbours. A site is the part's own vertices on the seam and the ends of
// the border edges the seam splits.
void stitched_dockings(int example, const Labeled_mesh& original, const Labeled_mesh& rebuilt,
                       const std::vector<Part_instance>& parts, const std::map<int, int>& part_of_label,
                       const Corresponded_training& corresponded, std::vector<Observation>& observations)
{
  std::map<int, std::vector<int>> part_vertices;
  for(const auto& [label, p] : part_of_label) part_vertices[label] = parts[p].vertices;
  for(internal::Stitched_seam& seam :
      internal::stitch_seams(original, rebuilt, corresponded.original_vertex[example], part_vertices,
                             corresponded.detached[example]))
  {
    Observation o;
    o.example = example;
    o.a = part_of_label.at(seam.label_a);
    o.b = part_of_label.at(seam.label_b);
    o.kind = Docking_kind::boundary;
    for(const Seam_vertex& v : seam.merged)
      for(int side = 0; side < 2; ++side)
      {
        std::vector<int>& site = side == 0 ? o.site_a : o.site_b;
        if(v.local[side] >= 0) site.push_back(v.local[side]);
        else site.insert(site.end(), {v.from[side], v.to[side]});
      }
    for(std::vector<int>* site : {&o.site_a, &o.site_b})
    {
      std::sort(site->begin(), site->end());
      site->erase(std::unique(site->begin(), site->end()), site->end());
    }
    o.merged = std::move(seam.merged);
    observations.push_back(std::move(o));
  }
}

} // namespace

// Boundary dockings: parts whose faces share an edge. Generalized dockings:
// parts of different connected components within the docking radius.
// With `corresponded`, a part rebuilt by dense correspondence (detached
// from the neighbours it shared seams with) docks only to those.
std::vector<Observation> find_dockings(const std::vector<Training_input>& inputs,
                                       const std::vector<Part_instance>& parts, double radius,
                                       const Corresponded_training* corresponded,
                                       const std::vector<Training_input>* originals)
{
  std::vector<Observation> observations;
  for(std::size_t e = 0; e < inputs.size(); ++e)
  {
    const Labeled_mesh& lm = inputs[e].mesh;
    const int n = lm.mesh.number_of_vertices();
    std::map<int, int> part_of_label;
    for(std::size_t p = 0; p < parts.size(); ++p)
      if(parts[p].example == int(e)) part_of_label[parts[p].label] = static_cast<int>(p);

    std::map<std::pair<int, int>, std::vector<int>> labels_of_edge;
    for(int f = 0; f < lm.mesh.number_of_faces(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = lm.mesh.triangles[f][k], b = lm.mesh.triangles[f][(k + 1) % 3];
        std::vector<int>& labels = labels_of_edge[{std::min(a, b), std::max(a, b)}];
        if(std::find(labels.begin(), labels.end(), lm.face_labels[f]) == labels.end())
          labels.push_back(lm.face_labels[f]);
      }
    std::map<std::pair<int, int>, std::set<int>> seam_vertices;
    for(const auto& [edge, labels] : labels_of_edge)
      for(std::size_t i = 0; i < labels.size(); ++i)
        for(std::size_t j = i + 1; j < labels.size(); ++j)
        {
          std::set<int>& s = seam_vertices[{std::min(labels[i], labels[j]), std::max(labels[i], labels[j])}];
          s.insert(edge.first);
          s.insert(edge.second);
        }

    std::vector<std::unordered_map<int, int>> local_of(parts.size());
    const auto local = [&](int p, int v) {
      std::unordered_map<int, int>& m = local_of[p];
      if(m.empty())
        for(std::size_t i = 0; i < parts[p].vertices.size(); ++i) m[parts[p].vertices[i]] = static_cast<int>(i);
      return m.at(v);
    };

    for(const auto& [labels, vertices] : seam_vertices)
    {
      Observation o;
      o.example = static_cast<int>(e);
      o.a = part_of_label.at(labels.first);
      o.b = part_of_label.at(labels.second);
      o.kind = Docking_kind::boundary;
      for(int v : vertices) o.seam.push_back({local(o.a, v), local(o.b, v)});
      std::sort(o.seam.begin(), o.seam.end());
      for(const auto& [la, lb] : o.seam)
      {
        o.site_a.push_back(la);
        o.site_b.push_back(lb);
      }
      std::sort(o.site_a.begin(), o.site_a.end());
      std::sort(o.site_b.begin(), o.site_b.end());
      observations.push_back(std::move(o));
    }

    // Connected components through shared edges.
    std::vector<int> rank(n), parent(n);
    boost::disjoint_sets<int*, int*> components(rank.data(), parent.data());
    for(int v = 0; v < n; ++v) components.make_set(v);
    for(const auto& [edge, labels] : labels_of_edge) components.union_set(edge.first, edge.second);
    std::map<int, std::set<int>> components_of_part;
    std::vector<std::vector<int>> parts_of_vertex(n);
    for(const auto& [label, p] : part_of_label)
      for(int v : parts[p].vertices)
      {
        components_of_part[p].insert(components.find_set(v));
        parts_of_vertex[v].push_back(p);
      }
    const auto share_component = [&](int p, int q) {
      const std::set<int>& a = components_of_part[p];
      const std::set<int>& b = components_of_part[q];
      return std::any_of(a.begin(), a.end(), [&](int c) { return b.count(c) > 0; });
    };
    std::set<int> seamed; // labels with a seam before the rebuild
    if(corresponded)
      for(const auto& [a, b] : corresponded->seams[e])
      {
        seamed.insert(a);
        seamed.insert(b);
      }
    // A rebuilt part that had seams docks by them, stitched (see below).
    const auto may_dock = [&](int p, int q) {
      if(!corresponded) return true;
      const auto bound = [&](int l) { return corresponded->detached[e].count(l) > 0 && seamed.count(l) > 0; };
      return !(bound(parts[p].label) || bound(parts[q].label));
    };
    if(corresponded && originals && !corresponded->detached[e].empty())
      stitched_dockings(int(e), (*originals)[e].mesh, lm, parts, part_of_label, *corresponded, observations);
    std::set<int> all_components;
    for(const auto& [p, comps] : components_of_part) all_components.insert(comps.begin(), comps.end());
    if(all_components.size() < 2) continue;

    using Traits_base = CGAL::Search_traits_3<Kernel>;
    using Point_map = CGAL::Pointer_property_map<Point_3>::type;
    using Traits = CGAL::Search_traits_adapter<int, Point_map, Traits_base>;
    using Tree = CGAL::Kd_tree<Traits>;
    using Sphere = CGAL::Fuzzy_sphere<Traits>;
    std::vector<Point_3> points(n);
    for(int v = 0; v < n; ++v) points[v] = Point_3(lm.mesh.points(v, 0), lm.mesh.points(v, 1), lm.mesh.points(v, 2));
    std::vector<int> referenced;
    for(int v = 0; v < n; ++v)
      if(!parts_of_vertex[v].empty()) referenced.push_back(v);
    Point_map point_map = CGAL::make_property_map(points);
    Tree tree(referenced.begin(), referenced.end(), Tree::Splitter(), Traits(point_map));
    std::map<std::pair<int, int>, std::pair<std::set<int>, std::set<int>>> near;
    std::vector<int> found;
    for(int v : referenced)
    {
      found.clear();
      tree.search(std::back_inserter(found), Sphere(points[v], radius, 0., Traits(point_map)));
      for(int w : found)
        for(int p : parts_of_vertex[v])
          for(int q : parts_of_vertex[w])
            if(p < q && !share_component(p, q) && may_dock(p, q))
            {
              auto& entry = near[{p, q}];
              entry.first.insert(local(p, v));
              entry.second.insert(local(q, w));
            }
    }
    for(const auto& [pq, sites] : near)
    {
      Observation o;
      o.example = static_cast<int>(e);
      o.a = pq.first;
      o.b = pq.second;
      o.kind = Docking_kind::generalized;
      o.site_a.assign(sites.first.begin(), sites.first.end());
      o.site_b.assign(sites.second.begin(), sites.second.end());
      observations.push_back(std::move(o));
    }
  }
  return observations;
}

// A boundary site is the exact seam; generalized sites of different
// observations are the same site when they mostly overlap (Jaccard >= 1/2),
// since their extent varies with the shape.
int find_or_add_site(Part_type& type, Docking_kind kind, const std::vector<int>& vertices)
{
  for(std::size_t s = 0; s < type.sites.size(); ++s)
  {
    Docking_site& site = type.sites[s];
    if(site.kind != kind) continue;
    if(kind == Docking_kind::boundary)
    {
      if(site.vertices == vertices) return static_cast<int>(s);
      continue;
    }
    std::vector<int> common, all;
    std::set_intersection(site.vertices.begin(), site.vertices.end(), vertices.begin(), vertices.end(),
                          std::back_inserter(common));
    std::set_union(site.vertices.begin(), site.vertices.end(), vertices.begin(), vertices.end(),
                   std::back_inserter(all));
    if(2 * common.size() >= all.size())
    {
      site.vertices = all;
      return static_cast<int>(s);
    }
  }
  type.sites.push_back({kind, vertices});
  return static_cast<int>(type.sites.size()) - 1;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
