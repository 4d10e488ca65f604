// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Example_untangling.h>

#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Edge_faces.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>
#include <CGAL/MPM/internal/Nearest_surface.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <map>
#include <set>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// Crossings are decided by exact predicates, as `self_intersecting_faces()`
// decides them: with rounded ones, faces meeting at a shallow angle along an
// edge are reported as crossing.
using Exact_mesh = internal::Exact_predicates_surface_mesh;
using Face = Exact_mesh::Face_index;
namespace PMP = CGAL::Polygon_mesh_processing;

// Per label, the input's faces of that label and of the labels it shares a
// seam with, to project onto: a vertex beside a seam may belong on the
// other side of it (a template's first row squeezed against its seam, which
// the part's own faces pinned to its border: ant_97's antenna), but never
// on a finger the part does not touch, however close.
std::map<int, Nearest_surface> surfaces_around_labels(const Labeled_mesh& input)
{
  std::map<int, std::set<int>> around;
  for(const auto& [edge, faces] : faces_of_edges(input.mesh))
    for(int f : faces)
      for(int g : faces) around[input.face_labels[std::size_t(f)]].insert(input.face_labels[std::size_t(g)]);
  std::map<int, Nearest_surface> surfaces;
  for(const auto& [label, labels] : around)
  {
    Indexed_mesh part;
    part.points = input.mesh.points;
    for(std::size_t f = 0; f < input.mesh.triangles.size(); ++f)
      if(labels.count(input.face_labels[f])) part.triangles.push_back(input.mesh.triangles[f]);
    surfaces.try_emplace(label, part);
  }
  return surfaces;
}

// The pairs of faces of `mesh` that cross each other.
std::vector<std::pair<int, int>> crossings_of(const Exact_mesh& mesh)
{
  std::vector<std::pair<Face, Face>> found;
  PMP::self_intersections(mesh, std::back_inserter(found));
  std::vector<std::pair<int, int>> pairs;
  for(const auto& [f, g] : found) pairs.emplace_back(int(f), int(g));
  return pairs;
}

// The example as a halfedge mesh whose points are changed in place for
// each trial, so that crossings and folds are counted only where a trial
// moves vertices: among the faces whose boxes meet those it touches.
class Trial_mesh
{
public:
  Trial_mesh(Exact_mesh mesh, const Nearest_surface& folds) : mesh_(std::move(mesh)), folds_(folds) {}

  std::vector<std::pair<int, int>> crossing_pairs() const { return crossings_of(mesh_); }

  std::vector<int> folded_faces() const
  {
    std::vector<int> folded;
    for(Face f : faces(mesh_))
      if(is_folded(f)) folded.push_back(int(f));
    return folded;
  }

  // Moves `moved` to `positions` if that lowers the crossings near them
  // without folding more faces over the input, or lowers the folded faces
  // among those it touches without more crossings; returns whether it did.
  bool try_move(const std::vector<int>& moved, const Point_matrix& positions)
  {
    std::vector<Exact_mesh::Point> before;
    for(int v : moved) before.push_back(mesh_.point(Exact_mesh::Vertex_index(v)));
    std::vector<Face> touched;
    for(int v : moved)
      for(Face f : CGAL::faces_around_target(mesh_.halfedge(Exact_mesh::Vertex_index(v)), mesh_))
        if(f != Exact_mesh::null_face()) touched.push_back(f);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    // The faces that can cross a touched face, before or after the move.
    set_points(moved, positions);
    CGAL::Bbox_3 box = box_of(touched);
    restore(moved, before);
    box += box_of(touched);
    std::vector<Face> near;
    for(Face f : faces(mesh_))
      if(CGAL::do_overlap(box, box_of({f}))) near.push_back(f);
    const auto state = [&](int& crossings, int& folded) {
      std::vector<std::pair<Face, Face>> found;
      PMP::self_intersections(near, mesh_, std::back_inserter(found));
      crossings = int(found.size());
      folded = 0;
      for(Face f : touched) folded += is_folded(f);
    };
    int crossings_before = 0, folded_before = 0, crossings_after = 0, folded_after = 0;
    state(crossings_before, folded_before);
    set_points(moved, positions);
    state(crossings_after, folded_after);
    if((crossings_after < crossings_before && folded_after <= folded_before) ||
       (folded_after < folded_before && crossings_after <= crossings_before))
      return true;
    restore(moved, before);
    return false;
  }

private:
  void set_points(const std::vector<int>& moved, const Point_matrix& positions)
  {
    for(int v : moved) mesh_.point(Exact_mesh::Vertex_index(v)) = Exact_mesh::Point(positions(v, 0), positions(v, 1), positions(v, 2));
  }

  void restore(const std::vector<int>& moved, const std::vector<Exact_mesh::Point>& before)
  {
    for(std::size_t i = 0; i < moved.size(); ++i) mesh_.point(Exact_mesh::Vertex_index(moved[i])) = before[i];
  }

  bool is_folded(Face f) const
  {
    Eigen::Vector3d corner[3];
    int k = 0;
    for(Exact_mesh::Vertex_index v : CGAL::vertices_around_face(mesh_.halfedge(f), mesh_))
    {
      const Exact_mesh::Point& p = mesh_.point(v);
      corner[k++] = Eigen::Vector3d(p.x(), p.y(), p.z());
    }
    return folds_.folded(corner[0], corner[1], corner[2]);
  }

