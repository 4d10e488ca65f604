// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Dense correspondence of the same-type segments of training meshes, and the
// segments that keep their own shape as types of their own.
#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/internal/Message_text.h>
#include <CGAL/MPM/internal/Training_segments.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

namespace CGAL {
namespace MPM {

namespace internal {

void local_part(const Indexed_mesh& mesh, const std::vector<int>& faces, std::vector<int>& local_of,
                std::vector<int>& vertices, std::vector<Triangle>& triangles)
{
  vertices.clear();
  triangles.clear();
  triangles.reserve(faces.size());
  for(int f : faces)
  {
    Triangle t;
    for(int k = 0; k < 3; ++k)
    {
      const int v = mesh.triangles[f][k];
      if(local_of[v] < 0)
      {
        local_of[v] = static_cast<int>(vertices.size());
        vertices.push_back(v);
      }
      t[k] = local_of[v];
    }
    triangles.push_back(t);
  }
  for(int v : vertices) local_of[v] = -1;
}

std::map<int, std::vector<int>> faces_by_label(const Labeled_mesh& lm)
{
  std::map<int, std::vector<int>> faces_of_label;
  for(int f = 0; f < lm.mesh.number_of_faces(); ++f) faces_of_label[lm.face_labels[f]].push_back(f);
  return faces_of_label;
}

} // namespace internal

using internal::faces_by_label;
using internal::label_element;
using internal::percent;
using internal::local_part;
using internal::quoted;

namespace {

// A segment of a part type in one input.
struct Segment_ref
{
  int example, label;
  std::vector<int> vertices;
  std::vector<Triangle> triangles;
};

// One segment of a type to correspond, from its input: its own vertices,
// the annotation's landmarks, and per seam vertex the type across the seam.
Correspondence_segment correspondence_segment(const Training_input& input, const Segment_ref& r, const std::string& name,
                                              const std::map<std::string, int>& tag_of_type)
{
  const Indexed_mesh& mesh = input.mesh.mesh;
  Correspondence_segment c;
  c.name = input.mesh.source + " label " + std::to_string(r.label);
  c.mesh.points.resize(r.vertices.size(), 3);
  std::unordered_map<int, int> local;
  for(std::size_t k = 0; k < r.vertices.size(); ++k)
  {
    c.mesh.points.row(k) = mesh.points.row(r.vertices[k]);
    local[r.vertices[k]] = static_cast<int>(k);
  }
  c.mesh.triangles = r.triangles;
  const auto landmarks = input.annotation.landmarks_of_label.find(r.label);
  if(landmarks != input.annotation.landmarks_of_label.end())
    for(std::size_t k = 0; k < landmarks->second.size(); ++k)
    {
      const auto it = local.find(landmarks->second[k]);
      if(it == local.end())
        throw Input_error(input.annotation.source.empty() ? input.mesh.source + " annotation" : input.annotation.source,
                          label_element(r.label, name) + ": landmark " + std::to_string(k),
                          "vertex " + std::to_string(landmarks->second[k]) + " is not a vertex of this part");
      c.landmarks.push_back(it->second);
    }
  c.seam_tags.assign(r.vertices.size(), -1);
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    const int other = input.mesh.face_labels[f];
    if(other == r.label) continue;
    const auto other_type = input.annotation.part_type_of_label.find(other);
    for(int v : mesh.triangles[f])
    {
      const auto it = local.find(v);
      if(it != local.end())
        c.seam_tags[it->second] =
          other_type == input.annotation.part_type_of_label.end() ? -1 : tag_of_type.at(other_type->second);
    }
  }
  return c;
}

// True when some vertex of the triangles lies on no border edge.
bool has_interior_vertex(const std::vector<Triangle>& triangles)
{
  std::map<std::pair<int, int>, int> uses;
  for(const Triangle& t : triangles)
    for(int k = 0; k < 3; ++k) ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::set<int> all, on_border;
  for(const auto& [e, count] : uses)
  {
    all.insert({e.first, e.second});
    if(count == 1) on_border.insert({e.first, e.second});
  }
  return on_border.size() < all.size();
}

// Coverage residual (of the segment's diagonal) above which the template
// did not find the segment: on the real hands a good fit stays under 1%, a
// thumb base matched to the other proximal phalanges' template is at 11%.
constexpr double max_correspondence_residual = 0.03;
// Fraction of the template's triangles facing against the segment (after
// the repairs of folds) above which the template is laid wrongly on it: a
// fold covers a few percent at most; octopus_124's thin arms, covered to
// 1% by a template twisted around them, had 40% turned, and their learned
// example 800 self-intersecting face pairs.
constexpr double max_flipped_fraction = 0.1;
// Pairs of crossing template triangles, as a fraction of the template's
// triangles, above which the template crumples on a segment it does not
// fit (hand_197's thinnest proximal phalanx: 147 pairs of 957 triangles,
// 15%); fewer are local folds at a seam (a CGAL diplodocus leg: 3).
constexpr double max_crossing_fraction = 0.02;

// Pairs of intersecting triangles of `mesh` (0 when it is no manifold).
std::size_t self_intersections_of(const Indexed_mesh& mesh)
{
  std::vector<std::pair<int, int>> pairs;
  return self_intersecting_faces(mesh, pairs) ? pairs.size() : 0;
}

// A segment whose correspondence failed, and why.
struct Failure
{
  std::size_t segment;
  std::string why;
};

// Segments whose correspondence failed, ascending: the template covers the
// segment poorly, lies twisted around it, or crumples on it (many of its
// triangles cross where the segment's do not: a learned example with such
// a part intersects itself in every edit). When most failed, the template is the
// odd one out (a thumb base among proximal phalanges).
std::vector<Failure> failed_segments(const Dense_correspondence& c, const std::vector<Correspondence_segment>& segments)
{
  std::vector<Failure> failed;
  for(std::size_t i = 1; i < c.segments.size(); ++i)
  {
    const Segment_correspondence& r = c.segments[i];
    const std::size_t crossing = self_intersections_of(Indexed_mesh{r.positions, c.triangles}),
                      own = self_intersections_of(segments[i].mesh);
    if(r.residual > max_correspondence_residual)
      failed.push_back({i, "the type's template covers it poorly (coverage residual " + percent(r.residual) +
                             " of its diagonal, over " + percent(max_correspondence_residual) + ")"});
    else if(r.flipped_faces > max_flipped_fraction * double(c.triangles.size()))
      failed.push_back({i, "the type's template lies twisted on it (" + std::to_string(r.flipped_faces) + " of its " +
                             std::to_string(c.triangles.size()) + " triangles turned against the segment, over " +
                             percent(max_flipped_fraction) + ")"});
    else if(double(crossing - std::min(crossing, own)) > max_crossing_fraction * double(c.triangles.size()))
      failed.push_back({i, "the type's template crumples on it (" + std::to_string(crossing) +
                             " pairs of its triangles cross, the segment's own " + std::to_string(own) + ")"});
  }
  if(2 * failed.size() > c.segments.size() - 1)
    return {{0, "as the template, it covers most of the type's other segments poorly"}};
  return failed;
}

// The first segment is the template. One of median size: a template much
// finer than a segment crumples on it (hand_190: the largest proximal
// phalanx, 1471 faces, on the smallest, 465, folded into 1347
// self-intersecting face pairs), a much coarser one loses its detail. Of
// two middle sizes the finer: the coarser, where the finer is over 1.3
// times finer than the type's smallest segment, took the PSB learned
// examples from 71 to 54 self-intersecting pairs and octopus_137 from 0.55%
// to 0.27% of the diagonal away from its input, but the mean of hand_181's
// proximal phalanges it gave crossed two fingers when symmetrized, and on
// CGAL's armadillo (two arms, two legs) the coarser always halved the
// smallest area ratio under a drag. A crumpling template is refused instead
// (failed_segments()).
void put_median_segment_first(std::vector<Segment_ref>& refs)
{
  std::vector<std::size_t> order(refs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return refs[a].triangles.size() < refs[b].triangles.size(); });
  if(!order.empty()) std::rotate(refs.begin(), refs.begin() + order[order.size() / 2], refs.begin() + order[order.size() / 2] + 1);
}

} // namespace

