// From a raw mesh to an edited model with no file written by hand: a
// Surface_mesh without any labels is cut at joints proposed from its curve
// skeleton (labels in a face property of the mesh), its segments get part
// types proposed from their places in the segment graph, a model is learned
// from the mesh and that map, and the learned example is exaggerated away
// from its types' means (a caricature), written through the vertex point
// map and saved.
//
// Usage: raw_mesh_to_model [mesh.off [caricature.off]]
// Without arguments, the built-in synthetic hand with its labels dropped;
// a scanned hand or octopus works the same way, e.g. hand_190.off of the
// Princeton Segmentation Benchmark (see doc/MPM/Cutting.md).
#include <CGAL/MPM/Cutting/Face_graph_cutting.h>
#include <CGAL/MPM/Editing/Face_graph_editing.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <string>

namespace MPM = CGAL::MPM;
using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

int main(int argc, char** argv)
{
  try {
    Mesh mesh;
    if(argc > 1) {
      if(!CGAL::IO::read_polygon_mesh(argv[1], mesh)) throw MPM::Input_error(argv[1], "", "cannot be read");
    } else {
      MPM::Synthetic_options options;
      options.vertices = 3000;
      MPM::copy_to_face_graph(MPM::make_synthetic_model(MPM::Synthetic_family::hand, options).mesh.mesh, mesh);
    }
    std::cout << (argc > 1 ? argv[1] : "synthetic hand") << ": " << num_vertices(mesh) << " vertices, no labels\n";

    // Cut: one label per face, in the mesh's own property map.
    Mesh::Property_map<Mesh::Face_index, int> part = mesh.add_property_map<Mesh::Face_index, int>("f:part", -1).first;
    const auto joints = MPM::cut_at_proposed_joints(mesh, part);
    std::cout << "cut at " << joints.cutting.cuts.size() << " proposed joints on " << joints.limbs << " limbs\n";

    // Part types from the segment graph: the fingers' segments share types.
    const MPM::Part_type_proposal types = MPM::propose_part_types(mesh, part);
    std::cout << types.segments.size() << " segments; proposed part types:";
    for(const auto& [type, count] : types.instances_of_type()) std::cout << " " << type << " x" << count;
    std::cout << "\n";

    // Learn from the mesh and its label map, then exaggerate the learned example.
    const MPM::Morphable_part_model model = MPM::learn_morphable_part_model(mesh, part, types.annotation);
    std::cout << "learned " << model.types.size() << " part types and " << model.rules.size() << " rules\n";
    Mesh edited;
    MPM::copy_training_example(model, 0, edited, get(CGAL::dynamic_face_property_t<int>(), edited));
    const MPM::Edit_result caricature = MPM::caricature(model, 1.5, edited);
    std::cout << "caricature (factor 1.5): " << caricature.report.iterations << " iterations"
              << (caricature.report.converged ? " (converged)" : " (not converged)") << ", energy "
              << caricature.report.energy() << "\n";

    const std::string output = argc > 2 ? argv[2] : "caricature.off";
    if(!CGAL::IO::write_polygon_mesh(output, edited, CGAL::parameters::stream_precision(17)))
      throw MPM::Input_error(output, "", "cannot be written");
    std::cout << "wrote " << output << "\n";
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
