// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Rotation_groups.h>

namespace CGAL {
namespace MPM {
namespace internal {
namespace embedding {

namespace {

// L_g P on the support of the star of point `i`, `support[0] == i`, the
// neighbours after it in the order of `star`: the covariance of the star's
// edges, sum_j w_ij (v_i - v_j)(p_i - p_j)^T, is then V_g^T (L_g P).
Point_matrix star_product(const std::vector<const Weighted_edge*>& star, int i, const Point_matrix& p)
{
  Point_matrix product = Point_matrix::Zero(Eigen::Index(star.size()) + 1, 3);
  for(std::size_t s = 0; s < star.size(); ++s)
  {
    const int j = star[s]->i == i ? star[s]->j : star[s]->i;
    const Eigen::RowVector3d difference = star[s]->w * (p.row(i) - p.row(j));
    product.row(0) += difference;
    product.row(Eigen::Index(s) + 1) = -difference;
  }
  return product;
}

} // namespace

Rotation_groups::Rotation_groups(const std::vector<Cluster_data>& clusters, Rotations kind)
  : per_vertex_(kind == Rotations::per_vertex)
{
  for(std::size_t c = 0; c < clusters.size(); ++c)
  {
    const Cluster_data& d = clusters[c];
    first_group_.push_back(size());
    if(!per_vertex_)
    {
      Group g;
      g.cluster = int(c);
      groups_.push_back(std::move(g));
      continue;
    }
    std::vector<std::vector<const Weighted_edge*>> stars(d.vertices.size());
    for(const Weighted_edge& e : d.edges)
    {
      stars[std::size_t(e.i)].push_back(&e);
      stars[std::size_t(e.j)].push_back(&e);
    }
    for(std::size_t i = 0; i < d.vertices.size(); ++i)
    {
      Group g;
      g.cluster = int(c);
      g.support.push_back(int(i));
      for(const Weighted_edge* e : stars[i]) g.support.push_back(e->i == int(i) ? e->j : e->i);
      g.laplacian_mean = star_product(stars[i], int(i), d.mean);
      for(const Point_matrix& mode : d.modes) g.laplacian_modes.push_back(star_product(stars[i], int(i), mode));
      groups_.push_back(std::move(g));
    }
  }
}

void Rotation_groups::fit(const std::vector<Cluster_data>& clusters, const Point_matrix& positions,
                          const Eigen::VectorXd& coordinates, std::vector<Eigen::Matrix3d>& rotations) const
{
  for(std::size_t g = 0; g < groups_.size(); ++g)
  {
    const Group& group = groups_[g];
    const Cluster_data& d = clusters[std::size_t(group.cluster)];
    // A group without support is a whole cluster, whose L_c M and L_c B_k
    // the cluster holds already.
    const bool whole = group.support.empty();
    Point_matrix lm = whole ? d.laplacian_mean : group.laplacian_mean;
    const std::vector<Point_matrix>& modes = whole ? d.laplacian_modes : group.laplacian_modes;
    for(int k = 0; k < d.number_of_modes(); ++k) lm += coordinates[d.offset + k] * modes[std::size_t(k)];
    Eigen::MatrixXd v(group.support.size(), 3);
    if(whole) v = gather(d, positions);
    for(std::size_t s = 0; s < group.support.size(); ++s)
      v.row(Eigen::Index(s)) = positions.row(d.vertices[std::size_t(group.support[s])]);
    rotations[g] = closest_rotation(v.transpose() * lm);
  }
}

Eigen::Matrix3d Rotation_groups::edge_transform(int c, const Weighted_edge& e,
                                                const std::vector<Eigen::Matrix3d>& rotations) const
{
  if(!per_vertex_) return cluster_transform(c, rotations);
  const int first = first_group_[std::size_t(c)];
  return 0.5 * (rotations[std::size_t(first + e.i)] + rotations[std::size_t(first + e.j)]);
}

} // namespace embedding
} // namespace internal
} // namespace MPM
} // namespace CGAL
