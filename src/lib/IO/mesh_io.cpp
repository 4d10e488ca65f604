// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/internal/Mesh_encoding.h>
#include <CGAL/MPM/internal/Mesh_file_checks.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/IO/PLY/PLY_reader.h>

#include <Eigen/Geometry>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <unordered_map>

namespace CGAL {
namespace MPM {

using namespace internal;

namespace {

namespace fs = std::filesystem;
using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;

// ----------------------------------------------------------------------------

// CGAL's OFF reader sizes a polygon from the corner count in the file before
// reading the corners: bound it by the file size so a corrupt count cannot
// allocate gigabytes.
struct Corner_limit_exceeded {};

struct Bounded_polygon : std::vector<std::size_t>
{
  static thread_local std::size_t corner_limit;

  void resize(std::size_t n)
  {
    if(n > corner_limit) throw Corner_limit_exceeded();
    std::vector<std::size_t>::resize(n);
  }
};
thread_local std::size_t Bounded_polygon::corner_limit = 0;

// Checks shared by the file reader and validate_labeled_mesh(): finite
// coordinates, in-range distinct corners, non-zero area. `file_face` maps
// triangles to the face numbers the user sees (null: triangle numbers).
void check_mesh_geometry(const Indexed_mesh& mesh, const std::string& source,
                         const std::vector<int>* file_face)
{
  if(mesh.number_of_faces() == 0)
    throw Input_error(source, "", "contains no faces");
  const int n = mesh.number_of_vertices();
  for(int v = 0; v < n; ++v)
    if(!mesh.points.row(v).allFinite()) {
      std::ostringstream c;
      c << mesh.points(v, 0) << ", " << mesh.points(v, 1) << ", " << mesh.points(v, 2);
      throw Input_error(source, vertex_name(v), "non-finite coordinate (" + c.str() + ")");
    }
  // Squared lengths (the bounding box, areas, every energy) must not
  // overflow: a coordinate beyond 1e150 in magnitude is refused rather than
  // turned into infinities downstream.
  for(int v = 0; v < n; ++v) {
    Eigen::Index axis;
    const double largest = mesh.points.row(v).cwiseAbs().maxCoeff(&axis);
    if(largest > max_coordinate_magnitude) {
      std::ostringstream c;
      c << mesh.points(v, axis);
      throw Input_error(source, vertex_name(v), "coordinate " + c.str() +
                                                  " is too large (beyond 1e150 in magnitude, squared lengths "
                                                  "would overflow)");
    }
  }
  const double diagonal = internal::bounding_box_diagonal(mesh.points);
  // Twice the area of a triangle counted as flat: 1e-14 of the squared
  // bounding-box diagonal, far below any modelled feature yet above rounding.
  // Edges are measured in diagonals, so that the test holds at any scale
  // (squares of coordinates near 1e-160 would underflow to zero).
  const double flat_cross_norm = 2e-14;

  for(int t = 0; t < mesh.number_of_faces(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    const std::string element = face_name(file_face ? (*file_face)[t] : t);
    const std::string corners = std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " +
                                std::to_string(tri[2]);
    for(int c = 0; c < 3; ++c)
      if(tri[c] < 0 || tri[c] >= n)
        throw Input_error(source, element, "vertex index " + std::to_string(tri[c]) +
                                             " is out of range (the mesh has " + std::to_string(n) +
                                             " vertices)");
    if(tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw Input_error(source, element, "degenerate triangle (vertices " + corners + ")");
    const Eigen::Vector3d a = mesh.points.row(tri[0]), b = mesh.points.row(tri[1]),
                          c = mesh.points.row(tri[2]);
    if(diagonal == 0. || ((b - a) / diagonal).cross((c - a) / diagonal).norm() <= flat_cross_norm)
      throw Input_error(source, element, "degenerate triangle (zero area, vertices " + corners + ")");
  }
}

Mesh_file mesh_from_polygons(const std::string& path, const std::vector<Point_3>& points,
                             const std::vector<Bounded_polygon>& polygons, bool one_based_indices)
{
  if(polygons.empty())
    throw Input_error(path, "", "contains no faces");
  if(points.size() > std::size_t(std::numeric_limits<int>::max())
     || polygons.size() > std::size_t(std::numeric_limits<int>::max()))
    throw Input_error(path, "", "too many vertices or faces for this library (more than 2^31)");

  Mesh_file r;
  const std::size_t n = points.size();
  r.mesh.points.resize(Eigen::Index(n), 3);
  for(std::size_t v = 0; v < n; ++v)
    r.mesh.points.row(Eigen::Index(v)) << points[v].x(), points[v].y(), points[v].z();
  r.number_of_file_faces = int(polygons.size());

  int fanned = 0, first_fanned = -1;
  std::vector<char> used(n, 0);
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    const Bounded_polygon& p = polygons[f];
    const std::string element = face_name(int(f));
    if(p.size() < 3)
      throw Input_error(path, element, "has " + std::to_string(p.size()) +
                                         " corners (a face needs at least 3)");
    for(std::size_t id : p)
      if(id >= n)
        throw Input_error(path, element, "vertex index " +
                                           std::to_string(one_based_indices ? id + 1 : id) +
                                           " is out of range (the file has " + std::to_string(n) +
                                           " vertices)");
    if(p.size() > 3 && fanned++ == 0) first_fanned = int(f);
    for(std::size_t c = 1; c + 1 < p.size(); ++c) {
      r.mesh.triangles.push_back({int(p[0]), int(p[c]), int(p[c + 1])});
      r.file_face.push_back(int(f));
    }
    for(std::size_t id : p) used[id] = 1;
  }
  check_mesh_geometry(r.mesh, path, &r.file_face);

  if(fanned > 0)
    r.warnings.push_back(path + ": " + std::to_string(fanned) + " polygon" + (fanned > 1 ? "s" : "") +
                         " with more than 3 corners " + (fanned > 1 ? "were" : "was") +
                         " fan-triangulated (first: face " + std::to_string(first_fanned) + ")");
  // Faces over the same three vertices (in any order): kept, but a mesh
  // with them is not manifold, and the user should know.
  std::map<std::array<int, 3>, int> file_face_of;
  int repeated = 0, first_repeat = -1, first_original = -1;
  for(std::size_t k = 0; k < r.mesh.triangles.size(); ++k) {
    std::array<int, 3> key = r.mesh.triangles[k];
    std::sort(key.begin(), key.end());
    const auto [it, added] = file_face_of.emplace(key, r.file_face[k]);
    if(!added && repeated++ == 0) {
      first_repeat = r.file_face[k];
      first_original = it->second;
    }
  }
  if(repeated > 0)
    r.warnings.push_back(path + ": " + std::to_string(repeated) + " face" + (repeated > 1 ? "s repeat" : " repeats") +
                         " the vertices of another (first: face " + std::to_string(first_repeat) + " repeats face " +
                         std::to_string(first_original) + "); kept");
  const std::size_t unused = std::size_t(std::count(used.begin(), used.end(), 0));
  if(unused > 0) {
    const std::size_t first = std::size_t(std::find(used.begin(), used.end(), 0) - used.begin());
    r.warnings.push_back(path + ": " + std::to_string(unused) + " " + (unused > 1 ? "vertices are" : "vertex is") +
                         " not used by any face (first: vertex " + std::to_string(first) +
                         "); kept");
  }
  return r;
}

} // namespace

Mesh_file read_mesh_file(const std::string& path)
{
  internal::check_readable_file(path);
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if(ec || size == 0)
    throw Input_error(path, "", "file is empty");
  const std::string ext = lower_extension(path);
  if(ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl")
    throw Input_error(path, "", "unsupported mesh file extension " + printable(ext.empty() ? "(none)" : ext) +
                                  " (supported: .off, .obj, .ply, .stl)");
  if(ext == ".off")
    check_off_counts_fit(path, size);
  std::string trailing_text;
  if(ext == ".off")
    trailing_text = check_off_lines(path);
  if(ext == ".ply")
    check_ply_header(path, size);
  // CGAL reads the OBJ index 0 (invalid: indices start at 1) as another
  // vertex, and the error then names the wrong one.
  if(ext == ".obj")
    diagnose_obj(path, internal::read_file(path));

  std::vector<Point_3> points;
  std::vector<Bounded_polygon> polygons;
  Bounded_polygon::corner_limit = std::size_t(size / 2);
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
  } catch(const Corner_limit_exceeded&) {
    throw Input_error(path, "", "a face announces more corners than the file can hold (corrupt file)");
  } catch(const std::length_error&) {
    // CGAL's PLY reader sizes a list from a (possibly negative) count it read.
    throw Input_error(path, "", "cannot be read as " + ext.substr(1) + " (a list size is negative or absurd: corrupt file)");
  }
  if(!ok) {
    if(ext == ".off") diagnose_off(path, internal::read_file(path));
    throw Input_error(path, "", "cannot be read as " + ext.substr(1) + " (malformed or truncated file)");
  }
  if(polygons.empty() && ext == ".stl") // CGAL reads a cut or foreign STL file as one without facets
    throw Input_error(path, "", "contains no faces (an empty, truncated or non-STL file)");
  Mesh_file file = mesh_from_polygons(path, points, polygons, ext == ".obj");
  if(!trailing_text.empty()) file.warnings.push_back(trailing_text);
  return file;
}

std::vector<int> read_seg_file(const std::string& path)
{
  const std::string text = internal::read_file(path);
  Text_scanner s(text);
  s.disable_comments();
  std::vector<int> labels;
  Token t;
  while(s.next(t)) {
    const std::string element = "line " + std::to_string(t.line);
    long long value;
    const bool integer = parse_integer(t.text, value);
    if(!integer) {
      const bool digits = !t.text.empty() &&
        std::all_of(t.text.begin() + (t.text[0] == '-' || t.text[0] == '+'), t.text.end(),
                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
      throw Input_error(path, element, printable(t.text) + (digits ? " is too large for a label"
                                                                : " is not an integer label"));
    }
    if(value < 0)
      throw Input_error(path, element, "negative label " + std::to_string(value));
    if(value > std::numeric_limits<int>::max())
      throw Input_error(path, element, printable(t.text) + " is too large for a label");
    labels.push_back(int(value));
  }
  if(labels.empty())
    throw Input_error(path, "", "is empty (expected one label per face)");
  return labels;
}

// A soup need not be a valid Surface_mesh (a fin on an edge, a bowtie), so
// CGAL's face-graph connected_components() does not apply to it: the faces
// sharing an edge are joined in Boost's union-find instead.
std::vector<int> connected_component_labels(const Indexed_mesh& mesh)
{
  const int nf = mesh.number_of_faces();
  boost::disjoint_sets_with_storage<> components(static_cast<std::size_t>(nf));
  std::unordered_map<std::uint64_t, int> face_of_edge;
  face_of_edge.reserve(std::size_t(nf) * 2);
  for(int f = 0; f < nf; ++f)
    for(int c = 0; c < 3; ++c) {
      const std::uint32_t a = std::uint32_t(mesh.triangles[f][c]), b = std::uint32_t(mesh.triangles[f][(c + 1) % 3]);
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      const auto inserted = face_of_edge.emplace(key, f);
      if(!inserted.second) components.union_set(f, inserted.first->second);
    }
  std::vector<int> labels(std::size_t(nf), -1), label_of_root(std::size_t(nf), -1);
  int next = 0;
  for(int f = 0; f < nf; ++f) {
    int& l = label_of_root[std::size_t(components.find_set(f))];
    if(l < 0) l = next++;
    labels[f] = l;
  }
  return labels;
}

Labeled_mesh read_labeled_mesh(const std::string& mesh_path, const std::string& labels,
                               std::vector<std::string>* warnings)
{
  Mesh_file file = read_mesh_file(mesh_path);
  if(warnings) warnings->insert(warnings->end(), file.warnings.begin(), file.warnings.end());

  Labeled_mesh r;
  r.source = mesh_path;
  if(labels == "components") {
    r.face_labels = connected_component_labels(file.mesh);
  } else {
    const std::string property_prefix = "property:";
    const bool from_property = labels.rfind(property_prefix, 0) == 0;
    const std::vector<int> per_file_face = from_property
      ? read_ply_face_property(mesh_path, labels.substr(property_prefix.size()))
      : read_seg_file(labels);
    if(per_file_face.size() != std::size_t(file.number_of_file_faces))
      throw Input_error(from_property ? mesh_path : labels, "",
                        "has " + std::to_string(per_file_face.size()) + " labels but " + mesh_path +
                          " has " + std::to_string(file.number_of_file_faces) + " faces");
    r.face_labels.reserve(file.file_face.size());
    for(int f : file.file_face) r.face_labels.push_back(per_file_face[std::size_t(f)]);
  }
  r.mesh = std::move(file.mesh);
  return r;
}

void write_mesh_file(const Indexed_mesh& mesh, const std::string& path,
                     const Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>* face_colors,
                     const Mesh_write_options& options)
{
  const std::string ext = lower_extension(path);
  if(ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl")
    throw Input_error(path, "", "unsupported extension " + printable(ext.empty() ? "(none)" : ext) +
                                  " for writing a mesh (supported: .off, .obj, .ply, .stl)");
  if(face_colors && face_colors->rows() != mesh.number_of_faces())
    throw Input_error(path, "", std::to_string(face_colors->rows()) + " face colours for " +
                                  std::to_string(mesh.number_of_faces()) + " faces");
  const bool colors = face_colors && ext == ".ply";
  if(ext == ".stl")
    return internal::write_file_atomically(
      path, [&](std::ostream& out) { internal::write_stl(out, mesh, options.binary); }, options.binary);
  if(ext == ".ply" && options.binary)
    return internal::write_file_atomically(
      path, [&](std::ostream& out) { internal::write_binary_ply(out, mesh, colors ? face_colors : nullptr); }, true);

  internal::write_file_atomically(path, [&](std::ostream& out) {
    // 17 significant digits make every double read back exactly.
    out << std::setprecision(17);
    const int nv = mesh.number_of_vertices(), nf = mesh.number_of_faces();
    if(ext == ".off") {
      out << "OFF\n" << nv << ' ' << nf << " 0\n";
    } else if(ext == ".ply") {
      out << "ply\nformat ascii 1.0\ncomment written by CGAL-MPM\n"
          << "element vertex " << nv << "\nproperty double x\nproperty double y\nproperty double z\n"
          << "element face " << nf << "\nproperty list uchar int vertex_indices\n";
      if(colors) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
      out << "end_header\n";
    }
    for(int v = 0; v < nv; ++v)
      out << (ext == ".obj" ? "v " : "") << mesh.points(v, 0) << ' ' << mesh.points(v, 1) << ' '
          << mesh.points(v, 2) << '\n';
    for(int f = 0; f < nf; ++f) {
      const Triangle& t = mesh.triangles[f];
      if(ext == ".obj")
        out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
      else
        out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2];
      if(colors)
        out << ' ' << int((*face_colors)(f, 0)) << ' ' << int((*face_colors)(f, 1)) << ' '
            << int((*face_colors)(f, 2));
      if(ext != ".obj") out << '\n';
    }
  });
}

void write_seg_file(const std::vector<int>& labels, const std::string& path)
{
  internal::write_file_atomically(path, [&](std::ostream& out) {
    for(int l : labels) out << l << '\n';
  });
}

void validate_labeled_mesh(const Labeled_mesh& mesh)
{
  check_mesh_geometry(mesh.mesh, mesh.source, nullptr);
  if(mesh.face_labels.size() != std::size_t(mesh.mesh.number_of_faces()))
    throw Input_error(mesh.source, "", "has " + std::to_string(mesh.face_labels.size()) +
                                         " face labels for " + std::to_string(mesh.mesh.number_of_faces()) +
                                         " faces");
  for(std::size_t f = 0; f < mesh.face_labels.size(); ++f)
    if(mesh.face_labels[f] < 0)
      throw Input_error(mesh.source, face_name(int(f)), "negative label " + std::to_string(mesh.face_labels[f]));
}

} // namespace MPM
} // namespace CGAL
