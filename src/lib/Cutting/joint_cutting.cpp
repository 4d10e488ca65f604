// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Cutting/Joint_cutting.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Mesh_file_checks.h>
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/internal/Joint_finder.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace MPM {

namespace {

using internal::vertex_name;

// `count` vertices of the loop spread evenly along its length.
std::vector<int> anchors(const Indexed_mesh& m, const std::vector<int>& loop, int count)
{
  std::vector<double> at{0.};
  for(std::size_t k = 0; k < loop.size(); ++k)
    at.push_back(at.back() + (m.points.row(loop[(k + 1) % loop.size()]) - m.points.row(loop[k])).norm());
  std::vector<int> r;
  std::size_t k = 0;
  for(int i = 0; i < count; ++i) {
    const double target = at.back() * i / count;
    while(k + 1 < loop.size() && at[k + 1] <= target) ++k;
    if(std::find(r.begin(), r.end(), loop[k]) == r.end()) r.push_back(loop[k]);
  }
  return r;
}

// Every clicked vertex exists and lies on a face.
void check_vertices(const Indexed_mesh& mesh, const std::vector<int>& vertices, const std::string& source)
{
  std::vector<bool> in_face(std::size_t(mesh.number_of_vertices()), false);
  for(const Triangle& t : mesh.triangles)
    for(int v : t)
      if(v >= 0 && v < mesh.number_of_vertices()) in_face[std::size_t(v)] = true;
  for(int v : vertices) {
    if(v < 0 || v >= mesh.number_of_vertices())
      throw Input_error(source, vertex_name(v),
                        "is out of range (the mesh has " + std::to_string(mesh.number_of_vertices()) + " vertices)");
    if(!in_face[std::size_t(v)]) throw Input_error(source, vertex_name(v), "belongs to no face");
  }
}

} // namespace

Joint_cutting_result cut_at_vertices(const Indexed_mesh& mesh, const std::vector<int>& vertices,
                                     const Joint_cutting_options& options, const std::string& mesh_source)
{
  // Checked before the skeleton is computed, so that a bad click fails at once.
  check_vertices(mesh, vertices, mesh_source);
  return Joint_cutter(mesh, options, mesh_source).cut(vertices);
}

Joint_cutter::Joint_cutter(const Indexed_mesh& mesh, const Joint_cutting_options& options,
                           const std::string& mesh_source)
  : finder_(std::make_unique<internal::Joint_finder>(mesh, options, mesh_source))
{
}

Joint_cutter::~Joint_cutter() = default;

Joint_cutting_result Joint_cutter::cut(const std::vector<int>& vertices) const
{
  check_vertices(finder_->mesh(), vertices, finder_->source());
  return internal::cut_at_vertices(*finder_, vertices);
}

namespace internal {

Joint_cutting_result cut_at_vertices(const Joint_finder& finder, const std::vector<int>& vertices)
{
  const Joint_cutting_options& options = finder.options();
  const Indexed_mesh& mesh = finder.mesh();
  const std::string& mesh_source = finder.source();
  Joint_cutting_result result;
  std::vector<int> found;
  std::vector<Section> sections;
  Cutting_options cutting;
  cutting.feature_weight = options.feature_weight;
  Cut_specification spec;
  spec.source = "clicked vertices";
  for(int v : vertices) {
    try {
      const Section s = finder.snapped(v, finder.find(v), options.snap_band);
      for(std::size_t i = 0; i < found.size(); ++i) finder.check_distinct(found[i], sections[i], v, s);
      const Cut_line line{anchors(mesh, s.loop, options.anchors), true, "at vertex " + std::to_string(v)};
      // Traced alone first, so that a section whose points cannot be joined
      // in order is blamed on its click (and skipped) rather than failing all.
      try {
        cut_mesh(mesh, Cut_specification{{line}, {}, spec.source}, cutting, mesh_source);
      } catch(const Input_error& e) {
        finder.fail(v, "the section across the limb there cannot be traced as a cut: " + e.problem());
      }
      found.push_back(v);
      sections.push_back(s);
      spec.cuts.push_back(line);
    } catch(const Input_error& e) {
      if(!options.skip_unfound) throw;
      result.skipped.push_back({v, e.what()});
    }
  }

  Cutting_result cut = cut_mesh(mesh, spec, cutting, mesh_source);

  result.mesh = std::move(cut.mesh);
  for(std::size_t i = 0; i < found.size(); ++i) {
    Joint_cut c;
    c.vertex = found[i];
    c.path = cut.paths[i];
    c.length = cut.lengths[i];
    c.limb_radius = sections[i].axis.radius;
    c.shift = std::abs(sections[i].shift);
    c.axis = sections[i].axis.direction;
    for(std::size_t k = 0; k + 1 < c.path.size(); ++k) c.centre += mesh.points.row(c.path[k]).transpose();
    c.centre /= double(std::max<std::size_t>(c.path.size() - 1, 1));
    result.cuts.push_back(std::move(c));
  }
  return result;
}

} // namespace internal

} // namespace MPM
} // namespace CGAL
