// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Synthetic_builders.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// 15 tiles: a 5 x 3 parallelogram in axial hexagon coordinates, all in the
// same orientation.
constexpr int grid_columns = 5;
constexpr int grid_rows = 3;
constexpr int tile_modes = 3;

// Vertices of the grid when each tile is a hexagon of side n lattice steps:
// F = 6 n^2 triangles per tile and, by Euler's formula on a disk,
// V = 1 + (F + B) / 2 with B = n * (tile sides on the border) border edges.
long hexa_grid_vertex_count(long n)
{
  const long tiles = grid_columns * grid_rows;
  const long shared_sides = (grid_columns - 1) * grid_rows + grid_columns * (grid_rows - 1)
                          + (grid_columns - 1) * (grid_rows - 1);
  const long border_sides = 6 * tiles - 2 * shared_sides;
  return 1 + (6 * tiles * n * n + border_sides * n) / 2;
}

} // namespace

// Each tile is the hexagon of lattice points (a, b) of a regular triangular
// lattice with max(|a|, |b|, |a + b|) <= n, so its sides lie on lattice lines
// and every tile has the same triangulation. A tile's height field is
// phi * (A0 + sum_k a_k g_k), where phi = prod (n^2 - a^2)(n^2 - b^2)(n^2 - (a+b)^2)
// vanishes exactly on the border (integer arithmetic), so seams match. The
// mean is a dome; each mode g_k (r^2, x^2 - y^2, x y, shifted to zero sum of
// phi g_k) is even under (x, y) -> (-x, -y), so it moves no tile's centroid
// and carries no infinitesimal rotation: Procrustes + PCA recovers it exactly.
Synthetic_model make_hexa_grid(const Synthetic_options& options)
{
  const int target = options.vertices > 0 ? options.vertices : 51465;
  // Two lattice steps per side is the coarsest tile with interior points:
  // with one, the height field vanishes everywhere but at the centre and the
  // modes degenerate.
  long n = 2;
  while(std::abs(hexa_grid_vertex_count(n + 1) - target) < std::abs(hexa_grid_vertex_count(n) - target))
    ++n;
  const int side = static_cast<int>(n);
  const double step = 1. / side; // every tile has side length 1
  const double sqrt3 = std::sqrt(3.);

  // The tile template: local lattice points and faces.
  std::vector<std::pair<int, int>> local_points;
  std::map<std::pair<int, int>, int> local_index;
  auto inside = [side](int a, int b) {
    return std::abs(a) <= side && std::abs(b) <= side && std::abs(a + b) <= side;
  };
  for(int b = -side; b <= side; ++b)
    for(int a = -side; a <= side; ++a)
      if(inside(a, b))
      {
        local_index[{a, b}] = static_cast<int>(local_points.size());
        local_points.emplace_back(a, b);
      }
  std::vector<Triangle> template_faces;
  for(int b = -side; b < side; ++b)
    for(int a = -side; a < side; ++a)
    {
      if(inside(a, b) && inside(a + 1, b) && inside(a, b + 1))
        template_faces.push_back({local_index[{a, b}], local_index[{a + 1, b}], local_index[{a, b + 1}]});
      if(inside(a + 1, b) && inside(a + 1, b + 1) && inside(a, b + 1))
        template_faces.push_back({local_index[{a + 1, b}], local_index[{a + 1, b + 1}], local_index[{a, b + 1}]});
    }

  // Height fields of the template: mean dome and zero-sum modes.
  const std::size_t np = local_points.size();
  std::vector<double> dome(np);
  std::vector<std::array<double, tile_modes>> modes(np);
  const double n2 = static_cast<double>(side) * side;
  for(std::size_t i = 0; i < np; ++i)
  {
    const int a = local_points[i].first, b = local_points[i].second;
    const double phi = (n2 - double(a) * a) * (n2 - double(b) * b) * (n2 - double(a + b) * (a + b)) / (n2 * n2 * n2);
    const double x = (a + 0.5 * b) / side, y = 0.5 * sqrt3 * b / side;
    dome[i] = phi;
    modes[i] = {phi * (x * x + y * y), phi * (x * x - y * y), phi * 2. * x * y};
  }
  for(int k = 0; k < tile_modes; ++k)
  {
    double sum_phi = 0., sum_mode = 0., max_abs = 0.;
    for(std::size_t i = 0; i < np; ++i)
    {
      sum_phi += dome[i];
      sum_mode += modes[i][k];
    }
    const double shift = sum_mode / sum_phi;
    for(std::size_t i = 0; i < np; ++i)
    {
      modes[i][k] -= shift * dome[i];
      max_abs = std::max(max_abs, std::abs(modes[i][k]));
    }
    for(std::size_t i = 0; i < np; ++i)
      modes[i][k] /= max_abs;
  }

  // Heights for tiles of side 1: the mean dome rises 0.25, each mode (scaled
  // to a maximum of 1) by up to its spread.
  const int tiles = grid_columns * grid_rows;
  const double spread[tile_modes] = {0.12, 0.09, 0.07};
  Synthetic_random random = latent_stream(Synthetic_family::hexa_grid, options);
  Eigen::MatrixXd latents(tiles, tile_modes);
  for(int t = 0; t < tiles; ++t)
    for(int k = 0; k < tile_modes; ++k)
      latents(t, k) = random.uniform(-spread[k], spread[k]);
  center_latents(latents, options);

  Model_builder builder;
  builder.add_type("tile", tile_modes, true);
  std::map<std::pair<int, int>, int> global_index;
  std::vector<int> label_of_tile(tiles);
  for(int r = 0; r < grid_rows; ++r)
    for(int q = 0; q < grid_columns; ++q)
    {
      const int t = r * grid_columns + q;
      // Tile centres n (1, 1) and n (-1, 2) apart: neighbours share a side.
      const int ca = side * (q - r), cb = side * (q + 2 * r);
      std::vector<int> to_global(np);
      for(std::size_t i = 0; i < np; ++i)
      {
        const int a = ca + local_points[i].first, b = cb + local_points[i].second;
        auto found = global_index.find({a, b});
        if(found != global_index.end())
        {
          to_global[i] = found->second; // a seam vertex, at height 0 in both tiles
          continue;
        }
        double z = 0.25 * dome[i];
        for(int k = 0; k < tile_modes; ++k)
          z += latents(t, k) * modes[i][k];
        const int v = builder.add_vertex(Eigen::Vector3d((a + 0.5 * b) * step, 0.5 * sqrt3 * b * step, z));
        global_index.emplace(std::make_pair(a, b), v);
        to_global[i] = v;
      }
      std::vector<Triangle> faces;
      faces.reserve(template_faces.size());
      for(const Triangle& f : template_faces)
        faces.push_back({to_global[f[0]], to_global[f[1]], to_global[f[2]]});
      label_of_tile[t] = builder.add_part("tile", faces, matrix_row(latents, t));
    }

  // Neighbours in the three side directions (1, 0), (0, 1), (1, -1).
  for(int r = 0; r < grid_rows; ++r)
    for(int q = 0; q < grid_columns; ++q)
    {
      const int t = label_of_tile[r * grid_columns + q];
      if(q + 1 < grid_columns)
        builder.add_connection(t, label_of_tile[r * grid_columns + q + 1], true);
      if(r + 1 < grid_rows)
        builder.add_connection(t, label_of_tile[(r + 1) * grid_columns + q], true);
      if(q + 1 < grid_columns && r > 0)
        builder.add_connection(t, label_of_tile[(r - 1) * grid_columns + q + 1], true);
    }

  // Rules: all tiles share one orientation, so a docking is fixed by the
  // direction of the shared side; opposite sides form one pair of sites, and
  // the three side directions give three rules.
  const double tile_width = sqrt3;
  return builder.finish(Synthetic_family::hexa_grid, options, tile_width / 3., 3);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
