// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Mesh_encoding.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <cstring>
#include <iomanip>
#include <ostream>
#include <string>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// Little-endian bytes whatever the host's order.
template <class T>
void put_little_endian(std::ostream& out, T value)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const std::uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  if(first == 0) // big-endian host
    for(std::size_t k = 0; k < sizeof(T) / 2; ++k) std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
  out.write(reinterpret_cast<const char*>(bytes), sizeof(T));
}

Eigen::Vector3d unit_normal(const Indexed_mesh& mesh, const Triangle& t)
{
  const Eigen::Vector3d a = mesh.points.row(t[0]).transpose(), b = mesh.points.row(t[1]).transpose(),
                        c = mesh.points.row(t[2]).transpose();
  const Eigen::Vector3d n = (b - a).cross(c - a);
  return n.norm() > 0. ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
}

} // namespace

void write_stl(std::ostream& out, const Indexed_mesh& mesh, bool binary)
{
  if(binary)
  {
    std::string header = "binary STL written by CGAL-MPM";
    header.resize(80, ' ');
    out.write(header.data(), 80);
    put_little_endian(out, std::uint32_t(mesh.number_of_faces()));
    for(const Triangle& t : mesh.triangles)
    {
      const Eigen::Vector3d n = unit_normal(mesh, t);
      for(int k = 0; k < 3; ++k) put_little_endian(out, float(n[k]));
      for(int v : t)
        for(int k = 0; k < 3; ++k) put_little_endian(out, float(mesh.points(v, k)));
      put_little_endian(out, std::uint16_t(0));
    }
    return;
  }
  out << std::setprecision(17) << "solid mesh\n";
  for(const Triangle& t : mesh.triangles)
  {
    const Eigen::Vector3d n = unit_normal(mesh, t);
    out << "facet normal " << n[0] << ' ' << n[1] << ' ' << n[2] << "\nouter loop\n";
    for(int v : t) out << "vertex " << mesh.points(v, 0) << ' ' << mesh.points(v, 1) << ' ' << mesh.points(v, 2) << '\n';
    out << "endloop\nendfacet\n";
  }
  out << "endsolid mesh\n";
}

void write_binary_ply(std::ostream& out, const Indexed_mesh& mesh,
                      const Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>* face_colors)
{
  out << "ply\nformat binary_little_endian 1.0\ncomment written by CGAL-MPM\n"
      << "element vertex " << mesh.number_of_vertices() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.number_of_faces() << "\nproperty list uchar int vertex_indices\n";
  if(face_colors) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out << "end_header\n";
  for(int v = 0; v < mesh.number_of_vertices(); ++v)
    for(int k = 0; k < 3; ++k) put_little_endian(out, mesh.points(v, k));
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    put_little_endian(out, std::uint8_t(3));
    for(int v : mesh.triangles[f]) put_little_endian(out, std::int32_t(v));
    if(face_colors)
      for(int k = 0; k < 3; ++k) put_little_endian(out, std::uint8_t((*face_colors)(f, k)));
  }
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
