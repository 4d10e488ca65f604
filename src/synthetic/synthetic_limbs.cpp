// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Synthetic_builders.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

constexpr double cap_height = 0.8; // of the half-ellipsoid closing the last segment

int rings_of(const Limb_segment_type& type, const Limbed_model_spec& spec)
{
  // Rings about as far apart as the ring's vertices (pi / (2 m) for radius 1).
  const double pi = std::acos(-1.);
  return std::max(2, static_cast<int>(std::lround(spec.ring_density * type.length * 2. * spec.hole_cells / pi)));
}

int cap_rings_of(const Limbed_model_spec& spec)
{
  return std::max(1, static_cast<int>(std::lround(0.9 * spec.ring_density * spec.hole_cells)));
}

Eigen::Vector3d axis_vector(int axis, int sign)
{
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  v[axis] = sign;
  return v;
}

// Offsets (u, v) of a hole's rim from its centre in lattice units,
// counter-clockwise about the outward normal in the frame (x', y').
std::vector<Eigen::Vector2d> rim_offsets(int m)
{
  const double h = 0.5 * m;
  std::vector<Eigen::Vector2d> rim;
  for(int side = 0; side < 4; ++side)
    for(int i = 0; i < m; ++i)
    {
      const Eigen::Vector2d p[4] = {{h, -h + i}, {h - i, h}, {-h, h - i}, {-h + i, -h}};
      rim.push_back(p[side]);
    }
  return rim;
}

struct Hole_frame
{
  Eigen::Vector3d normal, x, y; // x: bending axis, y = normal x x
  Eigen::Vector3d center;       // lattice units
  int normal_axis;
  double plane;                 // lattice coordinate of the face along the normal axis
};

} // namespace

Limbed_model_spec limbed_model_spec(const std::string& body_name, int m, double ring_density)
{
  Limbed_model_spec spec;
  spec.body_name = body_name;
  spec.hole_cells = m;
  spec.blend_cells = std::max(1, m / 6);
  spec.corner_cells = std::max(1, m / 6);
  spec.ring_density = ring_density;
  return spec;
}

int limbed_model_vertex_count(const Limbed_model_spec& spec)
{
  const long nx = spec.cells[0], ny = spec.cells[1], nz = spec.cells[2], m = spec.hole_cells;
  long count = (nx + 1) * (ny + 1) * (nz + 1) - (nx - 1) * (ny - 1) * (nz - 1);
  long limb = 4 * m * cap_rings_of(spec) + 1;
  for(const Limb_segment_type& type : spec.chain)
    limb += 4 * m * rings_of(type, spec);
  count += static_cast<long>(spec.holes.size()) * (limb - (m - 1) * (m - 1));
  return static_cast<int>(count);
}

Limbed_model_spec limbed_spec_for_vertex_count(int target,
                                               const std::function<Limbed_model_spec(int, double)>& spec_of)
{
  Limbed_model_spec best;
  double best_score = -1.;
  for(int m = 2; m <= 64; ++m)
    for(int d = 6; d <= 14; ++d)
    {
      const Limbed_model_spec spec = spec_of(m, 0.1 * d);
      const double score =
        std::abs(double(limbed_model_vertex_count(spec)) / target - 1.) + 0.05 * std::abs(std::log(0.1 * d));
      if(best_score < 0. || score < best_score)
      {
        best = spec;
        best_score = score;
      }
    }
  return best;
}

