// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Synthetic_builders.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

constexpr int window_columns = 5;
constexpr int window_rows = 4;
constexpr int window_modes = 4;        // width, height, frame border, frame depth
constexpr double column_pitch = 2.0;
constexpr double row_pitch = 2.6;
constexpr double margin = 1.0;
constexpr double wall_gap = 0.05;      // between the wall and a window's back
constexpr double mean_width = 1.0, mean_height = 1.4, mean_border = 0.12, mean_depth = 0.16;

struct Facade_resolution
{
  int loop = 1;    // frame segments per rectangle side
  int profile = 1; // segments per side of the frame's cross-section
  int wall_x = 1, wall_y = 1; // wall grid cells
};

Facade_resolution facade_resolution(int k)
{
  Facade_resolution r;
  r.loop = k;
  r.profile = std::max(1, static_cast<int>(std::lround(k / 6.)));
  r.wall_x = 5 * k;
  r.wall_y = static_cast<int>(std::lround(5.2 * k));
  return r;
}

long facade_vertex_count(const Facade_resolution& r)
{
  return long(r.wall_x + 1) * (r.wall_y + 1) + long(window_columns) * window_rows * 16 * r.loop * r.profile;
}

// (2 i - n) / n: exactly antisymmetric under i -> n - i, which keeps the
// window template exactly mirror-symmetric.
double symmetric_coordinate(int i, int n) { return (2. * i - n) / n; }

} // namespace

// A wall (a grid in the plane z = 0, facing +z) and 20 windows in front of
// it, each a closed rectangular frame: a rectangular cross-section (p, q),
// p from the outer (0) to the inner (1) rim, q from back (-1) to front (1),
// swept around a rectangle (X, Y) in [-1, 1]^2. A frame point is
//   (X (W/2 - p f), Y (H/2 - p f), q D/2),
// linear in (W, H, f, D). The template is mirror-symmetric in x, y and z and
// every mode moves each coordinate by an odd function of it that is even in
// the others, so the modes are orthogonal to infinitesimal rigid motions and
// Procrustes + PCA recovers them exactly.
Synthetic_model make_facade(const Synthetic_options& options)
{
  const int target = options.vertices > 0 ? options.vertices : 45493;
  int k = 1;
  while(std::labs(facade_vertex_count(facade_resolution(k + 1)) - target)
        < std::labs(facade_vertex_count(facade_resolution(k)) - target))
    ++k;
  const Facade_resolution res = facade_resolution(k);

  // Window template: loop positions (X, Y) counter-clockwise, profile (p, q).
  std::vector<Eigen::Vector2d> loop, profile;
  for(int side = 0; side < 4; ++side)
    for(int i = 0; i < res.loop; ++i)
    {
      const double s = symmetric_coordinate(i, res.loop);
      const Eigen::Vector2d p[4] = {{1., s}, {-s, 1.}, {-1., -s}, {s, -1.}};
      loop.push_back(p[side]);
    }
  for(int side = 0; side < 4; ++side)
    for(int i = 0; i < res.profile; ++i)
    {
      const double s = double(i) / res.profile, t = symmetric_coordinate(i, res.profile);
      const Eigen::Vector2d p[4] = {{s, 1.}, {1., -t}, {1. - s, -1.}, {0., t}};
      profile.push_back(p[side]);
    }
  const int nl = static_cast<int>(loop.size()), np = static_cast<int>(profile.size());
  auto window_point = [&](int l, int p, double w, double h, double f, double d) {
    return Eigen::Vector3d(loop[l].x() * (0.5 * w - profile[p].x() * f),
                           loop[l].y() * (0.5 * h - profile[p].x() * f),
                           0.5 * d * profile[p].y());
  };
  std::vector<Triangle> window_faces;
  for(int l = 0; l < nl; ++l)
    for(int p = 0; p < np; ++p)
    {
      const int a = l * np + p, b = ((l + 1) % nl) * np + p;
      const int c = ((l + 1) % nl) * np + (p + 1) % np, d = l * np + (p + 1) % np;
      window_faces.push_back({a, b, c});
      window_faces.push_back({a, c, d});
    }
  {
    std::vector<Eigen::Vector3d> mean;
    for(int l = 0; l < nl; ++l)
      for(int p = 0; p < np; ++p)
        mean.push_back(window_point(l, p, mean_width, mean_height, mean_border, mean_depth));
    orient_outward(window_faces, mean);
  }

  const int windows = window_columns * window_rows;
  const double spread[window_modes] = {0.2, 0.25, 0.03, 0.05};
  Synthetic_random random = latent_stream(Synthetic_family::facade, options);
  Eigen::MatrixXd latents(windows, window_modes);
  for(int w = 0; w < windows; ++w)
    for(int m = 0; m < window_modes; ++m)
      latents(w, m) = random.uniform(-spread[m], spread[m]);
  center_latents(latents, options);

  Model_builder builder;
  builder.add_type("wall", 0, true);
  builder.add_type("window", window_modes, true);

  const double wall_width = window_columns * column_pitch + 2. * margin;
  const double wall_height = window_rows * row_pitch + 2. * margin;
  std::vector<Triangle> wall_faces;
  const int first = builder.number_of_vertices();
  for(int j = 0; j <= res.wall_y; ++j)
    for(int i = 0; i <= res.wall_x; ++i)
      builder.add_vertex(Eigen::Vector3d(0.5 * wall_width * symmetric_coordinate(i, res.wall_x),
                                         0.5 * wall_height * symmetric_coordinate(j, res.wall_y), 0.));
  for(int j = 0; j < res.wall_y; ++j)
    for(int i = 0; i < res.wall_x; ++i)
    {
      const int a = first + j * (res.wall_x + 1) + i, b = a + 1, c = b + res.wall_x + 1, d = a + res.wall_x + 1;
      wall_faces.push_back({a, b, c});
      wall_faces.push_back({a, c, d});
    }
  const int wall = builder.add_part("wall", wall_faces, {});

  for(int w = 0; w < windows; ++w)
  {
    const double width = mean_width + latents(w, 0), height = mean_height + latents(w, 1);
    const double border = mean_border + latents(w, 2), depth = mean_depth + latents(w, 3);
    const Eigen::Vector3d center(column_pitch * (w % window_columns - 0.5 * (window_columns - 1)),
                                 row_pitch * (w / window_columns - 0.5 * (window_rows - 1)),
                                 wall_gap + 0.5 * depth);
    const int base = builder.number_of_vertices();
    for(int l = 0; l < nl; ++l)
      for(int p = 0; p < np; ++p)
        builder.add_vertex(center + window_point(l, p, width, height, border, depth));
    std::vector<Triangle> faces = window_faces;
    for(Triangle& f : faces)
      for(int& v : f)
        v += base;
    builder.add_connection(wall, builder.add_part("window", faces, matrix_row(latents, w)), false);
  }

  // The docking radius must exceed the gap, also measured between vertices:
  // every window vertex has a wall vertex within half a grid diagonal
  // laterally. It stays below the free space between windows (>= 0.8).
  const double wall_step = std::max(wall_width / res.wall_x, wall_height / res.wall_y);
  const double docking_radius = std::max(0.15, 1.1 * std::hypot(wall_step / std::sqrt(2.), wall_gap));

  // Rules: a window has one site (its back); each window docks to its own
  // region of the wall, a distinct site of the wall (as each hole of a palm
  // is), so there is one rule per window.
  return builder.finish(Synthetic_family::facade, options, docking_radius, windows);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
