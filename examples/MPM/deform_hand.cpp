// Free-form deformation with a morphable part model: learns the synthetic
// hand, takes a few handles from a held-out pose of the same hand (one per
// part), solves, and measures the result against the held-out pose.
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Solver/Handle_set.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace MPM = CGAL::MPM;

namespace {

double rms_distance(const MPM::Point_matrix& a, const MPM::Point_matrix& b)
{
  return std::sqrt((a - b).rowwise().squaredNorm().mean());
}

} // namespace

int main(int argc, char** argv)
{
  MPM::Synthetic_options options;
  options.vertices = 4000;
  const MPM::Synthetic_model hand = MPM::make_synthetic_model(MPM::Synthetic_family::hand, options);
  const MPM::Morphable_part_model model = MPM::learn_morphable_part_model(hand.mesh, hand.annotation);
  std::cout << "hand: " << hand.mesh.mesh.number_of_vertices() << " vertices, " << model.types.size()
            << " part types, " << model.rules.size() << " rules\n";

  // The rest pose is the energy's minimum ("exchange the means").
  const MPM::Embedding_problem problem = MPM::make_deformation_problem(model);
  MPM::Embedding_solver solver(problem);
  std::cout << problem.clusters.size() << " clusters, energy at rest " << solver.energy() << "\n";

  // A held-out pose: same connectivity, new latent parameters. Its positions
  // at one vertex per part are the handle targets.
  const MPM::Point_matrix pose = hand.draw_pose(7);
  const MPM::Handle_set handles = MPM::handles_per_part(hand.mesh, 1, pose);
  solver.set_handles(handles.vertices, handles.targets);

  const MPM::Solve_report report = solver.solve();
  std::cout << handles.size() << " handles; " << report.iterations << " iterations ("
            << (report.converged ? "converged" : "iteration cap") << ")\n";
  // The first iterations and the last one.
  const std::size_t shown = std::min<std::size_t>(3, report.energies.size());
  std::cout << "energies:";
  for(std::size_t i = 0; i < shown; ++i) std::cout << " " << report.energies[i];
  if(report.energies.size() > shown) std::cout << " ... " << report.energies.back();
  std::cout << "\n";

  const double diagonal = (pose.colwise().maxCoeff() - pose.colwise().minCoeff()).norm();
  std::cout << "RMS error to the held-out pose: " << rms_distance(solver.positions(), pose) << " ("
            << 100 * rms_distance(solver.positions(), pose) / diagonal << "% of the diagonal; rest pose: "
            << 100 * rms_distance(hand.mesh.mesh.points, pose) / diagonal << "%)\n";

  MPM::Indexed_mesh result = hand.mesh.mesh;
  result.points = solver.positions();
  const std::string path = argc > 1 ? argv[1] : "deformed_hand.ply";
  MPM::write_mesh_file(result, path);
  std::cout << "wrote " << path << "\n";
  return 0;
}
