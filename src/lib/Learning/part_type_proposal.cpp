// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Part types proposed from a segmentation (segment graph, seam loops, size)
// and the checks a real segmentation must pass before correspondence.
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Edge_faces.h>
#include <CGAL/MPM/internal/Message_text.h>
#include <CGAL/MPM/internal/Training_segments.h>

#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <set>
#include <tuple>
#include <unordered_map>

namespace CGAL {
namespace MPM {

using internal::quoted;

namespace {

using internal::faces_by_label;
using internal::faces_of_edges;

std::string segment_name(int label) { return "segment " + std::to_string(label); }

// The faces as a mesh of their own, vertices numbered by first appearance
// (the learner's convention, so connectivity comparisons agree with it).
Indexed_mesh segment_mesh(const Indexed_mesh& mesh, const std::vector<int>& faces)
{
  std::vector<int> local_of(std::size_t(mesh.number_of_vertices()), -1), vertices;
  Indexed_mesh r;
  internal::local_part(mesh, faces, local_of, vertices, r.triangles);
  r.points.resize(Eigen::Index(vertices.size()), 3);
  for(std::size_t i = 0; i < vertices.size(); ++i) r.points.row(Eigen::Index(i)) = mesh.points.row(vertices[i]);
  return r;
}

double area_of(const Indexed_mesh& m)
{
  double a = 0.;
  for(const Triangle& t : m.triangles)
  {
    const Eigen::RowVector3d u = m.points.row(t[1]) - m.points.row(t[0]);
    const Eigen::RowVector3d v = m.points.row(t[2]) - m.points.row(t[0]);
    a += 0.5 * u.cross(v).norm();
  }
  return a;
}

// Double sweep: the farthest vertex from any vertex, then the farthest from
// that one. A lower bound of the diameter within a factor of 2, usually
// much closer on elongated segments; enough to compare sizes.
double diameter_of(const Point_matrix& p)
{
  if(p.rows() == 0) return 0.;
  Eigen::Index a = 0, b = 0;
  (p.rowwise() - p.row(0)).rowwise().squaredNorm().maxCoeff(&a);
  const double d = (p.rowwise() - p.row(a)).rowwise().squaredNorm().maxCoeff(&b);
  return std::sqrt(d);
}

// Faces, area, diameter, seam loops and neighbours of every segment, by label.
std::map<int, Segment_proposal> measure_segments(const Labeled_mesh& lm)
{
  std::map<int, Segment_proposal> r;
  for(const auto& [label, faces] : faces_by_label(lm))
  {
    const Indexed_mesh m = segment_mesh(lm.mesh, faces);
    Segment_proposal& s = r[label];
    s.label = label;
    s.faces = int(faces.size());
    s.area = area_of(m);
    s.diameter = diameter_of(m.points);
    s.seam_loops = int(boundary_loops(m).size());
  }
  std::map<int, std::set<int>> neighbours;
  for(const auto& [key, faces] : faces_of_edges(lm.mesh))
    for(std::size_t i = 0; i < faces.size(); ++i)
      for(std::size_t j = i + 1; j < faces.size(); ++j)
      {
        const int a = lm.face_labels[faces[i]], b = lm.face_labels[faces[j]];
        if(a == b) continue;
        neighbours[a].insert(b);
        neighbours[b].insert(a);
      }
  for(auto& [label, s] : r) s.neighbours.assign(neighbours[label].begin(), neighbours[label].end());
  return r;
}

// Shared edges between two segments: the parent of a segment is its
// neighbour nearest the root with the longest seam, so that a phalanx that
// barely touches a second neighbour still hangs from the right one.
std::map<std::pair<int, int>, int> seam_lengths(const Labeled_mesh& lm)
{
  std::map<std::pair<int, int>, int> r;
  for(const auto& [key, faces] : faces_of_edges(lm.mesh))
    if(faces.size() == 2)
    {
      const int a = lm.face_labels[faces[0]], b = lm.face_labels[faces[1]];
      if(a != b) ++r[{std::min(a, b), std::max(a, b)}];
    }
  return r;
}

// Root (most neighbours, then largest area, then smallest label) and a
// breadth-first order with depth, parent and children filled in.
std::vector<int> breadth_first(const Labeled_mesh& lm, std::map<int, Segment_proposal>& segments, int& root)
{
  root = -1;
  for(const auto& [label, s] : segments)
    if(root < 0 || s.neighbours.size() > segments[root].neighbours.size() ||
       (s.neighbours.size() == segments[root].neighbours.size() && s.area > segments[root].area))
      root = label;
  const std::map<std::pair<int, int>, int> seams = seam_lengths(lm);
  const auto seam = [&](int a, int b) {
    const auto it = seams.find({std::min(a, b), std::max(a, b)});
    return it == seams.end() ? 0 : it->second;
  };
  std::vector<int> order{root};
  std::set<int> seen{root};
  segments[root].depth = 0;
  for(std::size_t i = 0; i < order.size(); ++i)
  {
    const int s = order[i];
    std::vector<int> next = segments[s].neighbours;
    std::stable_sort(next.begin(), next.end(), [&](int a, int b) { return seam(s, a) > seam(s, b); });
    for(int n : next)
      if(seen.insert(n).second)
      {
        segments[n].depth = segments[s].depth + 1;
        segments[n].parent = s;
        ++segments[s].children;
        order.push_back(n);
      }
  }
  // Segments not reached (a mesh of several components) start their own
  // search, so that every segment gets a place; their depth counts from
  // their own component's first segment.
  for(auto& [label, s] : segments)
    if(seen.insert(label).second)
    {
      order.push_back(label);
      for(std::size_t i = order.size() - 1; i < order.size(); ++i)
        for(int n : segments[order[i]].neighbours)
          if(seen.insert(n).second)
          {
            segments[n].depth = segments[order[i]].depth + 1;
            segments[n].parent = order[i];
            ++segments[order[i]].children;
            order.push_back(n);
          }
    }
  return order;
}

// The name a segment's position gives it (before the size split).
std::string position_name(const Segment_proposal& s, int root, const std::map<int, Segment_proposal>& segments)
{
  if(s.label == root) return "root";
  const std::string kind = s.children == 0 ? "tip" : s.children == 1 ? "chain" : "branch";
  std::string name = kind + std::to_string(s.depth);
  const int natural_loops = s.children == 0 ? 1 : 2;
  if(s.children >= 2 || s.seam_loops != natural_loops) name += "_s" + std::to_string(s.seam_loops);
  // The nearest branch above it (not the root) prefixes the name; its own
  // name was set first (breadth-first order).
  for(int a = s.parent; a >= 0 && a != root; a = segments.at(a).parent)
    if(segments.at(a).children >= 2) return segments.at(a).type + "." + name;
  return name;
}

// A segment of a class with its area as compared: scaled to the first
// mesh's size, so that one mesh of a pooled set scanned at another scale does
// not split a class by itself.
struct Class_member
{
  Segment_proposal* segment = nullptr;
  double area = 0.;
};

// Splits `members` (sorted by area) recursively at the largest consecutive
// area ratio while the spread exceeds `ratio`; appends the groups in area order.
void split_by_area(const std::vector<Class_member>& members, double ratio, std::vector<std::vector<Class_member>>& groups)
{
  if(members.size() < 2 || members.back().area <= ratio * members.front().area)
  {
    groups.push_back(members);
    return;
  }
  std::size_t cut = 1;
  for(std::size_t i = 1; i < members.size(); ++i)
    if(members[i].area / members[i - 1].area > members[cut].area / members[cut - 1].area) cut = i;
  split_by_area({members.begin(), members.begin() + std::ptrdiff_t(cut)}, ratio, groups);
  split_by_area({members.begin() + std::ptrdiff_t(cut), members.end()}, ratio, groups);
}

std::string area_range(const std::vector<Class_member>& g)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, g.size() == 1 ? "%.3g" : "%.3g-%.3g", g.front().area, g.back().area);
  return buffer;
}

// Gives the class `name` its final names: the biggest size group keeps it.
void name_size_groups(const std::string& name, std::vector<Class_member> members, double ratio)
{
  std::sort(members.begin(), members.end(), [](const Class_member& a, const Class_member& b) {
    return a.area < b.area || (a.area == b.area && a.segment->label < b.segment->label);
  });
  std::vector<std::vector<Class_member>> groups;
  split_by_area(members, ratio, groups);
  std::size_t main = 0;
  for(std::size_t g = 1; g < groups.size(); ++g)
    if(groups[g].size() >= groups[main].size()) main = g;
  for(std::size_t g = 0; g < groups.size(); ++g)
  {
    std::string type = name, reason;
    if(g != main)
    {
      const std::size_t rank = g > main ? g - main : main - g;
      type += (g > main ? "_large" : "_small") + (rank > 1 ? std::to_string(rank) : std::string());
      reason = "area " + area_range(groups[g]) + " against " + area_range(groups[main]) + " for the other " +
               std::to_string(groups[main].size()) + " of " + name;
    }
    for(const Class_member& m : groups[g])
    {
      m.segment->reason += std::string(m.segment->reason.empty() || reason.empty() ? "" : "; ") + reason;
      m.segment->type = type;
    }
  }
}

// One mesh's segments named by their position in its segment graph.
struct Positioned_segments
{
  std::map<int, Segment_proposal> segments;
  std::vector<int> order; // breadth-first
  int root = -1;
  double diagonal = 0.;
};

Positioned_segments position_segments(const Labeled_mesh& mesh)
{
  validate_segmentation(mesh);
  Positioned_segments p;
  p.segments = measure_segments(mesh);
  p.order = breadth_first(mesh, p.segments, p.root);
  // Parents before children, for the prefixes.
  for(int label : p.order)
  {
    Segment_proposal& s = p.segments[label];
    s.type = position_name(s, p.root, p.segments);
  }
  p.diagonal = internal::bounding_box_diagonal(mesh.mesh.points);
  return p;
}

// Where segments of one position name have different seam-loop counts in
// different meshes, those whose count differs from the first seen get `_sN`.
void separate_seam_counts(std::vector<Positioned_segments>& meshes)
{
  std::map<std::string, int> loops_of_type;
  for(Positioned_segments& m : meshes)
    for(int label : m.order)
    {
      Segment_proposal& s = m.segments[label];
      const auto seen = loops_of_type.emplace(s.type, s.seam_loops).first;
      if(seen->second == s.seam_loops) continue;
      s.reason = std::to_string(s.seam_loops) + " seam loops where " + s.type + " has " +
                 std::to_string(seen->second) + " in an earlier mesh";
      s.type += "_s" + std::to_string(s.seam_loops);
    }
}

Part_type_proposal proposal_of(Positioned_segments& m)
{
  Part_type_proposal r;
  r.root = m.root;
  for(int label : m.order)
  {
    r.segments.push_back(m.segments[label]);
    r.annotation.part_type_of_label[label] = m.segments[label].type;
  }
  // Rows a reader can scan: level by level, each type's segments together.
  std::stable_sort(r.segments.begin(), r.segments.end(), [](const Segment_proposal& a, const Segment_proposal& b) {
    return std::tie(a.depth, a.type, a.label) < std::tie(b.depth, b.type, b.label);
  });
  return r;
}

} // namespace