Corresponded_training correspond_training_inputs(const std::vector<Training_input>& inputs,
                                                 const Learning_options& options, bool all_types)
{
  Corresponded_training result;
  result.inputs = inputs;
  result.seams.resize(inputs.size());
  result.detached.resize(inputs.size());
  for(std::size_t e = 0; e < inputs.size(); ++e)
  {
    // Label pairs meeting at a vertex: the seams.
    const Labeled_mesh& lm = inputs[e].mesh;
    std::vector<std::set<int>> labels_of_vertex(lm.mesh.number_of_vertices());
    for(int f = 0; f < lm.mesh.number_of_faces(); ++f)
      for(int v : lm.mesh.triangles[f]) labels_of_vertex[v].insert(lm.face_labels[f]);
    for(const std::set<int>& labels : labels_of_vertex)
      for(auto a = labels.begin(); a != labels.end(); ++a)
        for(auto b = std::next(a); b != labels.end(); ++b) result.seams[e].insert({*a, *b});
  }
  // Segments of each annotated type, and the type index that tags seams.
  std::map<std::string, std::vector<Segment_ref>> segments_of_type;
  std::map<std::string, int> tag_of_type;
  std::vector<std::map<int, std::vector<int>>> faces(inputs.size());
  for(std::size_t e = 0; e < inputs.size(); ++e)
  {
    const Training_input& input = inputs[e];
    faces[e] = faces_by_label(input.mesh);
    std::vector<int> local_of(input.mesh.mesh.number_of_vertices(), -1);
    for(const auto& [label, part_faces] : faces[e])
    {
      const auto type = input.annotation.part_type_of_label.find(label);
      if(type == input.annotation.part_type_of_label.end()) continue;
      tag_of_type.insert({type->second, static_cast<int>(tag_of_type.size())});
      Segment_ref r{static_cast<int>(e), label, {}, {}};
      local_part(input.mesh.mesh, part_faces, local_of, r.vertices, r.triangles);
      segments_of_type[type->second].push_back(std::move(r));
    }
  }

  // Per input: new vertex block of each corresponded label, and its landmarks.
  std::vector<std::map<int, Point_matrix>> replaced(inputs.size());
  std::vector<std::map<int, std::vector<int>>> replaced_landmarks(inputs.size());
  std::vector<std::map<int, const std::vector<Triangle>*>> replaced_triangles(inputs.size());
  std::set<int> validated;
  int type_index = 0;
  for(auto& [name, refs] : segments_of_type)
  {
    // Segments `which` (ascending) leave the type, each a type of its own.
    const auto give_own_types = [&, &name = name, &refs = refs](const std::vector<std::size_t>& which, const std::string& why) {
      for(auto it = which.rbegin(); it != which.rend(); ++it)
      {
        const Segment_ref& r = refs[*it];
        // Labels repeat across meshes: with several, the mesh is named too,
        // or two meshes' own shapes would be taken for one type.
        const std::string own = name + (inputs.size() > 1 ? "_mesh" + std::to_string(r.example) : std::string()) +
                                "_label" + std::to_string(r.label);
        if(options.warning)
          options.warning(inputs[r.example].mesh.source + ": " + label_element(r.label, name) + ": " + why +
                          "; it keeps its own shape as part type " + quoted(own));
        result.inputs[r.example].annotation.part_type_of_label[r.label] = own;
        refs.erase(refs.begin() + std::ptrdiff_t(*it));
      }
    };
    bool retry = true;
    int templates_failed = 0;
    while(retry)
    {
      retry = false;
      ++type_index;
      put_median_segment_first(refs);
      bool differ = false;
      for(const Segment_ref& r : refs) differ = differ || r.triangles != refs.front().triangles;
      if(refs.size() < 2 || !(differ || all_types)) continue;
      // A segment to correspond must be one manifold piece (a soup of pieces
      // stays legitimate for parts in known correspondence).
      for(const Segment_ref& r : refs)
        if(validated.insert(r.example).second) validate_segmentation(inputs[r.example].mesh);
      // A sliver (every vertex on a seam, as the thin rings where an
      // octopus's arms were cut twice) has no surface to correspond.
      std::vector<std::size_t> slivers;
      for(std::size_t i = 0; i < refs.size(); ++i)
        if(!has_interior_vertex(refs[i].triangles)) slivers.push_back(i);
      if(!slivers.empty())
      {
        give_own_types(slivers, "has no vertex off its seams, too thin to put in correspondence");
        retry = true;
        continue;
      }
      internal::throw_if_cancelled(options.cancel, "learning");
      if(options.progress) options.progress("correspondence of " + name, double(type_index - 1) / segments_of_type.size());
      std::vector<Correspondence_segment> segments;
      for(const Segment_ref& r : refs) segments.push_back(correspondence_segment(inputs[r.example], r, name, tag_of_type));
      Dense_correspondence_options co = options.correspondence;
      if(options.warning && !co.warning) co.warning = options.warning;
      if(co.cancel == nullptr) co.cancel = options.cancel;
      if(options.progress && !co.progress)
        co.progress = [&](const std::string& stage, double within) {
          // One scale for all types: the type's share, advanced within it.
          options.progress(stage, (double(type_index - 1) + std::clamp(within, 0., 1.)) / segments_of_type.size());
        };
      Dense_correspondence c = compute_dense_correspondence(segments, name, co);
      // A segment the template cannot cover keeps its own shape, as a type of
      // its own; the others are put in correspondence again without it.
      std::vector<Failure> failed = failed_segments(c, segments);
      // A second template that fails as well: the type's segments are too
      // unlike (long arms in different poses); none is put in correspondence.
      if(!failed.empty() && failed.front().segment == 0 && templates_failed++ > 0)
      {
        failed.clear();
        for(std::size_t i = 0; i < refs.size(); ++i)
          failed.push_back({i, "no template covers the type's segments well (two tried)"});
      }
      if(!failed.empty())
      {
        // Highest index first: each leaves `refs`.
        for(auto it = failed.rbegin(); it != failed.rend(); ++it) give_own_types({it->segment}, it->why);
        retry = true;
        continue;
      }
      const Dense_correspondence& stored = result.types[name] = std::move(c);
      for(std::size_t i = 0; i < refs.size(); ++i)
      {
        replaced[refs[i].example][refs[i].label] = stored.segments[i].positions;
        result.detached[refs[i].example].insert(refs[i].label);
        replaced_triangles[refs[i].example][refs[i].label] = &stored.triangles;
        // Landmark k of every segment is the template's landmark vertex k.
        replaced_landmarks[refs[i].example][refs[i].label] = segments.front().landmarks;
        result.segments[name].push_back({refs[i].example, refs[i].label});
      }
    }
  }

  result.original_vertex.resize(inputs.size());
  for(std::size_t e = 0; e < inputs.size(); ++e)
  {
    std::vector<int>& original_vertex = result.original_vertex[e];
    if(replaced[e].empty())
    {
      original_vertex.resize(inputs[e].mesh.mesh.number_of_vertices());
      std::iota(original_vertex.begin(), original_vertex.end(), 0);
      continue;
    }
    const Labeled_mesh& lm = inputs[e].mesh;
    Labeled_mesh rebuilt;
    rebuilt.source = lm.source;
    std::vector<int> new_of(lm.mesh.number_of_vertices(), -1);
    std::vector<Eigen::RowVector3d> points;
    std::map<int, int> block_of_label;
    for(const auto& [label, part_faces] : faces[e])
    {
      const auto it = replaced[e].find(label);
      if(it != replaced[e].end())
      {
        block_of_label[label] = static_cast<int>(points.size());
        for(Eigen::Index v = 0; v < it->second.rows(); ++v) points.push_back(it->second.row(v));
        for(const Triangle& t : *replaced_triangles[e].at(label))
        {
          const int b = block_of_label[label];
          rebuilt.mesh.triangles.push_back({t[0] + b, t[1] + b, t[2] + b});
          rebuilt.face_labels.push_back(label);
        }
        continue;
      }
      for(int f : part_faces)
      {
        Triangle t;
        for(int k = 0; k < 3; ++k)
        {
          int& v = new_of[lm.mesh.triangles[f][k]];
          if(v < 0)
          {
            v = static_cast<int>(points.size());
            points.push_back(lm.mesh.points.row(lm.mesh.triangles[f][k]));
          }
          t[k] = v;
        }
        rebuilt.mesh.triangles.push_back(t);
        rebuilt.face_labels.push_back(label);
      }
    }
    rebuilt.mesh.points.resize(points.size(), 3);
    for(std::size_t v = 0; v < points.size(); ++v) rebuilt.mesh.points.row(v) = points[v];
    original_vertex.assign(points.size(), -1);
    for(std::size_t v = 0; v < new_of.size(); ++v)
      if(new_of[v] >= 0) original_vertex[new_of[v]] = static_cast<int>(v);
    Annotation& annotation = result.inputs[e].annotation;
    for(auto& [label, landmarks] : annotation.landmarks_of_label)
    {
      const auto block = block_of_label.find(label);
      if(block != block_of_label.end())
      {
        landmarks = replaced_landmarks[e].at(label);
        for(int& v : landmarks) v += block->second;
      }
      else
        for(int& v : landmarks)
          if(v >= 0 && v < int(new_of.size())) v = new_of[v];
    }
    result.inputs[e].mesh = std::move(rebuilt);
  }
  return result;
}

} // namespace MPM
} // namespace CGAL
