// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Synthetic_builders.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

constexpr int vertebrae = 18;
constexpr int vertebra_modes = 4; // width, depth, height, waist
constexpr double pitch = 1.0;     // distance of consecutive centres along the curve
constexpr double mean_width = 0.7, mean_depth = 0.5, mean_height = 0.3; // half axes
// Consecutive vertebrae are pitch - 2 * (half height +- 0.03) - tilt, about
// 0.3 to 0.45 apart, the next but one at least ~1.3: the radius lies
// between, and catches only the facing ends.
constexpr double docking_radius = 0.6;

struct Spine_resolution
{
  int longitudes = 4; // multiple of 4, so the template is mirror-symmetric in x and y
  int latitudes = 1;  // rings between the poles
};

long spine_vertex_count(const Spine_resolution& r)
{
  return long(vertebrae) * (long(r.longitudes) * r.latitudes + 2);
}

Spine_resolution spine_resolution(int target)
{
  // Rings about as far apart as longitudes: latitudes ~ longitudes / 2.
  Spine_resolution best;
  long best_error = -1;
  for(int q = 1; q < 200; ++q)
    for(int rings = std::max(1, q); rings <= 3 * q; ++rings)
    {
      const Spine_resolution r{4 * q, rings};
      const long error = std::labs(spine_vertex_count(r) - target) + std::labs(rings - 2 * q);
      if(best_error < 0 || error < best_error)
      {
        best = r;
        best_error = error;
      }
    }
  return best;
}

// A profile that makes the vertebral body a rounded cylinder: |t|^(1/2) with sign.
double rounded(double t) { return std::copysign(std::sqrt(std::abs(t)), t); }

} // namespace

// 18 closed vertebrae (type "vertebra") along an S-curve in the (y, z) plane,
// each placed by a rigid motion (centre on the curve, axis along its
// tangent). A vertebra is a rounded cylinder sampled by longitudes and
// latitudes, unit point (u, v, w), scaled to
//   (u (A + c w^2), v (B + c w^2), w C),
// linear in the width A, depth B, height C and waist c. The template is
// mirror-symmetric in x, y and z and each mode moves a coordinate by a
// function odd in it and even in the others, so the modes are orthogonal
// to infinitesimal rigid motions. Consecutive vertebrae dock (generalized).
Synthetic_model make_spine(const Synthetic_options& options)
{
  const int target = options.vertices > 0 ? options.vertices : 16254;
  const Spine_resolution res = spine_resolution(target);
  const double pi = std::acos(-1.);

  // Template: latitude rings (south to north), then the two poles.
  std::vector<Eigen::Vector3d> unit;
  for(int j = 0; j < res.latitudes; ++j)
  {
    const double phi = pi * ((2. * (j + 1)) - (res.latitudes + 1)) / (2. * (res.latitudes + 1));
    for(int i = 0; i < res.longitudes; ++i)
    {
      const double theta = 2. * pi * i / res.longitudes;
      const double r = rounded(std::cos(phi));
      unit.emplace_back(r * std::cos(theta), r * std::sin(theta), rounded(std::sin(phi)));
    }
  }
  const int south = static_cast<int>(unit.size()), north = south + 1;
  unit.emplace_back(0., 0., -1.);
  unit.emplace_back(0., 0., 1.);
  std::vector<Triangle> faces;
  const int nl = res.longitudes;
  for(int i = 0; i < nl; ++i)
    faces.push_back({south, (i + 1) % nl, i});
  for(int j = 0; j + 1 < res.latitudes; ++j)
    for(int i = 0; i < nl; ++i)
    {
      const int a = j * nl + i, b = j * nl + (i + 1) % nl;
      faces.push_back({a, b, b + nl});
      faces.push_back({a, b + nl, a + nl});
    }
  for(int i = 0; i < nl; ++i)
    faces.push_back({(res.latitudes - 1) * nl + i, (res.latitudes - 1) * nl + (i + 1) % nl, north});
  auto vertebra_point = [](const Eigen::Vector3d& u, double a, double b, double c, double waist) {
    const double w2 = u.z() * u.z();
    return Eigen::Vector3d(u.x() * (a + waist * w2), u.y() * (b + waist * w2), u.z() * c);
  };
  {
    std::vector<Eigen::Vector3d> mean;
    for(const Eigen::Vector3d& u : unit)
      mean.push_back(vertebra_point(u, mean_width, mean_depth, mean_height, 0.));
    orient_outward(faces, mean);
  }

  const double spread[vertebra_modes] = {0.08, 0.06, 0.03, 0.08};
  Synthetic_random random = latent_stream(Synthetic_family::spine, options);
  Eigen::MatrixXd latents(vertebrae, vertebra_modes);
  for(int v = 0; v < vertebrae; ++v)
    for(int m = 0; m < vertebra_modes; ++m)
      latents(v, m) = random.uniform(-spread[m], spread[m]);
  center_latents(latents, options);

  Model_builder builder;
  builder.add_type("vertebra", vertebra_modes, true);
  int previous = -1;
  for(int v = 0; v < vertebrae; ++v)
  {
    // S-curve z -> (0, 0.6 sin(z / 3), z): tangent angles stay below ~12
    // degrees, so the tilt between neighbours is a few degrees.
    const double z = pitch * (v - 0.5 * (vertebrae - 1));
    const Eigen::Vector3d center(0., 0.6 * std::sin(z / 3.), z);
    const double slope = 0.2 * std::cos(z / 3.);
    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(-std::atan(slope), Eigen::Vector3d::UnitX()).toRotationMatrix();
    const int base = builder.number_of_vertices();
    for(const Eigen::Vector3d& u : unit)
      builder.add_vertex(center + rotation * vertebra_point(u, mean_width + latents(v, 0), mean_depth + latents(v, 1),
                                                            mean_height + latents(v, 2), latents(v, 3)));
    std::vector<Triangle> part = faces;
    for(Triangle& f : part)
      for(int& i : f)
        i += base;
    const int label = builder.add_part("vertebra", part, matrix_row(latents, v));
    if(previous >= 0)
      builder.add_connection(previous, label, false);
    previous = label;
  }

  // Rules: every docking joins the top of one vertebra to the bottom of the
  // next: one pair of sites, one rule.
  return builder.finish(Synthetic_family::spine, options, docking_radius, 1);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