std::map<std::string, int> Part_type_proposal::instances_of_type() const
{
  std::map<std::string, int> r;
  for(const Segment_proposal& s : segments) ++r[s.type];
  return r;
}

namespace {

std::vector<Part_type_proposal> propose_for(const std::vector<const Labeled_mesh*>& meshes,
                                            const Part_type_proposal_options& options)
{
  std::vector<Positioned_segments> positioned;
  for(const Labeled_mesh* m : meshes) positioned.push_back(position_segments(*m));
  separate_seam_counts(positioned);
  // The size split runs within each mesh, then over each name's segments of
  // all meshes at once with the square of the ratio, so that a name means
  // segments of one size in every mesh without splitting a kind whose size
  // varies from one body to the next (one person cuts an octopus arm at a
  // thin ring by the body, another at half its length: both are `chain1` by
  // position).
  std::map<std::string, std::vector<Class_member>> pooled;
  for(Positioned_segments& m : positioned)
  {
    const double scale = positioned.front().diagonal / m.diagonal;
    const double area_scale = std::isfinite(scale) && scale > 0 ? scale * scale : 1.;
    std::map<std::string, std::vector<Class_member>> classes;
    for(int label : m.order)
    {
      Segment_proposal& s = m.segments[label];
      classes[s.type].push_back({&s, s.area * area_scale});
    }
    for(const auto& [name, members] : classes) name_size_groups(name, members, options.max_area_ratio);
    for(const auto& [name, members] : classes)
      for(const Class_member& member : members) pooled[member.segment->type].push_back(member);
  }
  if(positioned.size() > 1)
    for(const auto& [name, members] : pooled)
      name_size_groups(name, members, options.max_area_ratio * options.max_area_ratio);
  std::vector<Part_type_proposal> r;
  for(Positioned_segments& m : positioned) r.push_back(proposal_of(m));
  return r;
}

} // namespace

