// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes, labels and point sets across the Python boundary. Inputs are
// checked here (dtype, shape, finiteness, index range) so that an array
// the library would misread raises `ValueError` naming the argument and the
// element; the library then checks the geometry as it checks files.
// Outputs move the library's buffers into numpy arrays without a copy.
#ifndef CGAL_MPM_PYTHON_ARRAYS_H
#define CGAL_MPM_PYTHON_ARRAYS_H

#include <CGAL/MPM/Indexed_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace mpm_python {

namespace py = pybind11;

/// An n x 3 floating-point (or integer) array (`name` in messages) as
/// finite points.
CGAL::MPM::Point_matrix to_points(const py::handle& array, const std::string& name);

/// An m x 3 integer array of vertex indices in [0, `vertices`).
std::vector<CGAL::MPM::Triangle> to_triangles(const py::handle& array, int vertices, const std::string& name);

/// A one-dimensional integer array (or sequence) of `expected` entries (any
/// length when negative); each in [`low`, `high`) unless `high` < 0.
std::vector<int> to_indices(const py::handle& array, const std::string& name, long expected = -1, int low = 0,
                            int high = -1);

/// `V`, `F` as a mesh.
CGAL::MPM::Indexed_mesh to_mesh(const py::handle& V, const py::handle& F);

/// `V`, `F` and per-face `labels` as a labelled mesh, checked by
/// `validate_labeled_mesh()`.
CGAL::MPM::Labeled_mesh to_labeled_mesh(const py::handle& V, const py::handle& F, const py::handle& labels,
                                        const std::string& source = "mesh");

/// n x 3 float64 array owning `points` (moved, not copied).
py::array points_array(CGAL::MPM::Point_matrix&& points);
/// m x 3 int32 array owning `triangles` (moved, not copied).
py::array triangles_array(std::vector<CGAL::MPM::Triangle>&& triangles);
/// int32 array owning `values` (moved, not copied).
py::array int_array(std::vector<int>&& values);
/// float64 array of `values` (copied).
py::array double_array(const std::vector<double>& values);
/// float64 array of a dense Eigen matrix or vector (copied, C order).
py::array matrix_array(const Eigen::MatrixXd& m);
py::array vector_array(const Eigen::VectorXd& v);

} // namespace mpm_python

#endif
