// Learns a morphable part model from a CGAL::Surface_mesh whose faces carry
// part labels in a property map, through the FaceGraph overload of
// learn_morphable_part_model(). Any FaceGraph works the same way
// (Polyhedron_3, OpenMesh, ...); here the mesh is the built-in synthetic
// hexa-grid copied into a Surface_mesh.
#include <CGAL/MPM/Synthetic_model.h>
#include <CGAL/MPM/learn_morphable_part_model.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <vector>

namespace MPM = CGAL::MPM;
using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;

int main()
{
  MPM::Synthetic_options options;
  options.vertices = 3000;
  const MPM::Synthetic_model grid = MPM::make_synthetic_model(MPM::Synthetic_family::hexa_grid, options);

  // A Surface_mesh with an integer face property "f:label".
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertex;
  const MPM::Point_matrix& p = grid.mesh.mesh.points;
  for(Eigen::Index i = 0; i < p.rows(); ++i) vertex.push_back(mesh.add_vertex(Point_3(p(i, 0), p(i, 1), p(i, 2))));
  Mesh::Property_map<Mesh::Face_index, int> label = mesh.add_property_map<Mesh::Face_index, int>("f:label", -1).first;
  for(std::size_t f = 0; f < grid.mesh.mesh.triangles.size(); ++f) {
    const MPM::Triangle& t = grid.mesh.mesh.triangles[f];
    const Mesh::Face_index face = mesh.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]);
    if(face == Mesh::null_face()) {
      std::cerr << "face " << f << " cannot be added (non-manifold)\n";
      return 1;
    }
    label[face] = grid.mesh.face_labels[f];
  }
  std::cout << "surface mesh: " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces()
            << " faces\n";

  // Vertices and faces are numbered in vertices(mesh) and faces(mesh) order.
  const MPM::Morphable_part_model model =
    MPM::learn_morphable_part_model(mesh, label, grid.annotation,
                                    CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, mesh)));
  for(const MPM::Part_type& type : model.types)
    std::cout << "type " << type.name << ": " << type.space.number_of_instances() << " instances of "
              << type.number_of_vertices << " vertices, " << type.space.number_of_modes() << " modes\n";
  std::cout << model.rules.size() << " docking rules, sigma_sub = " << model.parameters.sigma_sub
            << ", docking radius = " << model.parameters.docking_radius << "\n";
  return 0;
}