  CGAL::Bbox_3 box_of(const std::vector<Face>& faces) const
  {
    CGAL::Bbox_3 box;
    for(Face f : faces)
      for(Exact_mesh::Vertex_index v : CGAL::vertices_around_face(mesh_.halfedge(f), mesh_)) box += mesh_.point(v).bbox();
    return box;
  }

  Exact_mesh mesh_;
  const Nearest_surface& folds_;
};

// The vertices of `faces` and `rings` rings around them that are inside a
// part (`label` >= 0).
std::vector<int> vertices_around(const Indexed_mesh& mesh, std::initializer_list<int> faces, int rings,
                                 const std::vector<std::vector<int>>& next, const std::vector<int>& label)
{
  std::vector<bool> within(label.size(), false);
  for(int face : faces)
    for(int v : mesh.triangles[std::size_t(face)]) within[std::size_t(v)] = true;
  for(int r = 0; r < rings; ++r)
  {
    const std::vector<bool> before = within;
    for(std::size_t v = 0; v < label.size(); ++v)
      if(before[v])
        for(int w : next[v]) within[std::size_t(w)] = true;
  }
  std::vector<int> vertices;
  for(std::size_t v = 0; v < label.size(); ++v)
    if(within[v] && label[v] >= 0) vertices.push_back(int(v));
  return vertices;
}

} // namespace

Point_matrix untangled_positions(const Indexed_mesh& mesh, const std::vector<int>& face_labels,
                                 const Labeled_mesh& input)
{
  Exact_mesh example;
  try
  {
    example = to_surface_mesh_of<Exact_mesh::Point>(mesh, "learned example", "untangling");
  }
  catch(const Input_error&)
  {
    return {};
  }
  // The input's crossings only when the example crosses itself at all,
  // which a learned example rarely does.
  std::vector<std::pair<int, int>> crossing = crossings_of(example);
  std::vector<std::pair<int, int>> own_pairs;
  const int own = !crossing.empty() && self_intersecting_faces(input.mesh, own_pairs) ? int(own_pairs.size()) : 0;
  const Nearest_surface folds(input.mesh);
  Trial_mesh trial(std::move(example), folds);
  std::vector<int> folded = trial.folded_faces();
  if(int(crossing.size()) <= own && folded.empty()) return {};
  // Each vertex's label; -1 on a seam (faces of two labels), where it stays:
  // a seam vertex moved would be merged anew when the model is learned
  // again, and the dockings it changed folded an ant's legs when
  // symmetrized.
  std::vector<int> label(std::size_t(mesh.points.rows()), -2);
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int v : mesh.triangles[f])
      label[std::size_t(v)] = label[std::size_t(v)] == -2 || label[std::size_t(v)] == face_labels[f] ? face_labels[f] : -1;
  std::vector<std::vector<int>> next(label.size());
  for(const Cluster_edge& e : mesh_edges(mesh.triangles))
  {
    next[std::size_t(e.source)].push_back(e.target);
    next[std::size_t(e.target)].push_back(e.source);
  }
  const std::map<int, Nearest_surface> surfaces = surfaces_around_labels(input);
  // A vertex inside a part to the mean of its neighbours, back onto the
  // input around its part. The seam splits the triangles along it into
  // fans, so a vertex next to a seam has many seam neighbours close
  // together: they count as one, or the mean would pull it onto the seam,
  // where the fan's slivers fold.
  const auto move_to_neighbours = [&](std::size_t v, Point_matrix& points) {
    const auto s = surfaces.find(label[v]);
    if(s == surfaces.end() || next[v].empty()) return;
    Eigen::RowVector3d inside = Eigen::RowVector3d::Zero(), seam = Eigen::RowVector3d::Zero();
    int inside_count = 0, seam_count = 0;
    for(int w : next[v])
    {
      if(label[std::size_t(w)] == -1) seam += points.row(w), ++seam_count;
      else inside += points.row(w), ++inside_count;
    }
    const Eigen::RowVector3d mean =
      (inside + (seam_count ? Eigen::RowVector3d(seam / seam_count) : Eigen::RowVector3d::Zero())) /
      double(inside_count + (seam_count ? 1 : 0));
    points.row(Eigen::Index(v)) = s->second.closest_point(mean.transpose()).transpose();
  };
  Point_matrix points = mesh.points;
  bool improved = false;
  // Each crossing pair and each folded face on its own, the moved region
  // grown ring by ring until a move takes it out: a move that helps one
  // place is not held back by another place it does not reach. A face
  // folded inside a part is a template's fold the correspondence's repair
  // left (a sliver by an ant's antenna seam).
  for(int pass = 0; pass < 6 && (int(crossing.size()) > own || !folded.empty()); ++pass)
  {
    std::vector<std::pair<int, int>> places = int(crossing.size()) > own ? crossing : std::vector<std::pair<int, int>>();
    for(int f : folded) places.emplace_back(f, f);
    bool moved_any = false;
    for(const auto& [f, g] : places)
      for(int rings = 0; rings <= 4; ++rings)
      {
        const std::vector<int> moved = vertices_around(mesh, {f, g}, rings, next, label);
        if(moved.empty()) continue;
        Point_matrix candidate = points;
        for(int sweep = 0; sweep < 5; ++sweep)
          for(int v : moved) move_to_neighbours(std::size_t(v), candidate);
        if(!trial.try_move(moved, candidate)) continue;
        for(int v : moved) points.row(v) = candidate.row(v);
        moved_any = improved = true;
        break;
      }
    if(!moved_any) break;
    crossing = trial.crossing_pairs();
    folded = trial.folded_faces();
  }
  return improved ? points : Point_matrix();
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
