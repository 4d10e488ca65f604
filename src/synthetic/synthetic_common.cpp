// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Synthetic_builders.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <unordered_map>

namespace CGAL {
namespace MPM {
namespace internal {

Synthetic_random latent_stream(Synthetic_family family, const Synthetic_options& options)
{
  const std::uint64_t family_salt = static_cast<std::uint64_t>(family) + 1;
  if(options.held_out_pose)
    return Synthetic_random(0x9E3779B97F4A7C15ull * (options.pose_seed + 1) + 0xD1B54A32D192ED03ull * family_salt + 7);
  return Synthetic_random(0xBF58476D1CE4E5B9ull * (options.seed + 1) + 0x94D049BB133111EBull * family_salt);
}

void center_latents(Eigen::MatrixXd& latents, const Synthetic_options& options)
{
  if(options.held_out_pose || latents.rows() == 0)
    return;
  latents.rowwise() -= latents.colwise().mean();
}

int Model_builder::add_vertex(const Eigen::Vector3d& p)
{
  points_.push_back(p);
  return static_cast<int>(points_.size()) - 1;
}

void Model_builder::add_type(const std::string& name, int modes, bool linear)
{
  Synthetic_type t;
  t.name = name;
  t.modes = modes;
  t.linear = linear;
  types_.push_back(t);
}

int Model_builder::add_part(const std::string& type, const std::vector<Triangle>& faces,
                            const std::vector<double>& latent)
{
  const int label = static_cast<int>(instances_.size());
  Synthetic_instance instance;
  instance.label = label;
  instance.type = type;
  instance.latent = latent;
  std::unordered_map<int, int> local;
  local.reserve(faces.size());
  for(const Triangle& f : faces)
  {
    for(int v : f)
      if(local.emplace(v, static_cast<int>(instance.vertices.size())).second)
        instance.vertices.push_back(v);
    triangles_.push_back(f);
    labels_.push_back(label);
  }
  instances_.push_back(std::move(instance));
  return label;
}

void Model_builder::add_connection(int first, int second, bool boundary)
{
  Synthetic_connection c;
  c.first = first;
  c.second = second;
  c.boundary = boundary;
  connections_.push_back(c);
}

Synthetic_model Model_builder::finish(Synthetic_family family, const Synthetic_options& options,
                                      double docking_radius, int expected_rules) const
{
  Synthetic_model model;
  model.family = family;
  model.options = options;
  model.mesh.mesh.points.resize(static_cast<Eigen::Index>(points_.size()), 3);
  for(std::size_t i = 0; i < points_.size(); ++i)
    model.mesh.mesh.points.row(static_cast<Eigen::Index>(i)) = points_[i].transpose();
  model.mesh.mesh.triangles = triangles_;
  model.mesh.face_labels = labels_;
  model.mesh.source = "synthetic " + family_name(family);
  for(const Synthetic_instance& instance : instances_)
    model.annotation.part_type_of_label[instance.label] = instance.type;
  model.annotation.parameters.docking_radius = docking_radius;
  model.annotation.parameters.explained_variance = 0.99;
  model.annotation.source = model.mesh.source;
  model.types = types_;
  model.instances = instances_;
  model.connections = connections_;
  model.expected_rules = expected_rules;
  return model;
}

void orient_outward(std::vector<Triangle>& faces, const std::vector<Eigen::Vector3d>& points)
{
  double volume = 0.;
  for(const Triangle& f : faces)
    volume += points[f[0]].dot(points[f[1]].cross(points[f[2]]));
  if(volume < 0.)
    for(Triangle& f : faces)
      std::swap(f[1], f[2]);
}

} // namespace internal

Point_matrix Synthetic_model::draw_pose(unsigned pose_seed) const
{
  Synthetic_options pose = options;
  pose.held_out_pose = true;
  pose.pose_seed = pose_seed;
  return make_synthetic_model(family, pose).mesh.mesh.points;
}

Synthetic_model make_synthetic_model(Synthetic_family family, const Synthetic_options& options)
{
  if(options.vertices < 0)
    throw Input_error("", "synthetic " + family_name(family), "negative vertex count " + std::to_string(options.vertices));
  switch(family)
  {
  case Synthetic_family::hexa_grid: return internal::make_hexa_grid(options);
  case Synthetic_family::facade: return internal::make_facade(options);
  case Synthetic_family::hand: return internal::make_hand(options);
  case Synthetic_family::spider: return internal::make_spider(options);
  case Synthetic_family::spine: return internal::make_spine(options);
  }
  throw Input_error("", "", "unknown synthetic family");
}

std::string family_name(Synthetic_family family)
{
  switch(family)
  {
  case Synthetic_family::hexa_grid: return "hexa-grid";
  case Synthetic_family::facade: return "facade";
  case Synthetic_family::hand: return "hand";
  case Synthetic_family::spider: return "spider";
  case Synthetic_family::spine: return "spine";
  }
  return "unknown";
}

std::vector<Synthetic_family> all_synthetic_families()
{
  return {Synthetic_family::hexa_grid, Synthetic_family::facade, Synthetic_family::hand,
          Synthetic_family::spider, Synthetic_family::spine};
}

Synthetic_family parse_family(const std::string& name)
{
  std::string valid;
  for(Synthetic_family f : all_synthetic_families())
  {
    if(family_name(f) == name)
      return f;
    valid += (valid.empty() ? "" : ", ") + family_name(f);
  }
  throw Input_error("", "synthetic family \"" + name + "\"", "unknown family (valid: " + valid + ")");
}

} // namespace MPM
} // namespace CGAL
