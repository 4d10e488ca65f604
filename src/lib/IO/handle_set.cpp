// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/internal/Farthest_point_sampling.h>
#include <CGAL/MPM/internal/Json_reader.h>

#include <limits>
#include <map>
#include <set>
#include <utility>

namespace CGAL {
namespace MPM {

namespace {

using json = nlohmann::json;
using internal::Json_reader;

const char* const handles_format = "cgal-mpm-handles";
constexpr int handles_version = 1;

std::string handle_element(std::size_t i) { return "handles[" + std::to_string(i) + "]"; }

Eigen::RowVector3d vector_of(const Json_reader& reader, const json& j, const std::string& element)
{
  const json& a = reader.array_of(j, element);
  if(a.size() != 3)
    reader.fail(element, "must hold 3 numbers, not " + std::to_string(a.size()));
  Eigen::RowVector3d v;
  for(int k = 0; k < 3; ++k) v[k] = reader.number_of(a[k], element + "[" + std::to_string(k) + "]");
  return v;
}

void check_targets_source(int number_of_vertices, const Point_matrix& targets_source)
{
  if(targets_source.rows() != number_of_vertices)
    throw Input_error("", "handle targets", "the target positions have " + std::to_string(targets_source.rows()) +
                                              " rows, the mesh has " + std::to_string(number_of_vertices) +
                                              " vertices");
}

Handle_set handles_at(std::vector<int> vertices, const Point_matrix& targets_source)
{
  Handle_set h;
  h.vertices = std::move(vertices);
  h.targets.resize(h.size(), 3);
  for(int i = 0; i < h.size(); ++i) h.targets.row(i) = targets_source.row(h.vertices[i]);
  return h;
}

} // namespace

void validate_handles(const Handle_set& handles, int number_of_vertices, const std::string& source)
{
  if(handles.targets.rows() != handles.size())
    throw Input_error(source, "", std::to_string(handles.size()) + " handle vertices but " +
                                    std::to_string(handles.targets.rows()) + " targets");
  std::map<int, int> entry_of_vertex;
  for(int i = 0; i < handles.size(); ++i) {
    const int v = handles.vertices[i];
    if(v < 0 || v >= number_of_vertices)
      throw Input_error(source, handle_element(i), "vertex " + std::to_string(v) + " is out of range (the mesh has " +
                                                     std::to_string(number_of_vertices) + " vertices)");
    if(!handles.targets.row(i).allFinite())
      throw Input_error(source, handle_element(i), "the target is not finite");
    const auto first = entry_of_vertex.emplace(v, i);
    if(!first.second)
      throw Input_error(source, handle_element(i), "vertex " + std::to_string(v) + " is also " +
                                                     handle_element(first.first->second));
  }
}

Handle_set parse_handles(const std::string& text, const std::string& source, const Point_matrix& rest)
{
  const Json_reader reader(source);
  const json root = reader.parse_document(text, handles_format, handles_version);
  reader.check_keys(root, "", {"format", "version", "handles"});
  if(!root.contains("handles")) reader.fail("handles", "no handles (the key is missing)");
  const json& list = reader.array_of(root["handles"], "handles");
  if(list.empty()) reader.fail("handles", "no handles");

  const long long n = rest.rows();
  std::vector<int> vertices;
  std::vector<Eigen::RowVector3d> targets;
  // First entry and result row of each vertex, to merge or reject repeats.
  std::map<int, std::pair<std::size_t, std::size_t>> first_of_vertex;
  for(std::size_t i = 0; i < list.size(); ++i) {
    const std::string element = handle_element(i);
    const json& h = reader.object_of(list[i], element);
    reader.check_keys(h, element, {"vertex", "target", "offset"});
    if(!h.contains("vertex")) reader.fail(element, "lacks \"vertex\"");
    const int v = reader.non_negative(h["vertex"], element + ".vertex");
    if(v >= n)
      reader.fail(element, "vertex " + std::to_string(v) + " is out of range (the mesh has " + std::to_string(n) +
                             " vertices)");
    const bool absolute = h.contains("target");
    if(absolute == h.contains("offset"))
      reader.fail(element, absolute ? "gives both \"target\" and \"offset\"; give one"
                                    : "gives neither \"target\" nor \"offset\"");
    const Eigen::RowVector3d target = absolute ? vector_of(reader, h["target"], element + ".target")
                                               : Eigen::RowVector3d(rest.row(v) + vector_of(reader, h["offset"],
                                                                                            element + ".offset"));
    // An offset can overflow where neither it nor the rest position does.
    if(!target.allFinite()) reader.fail(element, "the target is not finite");

    const auto first = first_of_vertex.emplace(v, std::make_pair(i, vertices.size()));
    if(first.second) {
      vertices.push_back(v);
      targets.push_back(target);
    } else if(targets[first.first->second.second] != target) {
      reader.fail(element, "vertex " + std::to_string(v) + " already has a different target in " +
                             handle_element(first.first->second.first));
    }
  }

  Handle_set result;
  result.vertices = std::move(vertices);
  result.targets.resize(result.size(), 3);
  for(int i = 0; i < result.size(); ++i) result.targets.row(i) = targets[i];
  return result;
}

Handle_set read_handles(const std::string& path, const Point_matrix& rest)
{
  return parse_handles(internal::read_file(path), path, rest);
}

std::string handles_to_json(const Handle_set& handles)
{
  // The format holds any vertex index; the mesh is checked on reading.
  validate_handles(handles, std::numeric_limits<int>::max(), "handle set");
  json list = json::array();
  for(int i = 0; i < handles.size(); ++i)
    list.push_back({{"vertex", handles.vertices[i]},
                    {"target", {handles.targets(i, 0), handles.targets(i, 1), handles.targets(i, 2)}}});
  const json root = {{"format", handles_format}, {"version", handles_version}, {"handles", list}};
  return root.dump(2) + "\n";
}

void write_handles(const Handle_set& handles, const std::string& path)
{
  const std::string text = handles_to_json(handles);
  internal::write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

Handle_set farthest_point_handles(const Indexed_mesh& mesh, int count, const Point_matrix& targets_source)
{
  const int n = mesh.number_of_vertices();
  check_targets_source(n, targets_source);
  if(count < 1 || count > n)
    throw Input_error("", "handle count", std::to_string(count) + " is not in [1, " + std::to_string(n) + "]");

  // The first handle is the vertex farthest from the centroid (maxCoeff()
  // takes the first of equals, the lowest index).
  Eigen::Index first = 0;
  (mesh.points.rowwise() - mesh.points.colwise().mean()).rowwise().squaredNorm().maxCoeff(&first);
  Eigen::VectorXd nearest = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  return handles_at(internal::farthest_point_sampling(mesh.points, count, int(first), nearest), targets_source);
}

Handle_set handles_per_part(const Labeled_mesh& mesh, int per_part, const Point_matrix& targets_source)
{
  check_targets_source(mesh.mesh.number_of_vertices(), targets_source);
  if(per_part != 1 && per_part != 2)
    throw Input_error(mesh.source, "handles per part", std::to_string(per_part) + " is not 1 or 2");
  if(mesh.face_labels.size() != mesh.mesh.triangles.size())
    throw Input_error(mesh.source, "", std::to_string(mesh.face_labels.size()) + " labels for " +
                                         std::to_string(mesh.mesh.triangles.size()) + " faces");

  std::map<int, std::set<int>> vertices_of_label;
  for(std::size_t f = 0; f < mesh.face_labels.size(); ++f)
    vertices_of_label[mesh.face_labels[f]].insert(mesh.mesh.triangles[f].begin(), mesh.mesh.triangles[f].end());

  std::vector<int> chosen;
  std::set<int> is_chosen;
  for(const auto& part : vertices_of_label) {
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for(int v : part.second) centroid += mesh.mesh.points.row(v);
    centroid /= double(part.second.size());
    // Strict comparisons over increasing indices break ties to the smallest.
    int nearest = -1, farthest = -1;
    double nearest_d = 0, farthest_d = 0;
    for(int v : part.second) {
      const double d = (mesh.mesh.points.row(v) - centroid).squaredNorm();
      if(nearest < 0 || d < nearest_d) nearest = v, nearest_d = d;
      if(farthest < 0 || d > farthest_d) farthest = v, farthest_d = d;
    }
    for(int v : per_part == 2 ? std::vector<int>{nearest, farthest} : std::vector<int>{nearest})
      if(is_chosen.insert(v).second) chosen.push_back(v);
  }
  return handles_at(std::move(chosen), targets_source);
}

} // namespace MPM
} // namespace CGAL
