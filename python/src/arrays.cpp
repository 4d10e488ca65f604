// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "arrays.h"

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>

#include <cmath>
#include <cstring>
#include <sstream>

namespace mpm_python {

namespace {

std::string shape_text(const py::array& a)
{
  std::ostringstream s;
  s << "(";
  for(py::ssize_t d = 0; d < a.ndim(); ++d) s << (d ? ", " : "") << a.shape(d);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

std::string describe(const py::array& a)
{
  return "an array of dtype " + py::str(a.dtype()).cast<std::string>() + " and shape " + shape_text(a);
}

// numpy's view of any array-like (a list of lists too); not an array: error.
py::array as_array(const py::handle& object, const std::string& name, const std::string& expected)
{
  py::array a = py::array::ensure(object);
  if(!a) throw py::value_error(name + ": expected " + expected + ", got " + py::repr(object).cast<std::string>());
  return a;
}

bool is_integer(const py::array& a) { return a.dtype().kind() == 'i' || a.dtype().kind() == 'u'; }

void check_rows_of_three(const py::array& a, const std::string& name, const std::string& expected)
{
  if(a.ndim() != 2 || a.shape(1) != 3) throw py::value_error(name + ": expected " + expected + ", got " + describe(a));
}

} // namespace

CGAL::MPM::Point_matrix to_points(const py::handle& object, const std::string& name)
{
  const std::string expected = "a float64 array of shape (n, 3)";
  py::array a = as_array(object, name, expected);
  if(a.dtype().kind() != 'f' && !is_integer(a)) throw py::value_error(name + ": expected " + expected + ", got " + describe(a));
  check_rows_of_three(a, name, expected);
  const auto d = py::array_t<double, py::array::forcecast>::ensure(a);
  const auto r = d.unchecked<2>();
  CGAL::MPM::Point_matrix points(r.shape(0), 3);
  for(py::ssize_t i = 0; i < r.shape(0); ++i)
    for(int k = 0; k < 3; ++k)
    {
      if(!std::isfinite(r(i, k)))
        throw py::value_error(name + ": row " + std::to_string(i) + ": coordinate " + std::to_string(k) +
                              " is not finite (" + py::repr(py::float_(r(i, k))).cast<std::string>() + ")");
      points(i, k) = r(i, k);
    }
  return points;
}

std::vector<CGAL::MPM::Triangle> to_triangles(const py::handle& object, int vertices, const std::string& name)
{
  const std::string expected = "an int32 or int64 array of shape (m, 3)";
  py::array a = as_array(object, name, expected);
  if(!is_integer(a)) throw py::value_error(name + ": expected " + expected + ", got " + describe(a));
  check_rows_of_three(a, name, expected);
  const auto d = py::array_t<long long, py::array::forcecast>::ensure(a);
  const auto r = d.unchecked<2>();
  std::vector<CGAL::MPM::Triangle> triangles(static_cast<std::size_t>(r.shape(0)));
  for(py::ssize_t f = 0; f < r.shape(0); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const long long v = r(f, k);
      if(v < 0 || v >= vertices)
        throw py::value_error(name + ": face " + std::to_string(f) + ": vertex index " + std::to_string(v) +
                              " is out of range [0, " + std::to_string(vertices) + ")");
      triangles[f][k] = static_cast<int>(v);
    }
  return triangles;
}

std::vector<int> to_indices(const py::handle& object, const std::string& name, long expected, int low, int high)
{
  const std::string wanted = "a one-dimensional integer array";
  py::array a = as_array(object, name, wanted);
  // An empty list comes out as float64: there is no element to misread.
  if(a.size() == 0 && a.ndim() == 1) a = py::array_t<int>(0);
  if(!is_integer(a) || a.ndim() != 1) throw py::value_error(name + ": expected " + wanted + ", got " + describe(a));
  if(expected >= 0 && a.shape(0) != expected)
    throw py::value_error(name + ": has " + std::to_string(a.shape(0)) + " entries, expected " +
                          std::to_string(expected));
  const auto d = py::array_t<long long, py::array::forcecast>::ensure(a);
  const auto r = d.unchecked<1>();
  std::vector<int> values(static_cast<std::size_t>(r.shape(0)));
  for(py::ssize_t i = 0; i < r.shape(0); ++i)
  {
    const long long v = r(i);
    if(v < low || (high >= 0 && v >= high) || v > std::numeric_limits<int>::max())
      throw py::value_error(name + ": entry " + std::to_string(i) + ": " + std::to_string(v) + " is out of range [" +
                            std::to_string(low) + ", " + (high >= 0 ? std::to_string(high) : std::string("2^31")) + ")");
    values[i] = static_cast<int>(v);
  }
  return values;
}

CGAL::MPM::Indexed_mesh to_mesh(const py::handle& V, const py::handle& F)
{
  CGAL::MPM::Indexed_mesh mesh;
  mesh.points = to_points(V, "V");
  mesh.triangles = to_triangles(F, mesh.number_of_vertices(), "F");
  return mesh;
}

CGAL::MPM::Labeled_mesh to_labeled_mesh(const py::handle& V, const py::handle& F, const py::handle& labels,
                                        const std::string& source)
{
  CGAL::MPM::Labeled_mesh mesh;
  mesh.mesh = to_mesh(V, F);
  mesh.face_labels = to_indices(labels, "labels", mesh.mesh.number_of_faces());
  mesh.source = source;
  CGAL::MPM::validate_labeled_mesh(mesh);
  return mesh;
}

py::array points_array(CGAL::MPM::Point_matrix&& points)
{
  auto* owned = new CGAL::MPM::Point_matrix(std::move(points));
  py::capsule owner(owned, [](void* p) { delete static_cast<CGAL::MPM::Point_matrix*>(p); });
  const py::ssize_t n = owned->rows();
  // Eigen stores the three columns one after the other.
  return py::array_t<double>({n, py::ssize_t(3)},
                             {py::ssize_t(sizeof(double)), py::ssize_t(sizeof(double)) * n}, owned->data(), owner);
}

py::array triangles_array(std::vector<CGAL::MPM::Triangle>&& triangles)
{
  static_assert(sizeof(CGAL::MPM::Triangle) == 3 * sizeof(int), "a triangle is three packed ints");
  auto* owned = new std::vector<CGAL::MPM::Triangle>(std::move(triangles));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<CGAL::MPM::Triangle>*>(p); });
  return py::array_t<std::int32_t>({py::ssize_t(owned->size()), py::ssize_t(3)},
                                   reinterpret_cast<const std::int32_t*>(owned->data()), owner);
}

py::array int_array(std::vector<int>&& values)
{
  auto* owned = new std::vector<int>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<int>*>(p); });
  return py::array_t<std::int32_t>(py::ssize_t(owned->size()), owned->data(), owner);
}

py::array double_array(const std::vector<double>& values)
{
  return py::array_t<double>(py::ssize_t(values.size()), values.data());
}

py::array matrix_array(const Eigen::MatrixXd& m)
{
  py::array_t<double> a({py::ssize_t(m.rows()), py::ssize_t(m.cols())});
  auto w = a.mutable_unchecked<2>();
  for(Eigen::Index i = 0; i < m.rows(); ++i)
    for(Eigen::Index j = 0; j < m.cols(); ++j) w(i, j) = m(i, j);
  return a;
}

py::array vector_array(const Eigen::VectorXd& v)
{
  return py::array_t<double>(py::ssize_t(v.size()), v.data());
}

} // namespace mpm_python
