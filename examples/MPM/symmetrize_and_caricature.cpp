// Two edits without handles on the synthetic hexa-grid: partial
// symmetrization (every tile pulled to its type's mean shape) and a
// caricature (every tile's deviation from the mean doubled). Writes both as
// OFF files and prints their residual energies.
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <cmath>
#include <iostream>
#include <string>

namespace MPM = CGAL::MPM;

namespace {

// Solves `problem` (no handles: each piece is anchored at one vertex to its
// rest position), reports and writes the result.
void solve_and_write(const std::string& what, const MPM::Embedding_problem& problem, const std::string& path)
{
  MPM::Embedding_solver solver(problem);
  const double initial = solver.energy();
  const MPM::Solve_report report = solver.solve();
  const MPM::Point_matrix& v = solver.positions();
  const double moved = std::sqrt((v - problem.mesh.points).rowwise().squaredNorm().mean());
  std::cout << what << ": energy " << initial << " at the input, " << report.energies.front()
            << " after one iteration, residual " << report.energy() << " after " << report.iterations
            << " iterations (" << (report.converged ? "converged" : "iteration cap") << ")\n"
            << "  RMS vertex motion " << moved << "\n";
  MPM::Indexed_mesh result = problem.mesh;
  result.points = v;
  MPM::write_mesh_file(result, path);
  std::cout << "  wrote " << path << "\n";
}

} // namespace

int main()
{
  MPM::Synthetic_options options;
  options.vertices = 3000;
  const MPM::Synthetic_model grid = MPM::make_synthetic_model(MPM::Synthetic_family::hexa_grid, options);
  const MPM::Morphable_part_model model = MPM::learn_morphable_part_model(grid.mesh, grid.annotation);
  const double diagonal =
    (grid.mesh.mesh.points.colwise().maxCoeff() - grid.mesh.mesh.points.colwise().minCoeff()).norm();
  std::cout << "hexa-grid: " << grid.mesh.mesh.number_of_vertices() << " vertices, diagonal " << diagonal << "\n";
  for(const MPM::Part_type& type : model.types)
    std::cout << "type " << type.name << ": " << type.space.number_of_instances() << " instances, "
              << type.space.number_of_modes() << " modes\n";

  MPM::Symmetrization_options symmetrization;
  symmetrization.relative_sigma = 0.01; // modes nearly frozen at the mean
  solve_and_write("symmetrization", MPM::make_symmetrization_problem(model, 0, symmetrization), "symmetrized.off");
  solve_and_write("caricature (factor 2)", MPM::make_caricature_problem(model, 2.), "caricature.off");
  return 0;
}
