// Cuts a mesh into parts along cutting lines (a few vertices per cut, joined
// by feature-weighted shortest paths) and learns a morphable part model from
// the parts, as `mpm cut` followed by `mpm learn` would.
//
// Usage: cut_and_learn mesh.off cuts.json annotation.json [model.mpm] [feature_weight]
// For instance, with CGAL's sample meshes (Debian: libcgal-demo) extracted to data/:
//   cut_and_learn data/diplodocus.off examples/MPM/data/diplodocus_legs.cuts.json \
//                 examples/MPM/data/diplodocus_legs.annotation.json
#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Cutting/Mesh_cutting.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

namespace MPM = CGAL::MPM;

int main(int argc, char** argv)
{
  if(argc < 4 || argc > 6) {
    std::cerr << "usage: " << argv[0] << " mesh.off cuts.json annotation.json [model.mpm] [feature_weight]\n";
    return 1;
  }
  const std::string mesh_path = argv[1], cuts_path = argv[2], annotation_path = argv[3];
  const std::string model_path = argc >= 5 ? argv[4] : "model.mpm";
  try {
    const MPM::Mesh_file file = MPM::read_mesh_file(mesh_path);
    const MPM::Cut_specification cuts = MPM::read_cut_specification(cuts_path);
    MPM::Cutting_options options;
    if(argc == 6) options.feature_weight = std::atof(argv[5]);
    const MPM::Cutting_result cut = MPM::cut_mesh(file.mesh, cuts, options, mesh_path);

    std::map<int, int> faces;
    for(int label : cut.mesh.face_labels) ++faces[label];
    std::cout << "cut " << mesh_path << " into " << cut.regions << " parts:";
    for(const auto& [label, count] : faces) std::cout << " label " << label << " (" << count << " faces)";
    std::cout << "\n";
    for(std::size_t i = 0; i < cuts.cuts.size(); ++i)
      std::cout << "  cut \"" << cuts.cuts[i].name << "\": " << cut.paths[i].size() << " path vertices, length "
                << cut.lengths[i] << "\n";

    // The labelled mesh is what `mpm learn` reads from a .off and a .seg file.
    const MPM::Annotation annotation = MPM::read_annotation(annotation_path);
    MPM::Learning_options learning;
    learning.warning = [](const std::string& w) { std::cerr << "warning: " << w << "\n"; };
    const MPM::Morphable_part_model model = MPM::learn_morphable_part_model(cut.mesh, annotation, learning);
    MPM::save_model(model, model_path);
    std::cout << "learned " << model.types.size() << " part types:";
    for(const MPM::Part_type& type : model.types)
      std::cout << " " << type.name << " (" << type.space.number_of_instances() << " instances, "
                << type.space.number_of_modes() << " modes)";
    std::cout << "; saved " << model_path << "\n";
  } catch(const MPM::Input_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  } catch(const MPM::Computation_error& e) {
    std::cerr << "computation failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