// The body is the surface of a lattice box (cell 2 / m, so a hole of m cells
// has the tube's radius 1 as inscribed circle), edges rounded with radius
// `corner_cells`. Around a hole, lattice points within `blend_cells` of the
// rim are moved radially so that the rim becomes the unit circle: the rim
// points are then exactly the first ring of the limb, at the angles of the
// square's lattice points, which every ring of every limb reuses. All
// segments are tubes of radius 1 (with a bulge vanishing at their ends); a
// joint of bend beta is a mitred cut: the shared ring lies in the bisector
// plane, tilted by beta / 2 against both segments' axes, so both ends match
// vertex by vertex. The rings inside a segment interpolate the two end
// planes, so they never cross for the moderate bends used.
Synthetic_model make_limbed_model(const Limbed_model_spec& spec, Synthetic_family family,
                                  const Synthetic_options& options)
{
  const int m = spec.hole_cells;
  const double step = 2. / m;
  const double pi = std::acos(-1.);
  const Eigen::Vector3i& cells = spec.cells;
  const Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = step * cells.cast<double>();
  const double corner = spec.corner_cells * step;

  std::vector<Hole_frame> frames;
  for(const Limb_hole& hole : spec.holes)
  {
    Hole_frame f;
    f.normal = axis_vector(hole.normal_axis, hole.normal_sign);
    f.x = axis_vector(hole.bend_axis, hole.bend_sign);
    f.y = f.normal.cross(f.x);
    f.center = hole.center;
    f.normal_axis = hole.normal_axis;
    f.plane = hole.normal_sign > 0 ? cells[hole.normal_axis] : 0;
    frames.push_back(f);
  }
  const std::vector<Eigen::Vector2d> rim = rim_offsets(m);
  const int ring_size = static_cast<int>(rim.size());

  // Latents per limb: lengths, bulges, then joint bends.
  const int segments = static_cast<int>(spec.chain.size());
  const int limbs = static_cast<int>(frames.size());
  Synthetic_random random = latent_stream(family, options);
  Eigen::MatrixXd latents(limbs, 3 * segments - 1);
  for(int l = 0; l < limbs; ++l)
  {
    for(int s = 0; s < segments; ++s)
    {
      const Limb_segment_type& t = spec.chain[s];
      latents(l, s) = random.uniform(-t.length_spread, t.length_spread);
      latents(l, segments + s) = random.uniform(-t.bulge_spread, t.bulge_spread);
      if(s + 1 < segments)
        latents(l, 2 * segments + s) = random.uniform(-t.end_bend_spread, t.end_bend_spread);
    }
  }
  center_latents(latents, options);

  Model_builder builder;
  builder.add_type(spec.body_name, 0, true);
  for(int s = 0; s < segments; ++s)
    builder.add_type(spec.chain[s].name, 2 + (s > 0) + (s + 1 < segments), false);

  // Body vertices, created on first use.
  auto lattice_index = [&](const Eigen::Vector3i& p) {
    return (p[2] * (cells[1] + 1) + p[1]) * (cells[0] + 1) + p[0];
  };
  std::vector<int> lattice_vertex(static_cast<std::size_t>((cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1)), -1);
  auto body_point = [&](const Eigen::Vector3i& p) -> Eigen::Vector3d {
    for(const Hole_frame& f : frames)
    {
      if(p[f.normal_axis] != f.plane)
        continue;
      const Eigen::Vector3d d = p.cast<double>() - f.center;
      const double u = d.dot(f.x), v = d.dot(f.y);
      const double rho = std::max(std::abs(u), std::abs(v));
      if(rho > 0.5 * m + spec.blend_cells)
        continue;
      const double t = (rho - 0.5 * m) / spec.blend_cells;
      const double r = std::hypot(u, v);
      const double radius = (1. - t) + t * r * step;
      return step * f.center + radius * (u * f.x + v * f.y) / r;
    }
    const Eigen::Vector3d x = step * p.cast<double>();
    const Eigen::Vector3d q = x.cwiseMax(lo + Eigen::Vector3d::Constant(corner)).cwiseMin(hi - Eigen::Vector3d::Constant(corner));
    const Eigen::Vector3d d = x - q;
    const double n = d.norm();
    return n > 0. ? Eigen::Vector3d(q + corner * d / n) : x;
  };
  auto body_vertex = [&](const Eigen::Vector3i& p) {
    int& v = lattice_vertex[static_cast<std::size_t>(lattice_index(p))];
    if(v < 0)
      v = builder.add_vertex(body_point(p));
    return v;
  };
  auto in_hole = [&](int axis, double plane, const Eigen::Vector3d& cell_center) {
    for(const Hole_frame& f : frames)
    {
      if(f.normal_axis != axis || f.plane != plane)
        continue;
      const Eigen::Vector3d d = cell_center - f.center;
      if(std::abs(d.dot(f.x)) < 0.5 * m && std::abs(d.dot(f.y)) < 0.5 * m)
        return true;
    }
    return false;
  };

  std::vector<Triangle> body_faces;
  for(int a = 0; a < 3; ++a)
    for(int sign = -1; sign <= 1; sign += 2)
    {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      const int plane = sign > 0 ? cells[a] : 0;
      for(int ic = 0; ic < cells[c]; ++ic)
        for(int ib = 0; ib < cells[b]; ++ib)
        {
          Eigen::Vector3d cell_center;
          cell_center[a] = plane;
          cell_center[b] = ib + 0.5;
          cell_center[c] = ic + 0.5;
          if(in_hole(a, plane, cell_center))
            continue;
          Eigen::Vector3i corner_point[4];
          for(int k = 0; k < 4; ++k)
          {
            corner_point[k][a] = plane;
            corner_point[k][b] = ib + (k == 1 || k == 2);
            corner_point[k][c] = ic + (k >= 2);
          }
          // Corners 0, 1, 2, 3 run counter-clockwise about +e_a (e_b x e_c = e_a).
          const int v0 = body_vertex(corner_point[0]), v1 = body_vertex(corner_point[1]);
          const int v2 = body_vertex(corner_point[2]), v3 = body_vertex(corner_point[3]);
          if(sign > 0)
          {
            body_faces.push_back({v0, v1, v2});
            body_faces.push_back({v0, v2, v3});
          }
          else
          {
            body_faces.push_back({v0, v2, v1});
            body_faces.push_back({v0, v3, v2});
          }
        }
    }
  const int body = builder.add_part(spec.body_name, body_faces, {});

  std::vector<double> ring_cos(ring_size), ring_sin(ring_size);
  for(int i = 0; i < ring_size; ++i)
  {
    const double r = rim[i].norm();
    ring_cos[i] = rim[i].x() / r;
    ring_sin[i] = rim[i].y() / r;
  }
  const int cap_rings = cap_rings_of(spec);

  for(int l = 0; l < limbs; ++l)
  {
    const Hole_frame& f = frames[l];
    std::vector<int> ring(ring_size);
    for(int i = 0; i < ring_size; ++i)
    {
      const Eigen::Vector3d p = f.center + rim[i].x() * f.x + rim[i].y() * f.y;
      ring[i] = body_vertex(Eigen::Vector3i(static_cast<int>(std::lround(p[0])), static_cast<int>(std::lround(p[1])),
                                            static_cast<int>(std::lround(p[2]))));
    }
    Eigen::Vector3d origin = step * f.center;
    Eigen::Matrix3d frame;
    frame << f.x, f.y, f.normal;
    int previous = body;
    for(int s = 0; s < segments; ++s)
    {
      const Limb_segment_type& type = spec.chain[s];
      const bool last = s + 1 == segments;
      const double length = type.length + latents(l, s);
      const double bulge = type.bulge + latents(l, segments + s);
      const double start_bend = s > 0 ? spec.chain[s - 1].end_bend + latents(l, 2 * segments + s - 1) : 0.;
      const double end_bend = last ? 0. : type.end_bend + latents(l, 2 * segments + s);
      const double t0 = -std::tan(0.5 * start_bend), t1 = std::tan(0.5 * end_bend);
      const int rings = rings_of(type, spec);
      std::vector<Triangle> faces;
      auto add_band = [&](const std::vector<int>& from, const std::vector<int>& to) {
        for(int i = 0; i < ring_size; ++i)
        {
          const int j = (i + 1) % ring_size;
          faces.push_back({from[i], from[j], to[j]});
          faces.push_back({from[i], to[j], to[i]});
        }
      };
      auto add_ring = [&](auto&& local_point) {
        std::vector<int> next(ring_size);
        for(int i = 0; i < ring_size; ++i)
          next[i] = builder.add_vertex(origin + frame * local_point(i));
        add_band(ring, next);
        ring = std::move(next);
      };
      for(int r = 1; r <= rings; ++r)
      {
        const double a = double(r) / rings;
        const double radius = 1. + bulge * std::sin(pi * a);
        add_ring([&](int i) {
          const double y = radius * ring_sin[i];
          return Eigen::Vector3d(radius * ring_cos[i], y, (1. - a) * t0 * y + a * (length + t1 * y));
        });
      }
      if(last)
      {
        for(int r = 1; r <= cap_rings; ++r)
        {
          const double phi = 0.5 * pi * r / (cap_rings + 1);
          add_ring([&](int i) {
            return Eigen::Vector3d(std::cos(phi) * ring_cos[i], std::cos(phi) * ring_sin[i],
                                   length + cap_height * std::sin(phi));
          });
        }
        const int pole = builder.add_vertex(origin + frame * Eigen::Vector3d(0., 0., length + cap_height));
        for(int i = 0; i < ring_size; ++i)
          faces.push_back({ring[i], ring[(i + 1) % ring_size], pole});
      }
      std::vector<double> latent = {latents(l, s), latents(l, segments + s)};
      if(s > 0)
        latent.push_back(latents(l, 2 * segments + s - 1));
      if(!last)
        latent.push_back(latents(l, 2 * segments + s));
      const int label = builder.add_part(type.name, faces, latent);
      builder.add_connection(previous, label, true);
      previous = label;
      origin += frame * Eigen::Vector3d(0., 0., length);
      frame = frame * Eigen::AngleAxisd(end_bend, Eigen::Vector3d::UnitX()).toRotationMatrix();
    }
  }

  // Rules: each hole of the body is its own site, so body-to-first-segment
  // gives one rule per hole; each joint between chain positions s and s + 1
  // joins the same two sites with the same ring mapping on every limb: one
  // rule per joint.
  double mean_length = 0.;
  for(const Limb_segment_type& type : spec.chain)
    mean_length += type.length / segments;
  return builder.finish(family, options, mean_length / 3., limbs + segments - 1);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
