// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_SYNTHETIC_BUILDERS_H
#define CGAL_MPM_INTERNAL_SYNTHETIC_BUILDERS_H

// Shared machinery of the synthetic model generators (not part of the API).

#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

/// Uniform random numbers that are bit-identical on every platform: the
/// standard distributions are implementation-defined, the engines are not.
class Synthetic_random
{
public:
  explicit Synthetic_random(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi)
  {
    return lo + (hi - lo) * static_cast<double>(engine_() >> 11) * 0x1.0p-53;
  }

private:
  std::mt19937_64 engine_;
};

/// The latent stream of a model: the training model draws from `seed`, a
/// held-out pose from `pose_seed` (salted so that the two never coincide).
Synthetic_random latent_stream(Synthetic_family family, const Synthetic_options& options);

/// Subtracts the column means from `latents` (instances x parameters) for a
/// training model, so the true mean shape is the mean of the instances; a
/// held-out pose keeps its draws.
void center_latents(Eigen::MatrixXd& latents, const Synthetic_options& options);

/// Row `i` of `m` as a vector (the latent parameters of instance `i`).
inline std::vector<double> matrix_row(const Eigen::MatrixXd& m, Eigen::Index i)
{
  std::vector<double> row(static_cast<std::size_t>(m.cols()));
  for(Eigen::Index k = 0; k < m.cols(); ++k)
    row[static_cast<std::size_t>(k)] = m(i, k);
  return row;
}

/// Accumulates the mesh, labels and ground truth of a synthetic model. Each
/// part's faces are added in one call, in its type's template order, so the
/// first-appearance numbering of its vertices is the true correspondence.
class Model_builder
{
public:
  /// Appends a vertex and returns its index.
  int add_vertex(const Eigen::Vector3d& p);
  /// Moves an existing vertex.
  void set_vertex(int v, const Eigen::Vector3d& p) { points_[v] = p; }
  /// Number of vertices so far.
  int number_of_vertices() const { return static_cast<int>(points_.size()); }
  /// Declares a part type with its number of latent modes.
  void add_type(const std::string& name, int modes, bool linear);
  /// Adds a part instance of a declared type from its faces (mesh vertex
  /// indices, template order); returns its label.
  int add_part(const std::string& type, const std::vector<Triangle>& faces,
               const std::vector<double>& latent);
  /// Records a docking between two labels.
  void add_connection(int first, int second, bool boundary);
  /// Finishes the model: mesh, labels, annotation and ground truth.
  Synthetic_model finish(Synthetic_family family, const Synthetic_options& options,
                         double docking_radius, int expected_rules) const;

private:
  std::vector<Eigen::Vector3d> points_;
  std::vector<Triangle> triangles_;
  std::vector<int> labels_;
  std::vector<Synthetic_type> types_;
  std::vector<Synthetic_instance> instances_;
  std::vector<Synthetic_connection> connections_;
};

/// Flips `faces` when the closed surface they bound over `points` has
/// negative signed volume, so that its normals point outward.
void orient_outward(std::vector<Triangle>& faces, const std::vector<Eigen::Vector3d>& points);

/// A chain of tube segments growing out of a hole of a rounded box: fingers
/// of a palm, legs of a spider body.
struct Limb_segment_type
{
  std::string name;          ///< part type name
  double length = 1.;        ///< mean length along the axis, in tube radii
  double length_spread = 0.; ///< half-width of the uniform length variation, in tube radii
  double bulge = 0.;         ///< mean radial bulge in the middle of the segment (fraction of the radius)
  double bulge_spread = 0.;  ///< half-width of the bulge variation
  double end_bend = 0.;      ///< mean bend (radians) of the joint at its far end
  double end_bend_spread = 0.; ///< half-width of the bend variation
};

/// A hole in one face of the box: the outward normal is lattice axis
/// `normal_axis` with sign `normal_sign`; the tube's bending axis is lattice
/// axis `bend_axis` with sign `bend_sign`; `center` in lattice units.
struct Limb_hole
{
  int normal_axis = 0;
  int normal_sign = 1;
  int bend_axis = 1;
  int bend_sign = 1;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
};

/// A rounded box of `cells` lattice cells with square holes of `hole_cells`
/// cells per side, each continued by the same chain of tube segments (the
/// last one capped). The tube radius is 1 and the lattice step
/// 2 / hole_cells, so the hole's inscribed circle is the tube's first ring.
struct Limbed_model_spec
{
  std::string body_name;                 ///< part type of the box
  Eigen::Vector3i cells = Eigen::Vector3i::Ones(); ///< box size in lattice cells
  int hole_cells = 4;                    ///< cells per hole side (ring of 4 hole_cells vertices)
  int blend_cells = 1;                   ///< cells over which a square rim turns into a circle
  int corner_cells = 1;                  ///< rounding radius of the box edges, in cells
  std::vector<Limb_hole> holes;          ///< one limb per hole
  std::vector<Limb_segment_type> chain;  ///< segment types from the body outward
  double ring_density = 1.;              ///< scales the number of rings per segment

  /// Cells that keep a rim off the rounding of the box's edges.
  int border() const { return blend_cells + corner_cells; }
  /// Cells that keep the blends of two neighbouring rims apart.
  int gap() const { return 2 * blend_cells; }
};

/// A spec of `m` cells per hole side, its rims blended and the box's edges
/// rounded over a sixth of that (at least one cell), with no holes yet.
Limbed_model_spec limbed_model_spec(const std::string& body_name, int m, double ring_density);

/// Vertex count of `make_limbed_model(spec, ...)` without building it.
int limbed_model_vertex_count(const Limbed_model_spec& spec);

/// The spec `spec_of(cells, ring_density)` whose vertex count is nearest to
/// `target`, over a grid of resolutions (a mild preference for unit density).
Limbed_model_spec limbed_spec_for_vertex_count(int target,
                                               const std::function<Limbed_model_spec(int, double)>& spec_of);

/// Builds a limbed model. Types: the body (single instance) and one type per
/// chain position. Latents per segment: length, bulge, then the bend of its
/// near joint (not for the first segment) and of its far joint (not for the
/// last one); a joint's bend is shared by the two segments it joins.
Synthetic_model make_limbed_model(const Limbed_model_spec& spec, Synthetic_family family,
                                  const Synthetic_options& options);

/// The generators of the families.
Synthetic_model make_hexa_grid(const Synthetic_options& options);
Synthetic_model make_facade(const Synthetic_options& options);
Synthetic_model make_hand(const Synthetic_options& options);
Synthetic_model make_spider(const Synthetic_options& options);
Synthetic_model make_spine(const Synthetic_options& options);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
