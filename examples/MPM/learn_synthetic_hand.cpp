// Learns a morphable part model from the built-in synthetic hand and prints
// what it learned: part types with their shape spaces, and the grammar.
#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Model/Shape_grammar.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <iostream>

namespace MPM = CGAL::MPM;

int main(int argc, char** argv)
{
  MPM::Synthetic_options options;
  options.vertices = 8000; // a smaller hand than the paper's 23k vertices, for a quick run
  const MPM::Synthetic_model hand = MPM::make_synthetic_model(MPM::Synthetic_family::hand, options);
  std::cout << "hand: " << hand.mesh.mesh.number_of_vertices() << " vertices, "
            << hand.mesh.mesh.number_of_faces() << " faces\n";

  const MPM::Morphable_part_model model = MPM::learn_morphable_part_model(hand.mesh, hand.annotation);
  for(const MPM::Part_type& type : model.types)
    std::cout << "type " << type.name << ": " << type.space.number_of_instances() << " instances, "
              << type.space.number_of_modes() << " modes explaining "
              << 100 * type.space.explained_variance(type.space.number_of_modes()) << "% of the variance, "
              << type.sites.size() << " docking sites\n";

  const MPM::Shape_grammar& grammar = model.grammar();
  std::cout << "grammar: " << grammar.number_of_sites() << " docking sites, " << grammar.number_of_rules()
            << " rules\n";

  const std::string path = argc > 1 ? argv[1] : "hand.mpm";
  MPM::save_model(model, path);
  std::cout << "saved " << path << "\n";
  return 0;
}
