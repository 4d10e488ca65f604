// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Editing/Arap_deformation.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>
#include <CGAL/MPM/internal/Vertex_components.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <CGAL/Surface_mesh_deformation.h>

#include <algorithm>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {

namespace {

using Mesh = internal::Indexed_surface_mesh;
using Kernel = CGAL::Simple_cartesian<double>;
using vertex_descriptor = Mesh::Vertex_index;

// The variants are distinct class templates; this interface lets one
// non-template wrapper drive whichever was chosen at run time.
class Deformation_interface
{
public:
  virtual ~Deformation_interface() = default;
  virtual void set_region(const std::vector<vertex_descriptor>& roi, const std::vector<vertex_descriptor>& controls) = 0;
  virtual void set_target(vertex_descriptor v, const Kernel::Point_3& target) = 0;
  virtual bool preprocess() = 0;
  virtual void deform_one_iteration() = 0;
  virtual void reset() = 0;
};

template <CGAL::Deformation_algorithm_tag tag>
class Deformation final : public Deformation_interface
{
public:
  explicit Deformation(Mesh& mesh) : deformation_(mesh) {}

  void set_region(const std::vector<vertex_descriptor>& roi, const std::vector<vertex_descriptor>& controls) override
  {
    // Rebuilding the region, not only the controls, drops a former handle on
    // a vertex in no triangle: left in the region it would make the matrix singular.
    deformation_.clear_roi_vertices();
    deformation_.insert_roi_vertices(roi.begin(), roi.end());
    deformation_.insert_control_vertices(controls.begin(), controls.end());
  }
  void set_target(vertex_descriptor v, const Kernel::Point_3& target) override
  {
    deformation_.set_target_position(v, target);
  }
  bool preprocess() override { return deformation_.preprocess(); }
  void deform_one_iteration() override { deformation_.deform(1, 0.); }
  void reset() override { deformation_.reset(); }

private:
  CGAL::Surface_mesh_deformation<Mesh, CGAL::Default, CGAL::Default, tag> deformation_;
};

std::unique_ptr<Deformation_interface> make_deformation(Mesh& mesh, Arap_variant variant)
{
  switch(variant) {
  case Arap_variant::spokes_and_rims: return std::make_unique<Deformation<CGAL::SPOKES_AND_RIMS>>(mesh);
  case Arap_variant::smooth_rotation_enhanced: return std::make_unique<Deformation<CGAL::SRE_ARAP>>(mesh);
  case Arap_variant::original: break;
  }
  return std::make_unique<Deformation<CGAL::ORIGINAL_ARAP>>(mesh);
}

} // namespace

class Arap_deformation::Implementation
{
public:
  Implementation(const Indexed_mesh& input, Arap_variant variant)
    : mesh_(internal::to_surface_mesh(input, "ARAP mesh", "ARAP"))
  {
    component_ = internal::vertex_component_labels(input, &number_of_components_);
    for(vertex_descriptor v : mesh_.vertices())
      if(component_[v] >= 0) surface_vertices_.push_back(v);
    diagonal_ = internal::bounding_box_diagonal(input.points);

    deformation_ = make_deformation(mesh_, variant);
  }

  void set_handles(const Handle_set& handles)
  {
    validate_handles(handles, static_cast<int>(mesh_.number_of_vertices()), "handle set");
    if(handles.size() == 0) throw Input_error("handle set", "", "no handles");
    std::vector<bool> held(std::size_t(number_of_components_), false);
    for(int v : handles.vertices)
      if(component_[std::size_t(v)] >= 0) held[std::size_t(component_[std::size_t(v)])] = true;
    for(std::size_t v = 0; v < component_.size(); ++v)
      if(component_[v] >= 0 && !held[std::size_t(component_[v])])
        throw Input_error("handle set", "connected component of vertex " + std::to_string(v),
                          "has no handle; ARAP cannot place a free piece of the mesh");

    std::vector<vertex_descriptor> controls;
    for(int v : handles.vertices) controls.emplace_back(v);
    std::sort(controls.begin(), controls.end());
    // Same vertices, new targets: keep the factorization (dragging).
    if(controls != controls_) {
      deformation_->set_region(surface_vertices_, controls);
      controls_ = controls;
    }
    for(int i = 0; i < handles.size(); ++i)
      deformation_->set_target(vertex_descriptor(handles.vertices[std::size_t(i)]),
                               Kernel::Point_3(handles.targets(i, 0), handles.targets(i, 1), handles.targets(i, 2)));
  }

  void preprocess()
  {
    if(controls_.empty()) throw Input_error("handle set", "", "no handles; call set_handles() first");
    if(!deformation_->preprocess())
      throw Computation_error("ARAP: factoring the Laplacian of " + std::to_string(mesh_.number_of_vertices()) +
                              " vertices with " + std::to_string(controls_.size()) +
                              " handles failed; degenerate triangles can make it singular");
  }

  int deform(int max_iterations, double tolerance, const std::function<void(int)>& after_iteration)
  {
    preprocess();
    Point_matrix previous = positions();
    for(int iteration = 1; iteration <= max_iterations; ++iteration) {
      deformation_->deform_one_iteration();
      Point_matrix current = positions();
      if(!current.allFinite())
        throw Computation_error("ARAP: non-finite positions after iteration " + std::to_string(iteration) +
                                "; degenerate triangles give infinite cotangent weights");
      if(after_iteration) after_iteration(iteration);
      if(tolerance > 0 && (current - previous).rowwise().norm().maxCoeff() <= tolerance * diagonal_)
        return iteration;
      previous.swap(current);
    }
    return std::max(max_iterations, 0);
  }

  void deform_one_iteration()
  {
    preprocess();
    deformation_->deform_one_iteration();
  }

  Point_matrix positions() const
  {
    Point_matrix p(static_cast<Eigen::Index>(mesh_.number_of_vertices()), 3);
    for(vertex_descriptor v : mesh_.vertices()) {
      const Kernel::Point_3& q = mesh_.point(v);
      p.row(Eigen::Index(v.idx())) << q.x(), q.y(), q.z();
    }
    return p;
  }

  void reset() { deformation_->reset(); }

private:
  Mesh mesh_; // deformation_ refers to it: the Implementation never moves
  std::vector<int> component_; // per vertex: its connected component, -1 when in no triangle
  int number_of_components_ = 0;
  std::vector<vertex_descriptor> surface_vertices_; // the region of interest
  std::vector<vertex_descriptor> controls_;         // sorted handle vertices
  double diagonal_ = 0;
  std::unique_ptr<Deformation_interface> deformation_;
};

Arap_deformation::Arap_deformation(const Indexed_mesh& mesh, Arap_variant variant)
  : implementation_(std::make_unique<Implementation>(mesh, variant))
{}

Arap_deformation::~Arap_deformation() = default;
Arap_deformation::Arap_deformation(Arap_deformation&&) noexcept = default;
Arap_deformation& Arap_deformation::operator=(Arap_deformation&&) noexcept = default;

void Arap_deformation::set_handles(const Handle_set& handles) { implementation_->set_handles(handles); }
void Arap_deformation::preprocess() { implementation_->preprocess(); }
int Arap_deformation::deform(int max_iterations, double tolerance, const std::function<void(int)>& after_iteration)
{
  return implementation_->deform(max_iterations, tolerance, after_iteration);
}
void Arap_deformation::deform_one_iteration() { implementation_->deform_one_iteration(); }
Point_matrix Arap_deformation::positions() const { return implementation_->positions(); }
void Arap_deformation::reset() { implementation_->reset(); }

} // namespace MPM
} // namespace CGAL
