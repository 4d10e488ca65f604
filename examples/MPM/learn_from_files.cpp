// Learns a morphable part model from files: a mesh, its per-face part labels
// (.seg) and an annotation (JSON), then saves the model and prints the
// grammar's rules.
//
// Usage: learn_from_files [mesh.off labels.seg annotation.json [model.mpm]]
// Without arguments, a small synthetic spine (separate vertebrae, so the
// dockings are generalized) is first written to a temporary directory.
#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <filesystem>
#include <iostream>
#include <string>

namespace MPM = CGAL::MPM;
namespace fs = std::filesystem;

namespace {

std::string site_name(const MPM::Morphable_part_model& model, const MPM::Site_ref& s)
{
  return model.types[s.type].name + "#" + std::to_string(s.site);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 1 && argc != 4 && argc != 5) {
    std::cerr << "usage: " << argv[0] << " [mesh labels.seg annotation.json [model.mpm]]\n";
    return 1;
  }
  std::string mesh_path, labels_path, annotation_path, model_path;
  if(argc == 1) {
    const fs::path dir = fs::temp_directory_path() / "cgal_mpm_learn_from_files";
    fs::create_directories(dir);
    MPM::Synthetic_options options;
    options.vertices = 3000;
    const MPM::Synthetic_model spine = MPM::make_synthetic_model(MPM::Synthetic_family::spine, options);
    mesh_path = (dir / "spine.off").string();
    labels_path = (dir / "spine.seg").string();
    annotation_path = (dir / "spine.json").string();
    model_path = (dir / "spine.mpm").string();
    MPM::write_mesh_file(spine.mesh.mesh, mesh_path);
    MPM::write_seg_file(spine.mesh.face_labels, labels_path);
    MPM::write_annotation(spine.annotation, annotation_path);
    std::cout << "wrote a synthetic spine to " << dir.string() << "\n";
  } else {
    mesh_path = argv[1];
    labels_path = argv[2];
    annotation_path = argv[3];
    model_path = argc == 5 ? argv[4] : "model.mpm";
  }

  try {
    std::vector<std::string> warnings;
    const MPM::Labeled_mesh mesh = MPM::read_labeled_mesh(mesh_path, labels_path, &warnings);
    for(const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    const MPM::Annotation annotation = MPM::read_annotation(annotation_path);
    std::cout << "read " << mesh.mesh.number_of_vertices() << " vertices, " << mesh.mesh.number_of_faces()
              << " faces, " << annotation.part_type_of_label.size() << " annotated parts\n";

    MPM::Learning_options learning;
    learning.warning = [](const std::string& w) { std::cerr << "warning: " << w << "\n"; };
    const MPM::Morphable_part_model model = MPM::learn_morphable_part_model(mesh, annotation, learning);
    MPM::save_model(model, model_path);
    std::cout << "learned " << model.types.size() << " part types and " << model.rules.size()
              << " rules; saved " << fs::path(model_path).filename().string() << "\n";

    // The grammar: docking sites are its vertices, rules its edges.
    const MPM::Shape_grammar& grammar = model.grammar();
    std::cout << "grammar: " << grammar.number_of_sites() << " docking sites, " << grammar.number_of_rules()
              << " rules\n";
    const auto edges = boost::edges(grammar.graph());
    for(auto e = edges.first; e != edges.second; ++e) {
      const int r = grammar.graph()[*e];
      const MPM::Docking_rule& rule = model.rules[r];
      std::cout << "  rule " << r << ": " << site_name(model, rule.first) << " - " << site_name(model, rule.second)
                << (rule.kind == MPM::Docking_kind::boundary ? ", boundary, " : ", generalized, ")
                << rule.points.size() << " pair points, " << rule.space.number_of_instances() << " observations, "
                << rule.space.number_of_modes() << " modes\n";
    }
  } catch(const MPM::Input_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
