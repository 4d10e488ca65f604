// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Baselines/Deformation_method.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Editing/Laplacian_editing.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Baselines/Shape_space_fit.h>
#include <CGAL/MPM/Correspondence/Thin_plate_spline.h>
#include <CGAL/MPM/internal/Vertex_components.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace CGAL {
namespace MPM {

namespace {

class Mpm_method final : public Deformation_method
{
public:
  Mpm_method(const Morphable_part_model& model, int example, const Embedding_options& options)
    : solver_(make_deformation_problem(model, example), options), n_(static_cast<int>(model.examples[std::size_t(example)].mesh.number_of_vertices()))
  {}
  std::string name() const override { return "mpm"; }
  void set_handles(const Handle_set& handles) override
  {
    validate_handles(handles, n_, "handle set");
    if(handles.size() == 0) throw Input_error("handle set", "", "no handles");
    solver_.set_handles(handles.vertices, handles.targets);
  }
  Point_matrix deform() override
  {
    solver_.reset();
    iterations_ = solver_.solve().iterations;
    return solver_.positions();
  }
  int iterations() const override { return iterations_; }

private:
  Embedding_solver solver_;
  int n_ = 0;
  int iterations_ = 0;
};

class Arap_method final : public Deformation_method
{
public:
  Arap_method(const Indexed_mesh& mesh, Arap_variant variant, const Deformation_method_options& options)
    : arap_(mesh, variant), variant_(variant), options_(options), rest_(mesh.points)
  {
    // One pin per connected component, for components the handles miss.
    int components = 0;
    component_ = internal::vertex_component_labels(mesh, &components);
    std::vector<Eigen::RowVector3d> centroid(std::size_t(components), Eigen::RowVector3d::Zero());
    std::vector<int> size(std::size_t(components), 0);
    for(std::size_t v = 0; v < component_.size(); ++v)
      if(component_[v] >= 0)
      {
        centroid[std::size_t(component_[v])] += mesh.points.row(Eigen::Index(v));
        ++size[std::size_t(component_[v])];
      }
    pin_.assign(std::size_t(components), -1);
    for(std::size_t v = 0; v < component_.size(); ++v)
    {
      const int c = component_[v];
      if(c < 0) continue;
      const Eigen::RowVector3d centre = centroid[std::size_t(c)] / size[std::size_t(c)];
      const int best = pin_[std::size_t(c)];
      if(best < 0 || (mesh.points.row(Eigen::Index(v)) - centre).squaredNorm() <
                       (mesh.points.row(best) - centre).squaredNorm())
        pin_[std::size_t(c)] = static_cast<int>(v);
    }
  }
  std::string name() const override { return variant_ == Arap_variant::original ? "arap" : "arap-sre"; }
  void set_handles(const Handle_set& handles) override
  {
    validate_handles(handles, static_cast<int>(rest_.rows()), "handle set");
    if(handles.size() == 0) throw Input_error("handle set", "", "no handles");
    std::vector<bool> held(pin_.size(), false);
    for(int v : handles.vertices)
      if(component_[std::size_t(v)] >= 0) held[std::size_t(component_[std::size_t(v)])] = true;
    Handle_set all = handles;
    std::vector<int> extra;
    for(std::size_t c = 0; c < pin_.size(); ++c)
      if(!held[c]) extra.push_back(pin_[c]);
    if(!extra.empty())
    {
      all.targets.conservativeResize(handles.size() + Eigen::Index(extra.size()), 3);
      for(std::size_t i = 0; i < extra.size(); ++i)
      {
        all.vertices.push_back(extra[i]);
        all.targets.row(handles.size() + Eigen::Index(i)) = rest_.row(extra[i]);
      }
    }
    arap_.set_handles(all);
    handles_ = std::move(all);
  }
  Point_matrix deform() override
  {
    // CGAL keeps the targets in the mesh's control vertices, which reset()
    // puts back to rest: set them again (same vertices, no refactoring).
    arap_.reset();
    arap_.set_handles(handles_);
    arap_.preprocess();
    iterations_ = arap_.deform(options_.arap_max_iterations, options_.arap_tolerance, [this](int iteration) {
      internal::throw_if_cancelled(options_.cancel, "ARAP");
      if(options_.iteration_callback) options_.iteration_callback(iteration);
    });
    return arap_.positions();
  }
  int iterations() const override { return iterations_; }

private:
  Arap_deformation arap_;
  Arap_variant variant_;
  Deformation_method_options options_;
  Point_matrix rest_;
  Handle_set handles_; // the user's handles and the pins
  std::vector<int> component_, pin_;
  int iterations_ = 0;
};

class Laplacian_method final : public Deformation_method
{
public:
  Laplacian_method(const Indexed_mesh& mesh, double handle_weight)
    : editing_(mesh, [handle_weight] {
        Laplacian_editing_options o;
        o.handle_weight = handle_weight;
        return o;
      }())
  {}
  std::string name() const override { return "laplacian"; }
  void set_handles(const Handle_set& handles) override { editing_.set_handles(handles); }
  Point_matrix deform() override { return editing_.deform(); }

private:
  Laplacian_editing editing_;
};

class Tps_method final : public Deformation_method
{
public:
  explicit Tps_method(const Indexed_mesh& mesh) : tps_(mesh) {}
  std::string name() const override { return "tps"; }
  void set_handles(const Handle_set& handles) override { tps_.set_handles(handles); }
  Point_matrix deform() override { return tps_.deform(); }

private:
  Thin_plate_spline_deformation tps_;
};

class Pca_method final : public Deformation_method
{
public:
  Pca_method(const Morphable_part_model& model, int example) : fit_(model, example) {}
  std::string name() const override { return "pca"; }
  void set_handles(const Handle_set& handles) override { fit_.set_handles(handles); }
  Point_matrix deform() override
  {
    Point_matrix p = fit_.deform();
    iterations_ = fit_.iterations();
    return p;
  }
  int iterations() const override { return iterations_; }

private:
  Shape_space_fit fit_;
  int iterations_ = 0;
};

} // namespace

std::vector<std::string> deformation_method_names() { return {"mpm", "arap", "arap-sre", "laplacian", "tps", "pca"}; }

std::unique_ptr<Deformation_method> make_deformation_method(const std::string& name, const Morphable_part_model& model,
                                                            int example, const Deformation_method_options& options)
{
  if(example < 0 || example >= static_cast<int>(model.examples.size()))
    throw Input_error("model", "example " + std::to_string(example),
                      "does not exist (the model has " + std::to_string(model.examples.size()) + " examples)");
  const Indexed_mesh mesh = to_labeled_mesh(model.examples[std::size_t(example)]).mesh;
  if(name == "mpm")
  {
    Embedding_options mpm = options.mpm;
    if(mpm.cancel == nullptr) mpm.cancel = options.cancel;
    if(!mpm.iteration_callback && options.iteration_callback)
      mpm.iteration_callback = [callback = options.iteration_callback](int iteration, double) { callback(iteration); };
    return std::make_unique<Mpm_method>(model, example, mpm);
  }
  if(name == "arap") return std::make_unique<Arap_method>(mesh, Arap_variant::original, options);
  if(name == "arap-sre") return std::make_unique<Arap_method>(mesh, Arap_variant::smooth_rotation_enhanced, options);
  if(name == "laplacian") return std::make_unique<Laplacian_method>(mesh, options.mpm.handle_weight);
  if(name == "tps") return std::make_unique<Tps_method>(mesh);
  if(name == "pca") return std::make_unique<Pca_method>(model, example);
  std::string valid;
  for(const std::string& n : deformation_method_names()) valid += (valid.empty() ? "" : ", ") + n;
  throw Input_error("deformation method", "'" + name + "'", "is unknown (valid: " + valid + ")");
}

double handle_rms_residual(const Point_matrix& positions, const Handle_set& handles)
{
  if(handles.size() == 0) return 0.;
  double sum = 0.;
  for(int h = 0; h < handles.size(); ++h)
    sum += (positions.row(handles.vertices[std::size_t(h)]) - handles.targets.row(h)).squaredNorm();
  return std::sqrt(sum / handles.size());
}

} // namespace MPM
} // namespace CGAL