Part_type_proposal propose_part_types(const Labeled_mesh& mesh, const Part_type_proposal_options& options)
{
  return propose_for({&mesh}, options).front();
}

std::vector<Part_type_proposal> propose_part_types(const std::vector<Labeled_mesh>& meshes,
                                                   const Part_type_proposal_options& options)
{
  std::vector<const Labeled_mesh*> pointers;
  for(const Labeled_mesh& m : meshes) pointers.push_back(&m);
  return propose_for(pointers, options);
}

void validate_segmentation(const Labeled_mesh& lm)
{
  validate_labeled_mesh(lm);
  const Indexed_mesh& m = lm.mesh;
  const auto edges = faces_of_edges(m);
  const auto segments_of = [&](const std::vector<int>& faces) {
    std::set<int> labels;
    for(int f : faces) labels.insert(lm.face_labels[f]);
    std::string r;
    for(int l : labels) r += (r.empty() ? "" : ", ") + std::to_string(l);
    return (labels.size() == 1 ? "segment " : "segments ") + r;
  };
  for(const auto& [key, faces] : edges)
    if(faces.size() > 2)
    {
      const auto [a, b] = key;
      std::string list;
      for(int f : faces) list += (list.empty() ? "" : ", ") + std::to_string(f);
      throw Input_error(lm.source, segments_of(faces) + ": edge (" + std::to_string(a) + ", " + std::to_string(b) + ")",
                        "shared by " + std::to_string(faces.size()) + " faces (" + list +
                          "): the mesh is not manifold; remove the extra faces (e.g. read it as a soup and "
                          "repair it with CGAL::Polygon_mesh_processing::orient_polygon_soup())");
  }
  // A vertex is manifold when its faces form one fan: faces around it
  // joined through the edges they share with it.
  std::vector<std::vector<int>> faces_of_vertex(std::size_t(m.number_of_vertices()));
  for(int f = 0; f < m.number_of_faces(); ++f)
    for(int v : m.triangles[f]) faces_of_vertex[std::size_t(v)].push_back(f);
  for(int v = 0; v < m.number_of_vertices(); ++v)
  {
    const std::vector<int>& around = faces_of_vertex[std::size_t(v)];
    if(around.size() < 2) continue;
    std::unordered_map<int, int> first_face_with; // other vertex -> local face
    boost::disjoint_sets_with_storage<> fans(around.size());
    for(int i = 0; i < int(around.size()); ++i)
      for(int w : m.triangles[around[i]])
        if(w != v)
        {
          const auto it = first_face_with.emplace(w, i);
          if(!it.second) fans.union_set(i, it.first->second);
        }
    for(int i = 1; i < int(around.size()); ++i)
      if(fans.find_set(i) != fans.find_set(0))
        throw Input_error(lm.source, segments_of(around) + ": vertex " + std::to_string(v),
                          "its faces form several fans (a pinched, non-manifold vertex); repair the mesh first "
                          "(e.g. CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices())");
  }
  // Each segment one face-connected piece.
  boost::disjoint_sets_with_storage<> pieces(std::size_t(m.number_of_faces()));
  for(const auto& [key, faces] : edges)
    if(faces.size() == 2 && lm.face_labels[faces[0]] == lm.face_labels[faces[1]]) pieces.union_set(faces[0], faces[1]);
  for(const auto& [label, faces] : faces_by_label(lm))
  {
    std::map<int, std::vector<int>> by_piece;
    for(int f : faces) by_piece[pieces.find_set(f)].push_back(f);
    if(by_piece.size() < 2) continue;
    std::vector<std::vector<int>> list;
    for(auto& [root, fs] : by_piece) list.push_back(std::move(fs));
    // Largest first; ties by first face, so that the message does not depend on the union-find's roots.
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) {
      return a.size() != b.size() ? a.size() > b.size() : a.front() < b.front();
    });
    std::string sizes;
    for(std::size_t i = 0; i < list.size() && i < 5; ++i) sizes += (i ? ", " : "") + std::to_string(list[i].size());
    if(list.size() > 5) sizes += ", ...";
    throw Input_error(lm.source, segment_name(label),
                      "is not connected: " + std::to_string(list.size()) + " face-connected pieces (" + sizes +
                        " faces; face " + std::to_string(list.back().front()) +
                        " is in the smallest); give each piece its own label");
  }
}

