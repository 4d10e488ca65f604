// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Farthest_point_sampling.h>

namespace CGAL {
namespace MPM {
namespace internal {

std::vector<int> farthest_point_sampling(const Point_matrix& points, int count, int first,
                                         Eigen::VectorXd& squared_distance, const std::function<bool(int)>& eligible,
                                         double min_squared_distance, std::vector<int>* nearest_pick)
{
  const int n = static_cast<int>(points.rows());
  std::vector<bool> picked(std::size_t(n), false);
  std::vector<int> picks;
  int next = first;
  while(static_cast<int>(picks.size()) < count)
  {
    if(next < 0)
    {
      for(int v = 0; v < n; ++v)
        if(!picked[std::size_t(v)] && (!eligible || eligible(v)) &&
           (next < 0 || squared_distance[v] > squared_distance[next]))
          next = v;
      if(next < 0 || !(squared_distance[next] > min_squared_distance)) break;
    }
    picked[std::size_t(next)] = true;
    picks.push_back(next);
    for(int v = 0; v < n; ++v)
    {
      const double d = (points.row(v) - points.row(next)).squaredNorm();
      if(d < squared_distance[v])
      {
        squared_distance[v] = d;
        if(nearest_pick) (*nearest_pick)[std::size_t(v)] = static_cast<int>(picks.size()) - 1;
      }
    }
    next = -1;
  }
  return picks;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
