// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shape-space quality per part type of every synthetic family (the classic
// statistical-shape-model measures), learned from the family's training mesh:
//   compactness     fraction of the variance the first `modes` modes explain;
//   generalization  leave-one-out: each instance fitted (rigid motion and
//                   coordinates, Shape_space::fit) by the space of the others
//                   truncated to `modes` modes; mean RMS point error;
//   specificity     random shapes of the space truncated to `modes` modes
//                   (coordinates drawn from N(0, sigma_k^2)), each compared with
//                   the nearest training instance after rigid alignment;
//                   mean RMS point error.
// Errors are relative to the bounding-box diagonal of the type's mean shape.
// true_modes is the generator's number of latent parameters of the type.
// CSV on stdout or --csv FILE. --poses and --counts are accepted (so the
// quality programs share a command line) and ignored.
#include "quality_common.h"

#include <CGAL/MPM/Model/Shape_space.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>
#include <CGAL/MPM/internal/Bounding_box.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <random>

namespace {

const char* const usage =
  "Usage: quality_shape_space [--vertices N] [--samples S] [--seed K] [--families LIST|all] [--csv FILE]\n"
  "Defaults: --vertices 3000 --samples 200 --seed 1 --families all (--poses, --counts: ignored)\n";

using namespace CGAL::MPM;

double rms(const Point_matrix& a, const Point_matrix& b)
{
  return std::sqrt((a - b).rowwise().squaredNorm().mean());
}

// The space with its first `k` modes only.
Shape_space truncated(const Shape_space& space, int k)
{
  Shape_space t = space;
  k = std::min(k, space.number_of_modes());
  t.modes = space.modes.leftCols(k);
  t.sigmas = space.sigmas.head(k);
  return t;
}

Shape_space full_space(const std::vector<Point_matrix>& instances)
{
  Shape_space_options o;
  o.modes = static_cast<int>(instances.size()); // as many as the data hold
  return learn_shape_space(instances, o);
}

} // namespace

int main(int argc, char** argv)
{
  const mpm_quality::Options options(argc, argv,
                                     {{"vertices", "3000"},
                                      {"samples", "200"},
                                      {"seed", "1"},
                                      {"families", "all"},
                                      {"poses", ""},
                                      {"counts", ""},
                                      {"csv", ""}},
                                     usage);
  mpm_quality::Csv_output csv(options.text("csv"));
  std::ostream& out = csv.stream();
  out << "family,type,instances,points,true_modes,measure,modes,value\n";
  std::mt19937 random(static_cast<unsigned>(options.integer("seed")));
  const int samples = options.integer("samples");

  for(const Synthetic_family family : options.families())
  {
    Synthetic_options so;
    so.vertices = options.integer("vertices");
    const Synthetic_model truth = make_synthetic_model(family, so);
    const Morphable_part_model model = learn_morphable_part_model(truth.mesh, truth.annotation);
    const Training_example& example = model.examples[0];
    const Point_matrix rest = rest_positions(example);
    const std::string name = family_name(family);
    std::cerr << name << ": " << model.types.size() << " part types\n";

    for(std::size_t t = 0; t < model.types.size(); ++t)
    {
      const Part_type& type = model.types[t];
      std::vector<Point_matrix> instances;
      for(const Part_node& node : example.graph.nodes)
        if(node.type == static_cast<int>(t))
        {
          Point_matrix p(Eigen::Index(node.vertices.size()), 3);
          for(std::size_t i = 0; i < node.vertices.size(); ++i) p.row(Eigen::Index(i)) = rest.row(node.vertices[i]);
          instances.push_back(std::move(p));
        }
      const int m = static_cast<int>(instances.size());
      if(m < 2) continue; // one instance: nothing varies
      int true_modes = -1;
      for(const Synthetic_type& st : truth.types)
        if(st.name == type.name) true_modes = st.modes;
      const Shape_space space = full_space(instances);
      const double scale = internal::bounding_box_diagonal(space.mean);
      auto row = [&](const char* measure, int modes, double value) {
        out << name << ',' << type.name << ',' << m << ',' << type.number_of_vertices << ',' << true_modes << ','
            << measure << ',' << modes << ',' << mpm_quality::number(value) << '\n';
        out.flush();
      };

      // Compactness.
      for(int k = 0; k <= space.number_of_modes(); ++k) row("compactness", k, space.explained_variance(k));

      // Generalization: leave one out, fit with k modes.
      if(m >= 3)
      {
        std::vector<Shape_space> without(static_cast<std::size_t>(m));
        int common = std::numeric_limits<int>::max();
        for(int j = 0; j < m; ++j)
        {
          std::vector<Point_matrix> others;
          for(int i = 0; i < m; ++i)
            if(i != j) others.push_back(instances[std::size_t(i)]);
          without[std::size_t(j)] = full_space(others);
          common = std::min(common, without[std::size_t(j)].number_of_modes());
        }
        for(int k = 0; k <= common; ++k)
        {
          double sum = 0.;
          for(int j = 0; j < m; ++j)
          {
            const Shape_space s = truncated(without[std::size_t(j)], k);
            Eigen::VectorXd coordinates;
            Rigid_motion motion;
            s.fit(instances[std::size_t(j)], coordinates, motion);
            sum += rms(motion.apply(s.shape(coordinates)), instances[std::size_t(j)]);
          }
          row("generalization", k, sum / m / scale);
        }
      }

      // Specificity: random shapes against their nearest training instance.
      for(int k = 0; k <= space.number_of_modes(); ++k)
      {
        const Shape_space s = truncated(space, k);
        double sum = 0.;
        for(int r = 0; r < samples; ++r)
        {
          Eigen::VectorXd coordinates(k);
          for(int i = 0; i < k; ++i) coordinates[i] = std::normal_distribution<double>(0., s.sigmas[i])(random);
          const Point_matrix shape = s.shape(coordinates);
          double nearest = std::numeric_limits<double>::infinity();
          for(const Point_matrix& instance : instances)
            nearest = std::min(nearest, rms(fit_rigid_motion(shape, instance).apply(shape), instance));
          sum += nearest;
        }
        row("specificity", k, sum / std::max(samples, 1) / scale);
      }
    }
  }
  return 0;
}
