// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Editing/Laplacian_editing.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/internal/Cotangent_weights.h>
#include <CGAL/MPM/internal/Vertex_components.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace MPM {

Eigen::SparseMatrix<double> cotangent_laplacian(const Indexed_mesh& mesh)
{
  const int n = mesh.number_of_vertices();
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for(int corner : mesh.triangles[f])
      if(corner < 0 || corner >= n)
        throw Input_error("Laplacian", "face " + std::to_string(f),
                          "vertex " + std::to_string(corner) + " is out of range");
  return internal::edge_weight_laplacian(internal::cotangent_weights(mesh.points, mesh.triangles), n);
}

struct Laplacian_editing::Impl
{
  using Sparse = Eigen::SparseMatrix<double>;
  Laplacian_editing_options options;
  Point_matrix rest;
  Sparse normal;              // L^T L
  std::vector<int> component; // per vertex, -1 in no triangle
  int number_of_components = 0;
  double mean_diagonal = 1.;
  Handle_set handles;
  std::vector<int> factored_vertices;
  bool factored = false;
  Eigen::VectorXd diagonal_extra; // handle and anchor weights on the diagonal
  Eigen::SimplicialLDLT<Sparse> solver;
};

Laplacian_editing::Laplacian_editing(const Indexed_mesh& mesh, const Laplacian_editing_options& options)
  : impl_(std::make_unique<Impl>())
{
  if(!mesh.points.allFinite()) throw Input_error("Laplacian editing", "rest positions", "contain non-finite coordinates");
  if(!(options.handle_weight > 0) || !(options.anchor_weight > 0))
    throw Input_error("Laplacian editing", "options", "handle and anchor weights must be positive");
  Impl& d = *impl_;
  d.options = options;
  d.rest = mesh.points;
  const Impl::Sparse L = cotangent_laplacian(mesh);
  d.normal = Impl::Sparse(L.transpose() * L);
  const int n = mesh.number_of_vertices();
  double sum = 0.;
  int count = 0;
  for(int i = 0; i < n; ++i)
    if(d.normal.coeff(i, i) > 0)
    {
      sum += d.normal.coeff(i, i);
      ++count;
    }
  d.mean_diagonal = count > 0 ? sum / count : 1.;
  d.component = internal::vertex_component_labels(mesh, &d.number_of_components);
}

Laplacian_editing::~Laplacian_editing() = default;
Laplacian_editing::Laplacian_editing(Laplacian_editing&&) noexcept = default;
Laplacian_editing& Laplacian_editing::operator=(Laplacian_editing&&) noexcept = default;

void Laplacian_editing::set_handles(const Handle_set& handles)
{
  Impl& d = *impl_;
  const int n = static_cast<int>(d.rest.rows());
  validate_handles(handles, n, "handle set");
  if(handles.size() == 0) throw Input_error("handle set", "", "no handles");
  std::vector<int> sorted = handles.vertices;
  std::sort(sorted.begin(), sorted.end());
  d.handles = handles;
  if(d.factored && sorted == d.factored_vertices) return;

  // Handles, weak anchors on components without handles, and a unit anchor
  // on vertices in no triangle (nothing else holds them).
  Eigen::VectorXd extra = Eigen::VectorXd::Zero(n);
  std::vector<bool> held(std::size_t(d.number_of_components), false);
  for(int v : handles.vertices)
  {
    extra[v] = d.options.handle_weight * d.mean_diagonal;
    if(d.component[std::size_t(v)] >= 0) held[std::size_t(d.component[std::size_t(v)])] = true;
  }
  for(int v = 0; v < n; ++v)
  {
    if(extra[v] > 0) continue;
    const int c = d.component[std::size_t(v)];
    if(c < 0) extra[v] = d.mean_diagonal;
    else if(!held[std::size_t(c)]) extra[v] = d.options.anchor_weight * d.mean_diagonal;
  }
  Impl::Sparse system = d.normal;
  for(int v = 0; v < n; ++v)
    if(extra[v] > 0) system.coeffRef(v, v) += extra[v];
  d.solver.compute(system);
  if(d.solver.info() != Eigen::Success)
  {
    d.factored = false;
    throw Computation_error("Laplacian editing: the factorization of L^T L + handle weights failed");
  }
  d.diagonal_extra = extra;
  d.factored_vertices = sorted;
  d.factored = true;
}

Point_matrix Laplacian_editing::deform() const
{
  const Impl& d = *impl_;
  if(!d.factored) throw Input_error("Laplacian editing", "", "no handles are set");
  // Solved for the displacement from the rest positions: the elastic term
  // and the anchors ask for none, the handles for theirs. (Zero handle
  // displacements give the input back exactly.)
  Point_matrix rhs = Point_matrix::Zero(d.rest.rows(), 3);
  for(int h = 0; h < d.handles.size(); ++h)
  {
    const int v = d.handles.vertices[std::size_t(h)];
    rhs.row(v) = d.diagonal_extra[v] * (d.handles.targets.row(h) - d.rest.row(v));
  }
  Point_matrix result(d.rest.rows(), 3);
  for(int k = 0; k < 3; ++k)
  {
    Eigen::VectorXd column = rhs.col(k);
    result.col(k) = d.rest.col(k) + d.solver.solve(column);
  }
  if(!result.allFinite()) throw Computation_error("Laplacian editing produced non-finite positions");
  return result;
}

} // namespace MPM
} // namespace CGAL