std::map<int, int> seam_loops_of_segments(const Labeled_mesh& mesh)
{
  std::map<int, int> r;
  for(const auto& [label, faces] : faces_by_label(mesh))
    r[label] = int(boundary_loops(segment_mesh(mesh.mesh, faces)).size());
  return r;
}

void validate_seam_counts(const std::vector<Training_input>& inputs)
{
  struct Member { std::size_t input; int label, loops; };
  std::map<std::string, std::vector<Member>> members;
  std::map<std::string, std::string> source; // the first annotation naming the type
  for(std::size_t i = 0; i < inputs.size(); ++i)
  {
    const Annotation& a = inputs[i].annotation;
    if(a.part_type_of_label.empty()) continue;
    for(const auto& [label, loops] : seam_loops_of_segments(inputs[i].mesh))
    {
      const auto type = a.part_type_of_label.find(label);
      if(type == a.part_type_of_label.end()) continue;
      members[type->second].push_back({i, label, loops});
      source.emplace(type->second, a.source.empty() ? inputs[i].mesh.source + " annotation" : a.source);
    }
  }
  for(const auto& [type, list] : members)
  {
    const int first_loops = list[0].loops;
    const bool mixed = std::any_of(list.begin(), list.end(), [first_loops](const Member& m) { return m.loops != first_loops; });
    if(!mixed) continue;
    std::string detail;
    for(const Member& m : list)
      detail += (detail.empty() ? "" : ", ") + std::string(inputs.size() > 1 ? inputs[m.input].mesh.source + " " : "") +
                "label " + std::to_string(m.label) + ": " + std::to_string(m.loops);
    throw Input_error(source[type], "part type " + quoted(type),
                      "segments have different numbers of seam loops (" + detail +
                        "); dense correspondence needs the same number in every segment of a type: give the "
                        "odd segments a type of their own");
  }
}

bool segments_share_connectivity(const std::vector<Labeled_mesh>& meshes)
{
  std::set<std::vector<Triangle>> seen;
  for(const Labeled_mesh& m : meshes)
    for(const auto& [label, faces] : faces_by_label(m))
    {
      if(faces.empty() || std::size_t(faces.back()) >= m.mesh.triangles.size()) continue;
      std::vector<Triangle> local = segment_mesh(m.mesh, faces).triangles;
      if(!seen.insert(std::move(local)).second) return true;
    }
  return false;
}

bool part_types_need_proposing(const std::vector<Labeled_mesh>& meshes)
{
  const bool several_segments = std::any_of(meshes.begin(), meshes.end(), [](const Labeled_mesh& m) {
    const std::vector<int>& l = m.face_labels;
    return std::any_of(l.begin(), l.end(), [&](int x) { return x != l.front(); });
  });
  return several_segments && !segments_share_connectivity(meshes);
}

} // namespace MPM
} // namespace CGAL
