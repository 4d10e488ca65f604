// The whole pipeline on the user's own mesh type: a mesh file read with
// CGAL's IO into a Surface_mesh, a Polyhedron_3 and (when OpenMesh is
// installed) an OpenMesh triangle mesh is cut into parts (labels in a face
// property map), learned from, deformed in place (the result written through
// the vertex point map, as Surface_mesh_deformation does) and reassembled
// into a new mesh whose faces know their part graph node and part type and
// whose vertices know whether they lie on a seam (property maps again); a
// learned part type, moved along its first mode, is copied out as a mesh.
//
// Usage: face_graph_pipeline mesh.off cuts.json annotation.json
// For instance, with CGAL's sample meshes (Debian: libcgal-demo) extracted to data/:
//   face_graph_pipeline data/diplodocus.off examples/MPM/data/diplodocus_legs.cuts.json \
//                       examples/MPM/data/diplodocus_legs.annotation.json
#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Cutting/Face_graph_cutting.h>
#include <CGAL/MPM/Editing/Face_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#ifdef MPM_HAS_OPENMESH
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#endif

#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace MPM = CGAL::MPM;
using Kernel = CGAL::Simple_cartesian<double>;

template <class Mesh>
void run(const std::string& name, const std::string& mesh_path, const MPM::Cut_specification& cuts,
         const MPM::Annotation& annotation)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using Point = typename boost::property_traits<typename CGAL::GetVertexPointMap<Mesh>::type>::value_type;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(mesh_path, mesh)) throw MPM::Input_error(mesh_path, "", "cannot be read");

  // Cut: one label per face, in a property map of the mesh.
  auto labels = get(CGAL::dynamic_face_property_t<int>(), mesh);
  const auto cut = MPM::cut_mesh(mesh, cuts, labels);
  const MPM::Morphable_part_model model = MPM::learn_morphable_part_model(mesh, labels, annotation);

  // Deform the learned example in place: its lowest vertex held, its highest lifted.
  Mesh edited;
  auto parts = get(CGAL::dynamic_face_property_t<int>(), edited);
  MPM::copy_training_example(model, 0, edited, parts);
  const auto vpm = get(CGAL::vertex_point, edited);
  vertex_descriptor low = *vertices(edited).begin(), high = low;
  for(vertex_descriptor v : vertices(edited)) {
    if(get(vpm, v).y() < get(vpm, low).y()) low = v;
    if(get(vpm, v).y() > get(vpm, high).y()) high = v;
  }
  const double lift = 0.05 * (get(vpm, high).y() - get(vpm, low).y());
  const Point top = get(vpm, high);
  const std::vector<std::pair<vertex_descriptor, Point>> handles = {
    {low, get(vpm, low)}, {high, Point(top.x(), top.y() + lift, top.z())}};
  const MPM::Edit_result deformed = MPM::deform(model, edited, handles);

  // Reassemble the example's part graph into a new mesh; faces know their
  // node and part type, vertices whether they join two parts.
  Mesh assembled;
  auto nodes = get(CGAL::dynamic_face_property_t<int>(), assembled);
  auto types = get(CGAL::dynamic_face_property_t<int>(), assembled);
  auto seams = get(CGAL::dynamic_vertex_property_t<int>(), assembled);
  const MPM::Assembly_result assembly =
    MPM::assemble(model, MPM::part_graph_of_example(model), assembled, nodes, MPM::Assembly_options(),
                  MPM::parameters::face_part_type_map(types).vertex_is_seam_map(seams));
  std::vector<int> faces_of_type(model.types.size(), 0);
  for(auto f : faces(assembled)) ++faces_of_type[std::size_t(get(types, f))];
  int seam_vertices = 0;
  for(vertex_descriptor v : vertices(assembled)) seam_vertices += get(seams, v) ? 1 : 0;

  // The last part type's shape two standard deviations along its first
  // mode (the legs vary; the one body does not), as a mesh of its own; its
  // seams are where it docks.
  const int type = int(model.types.size()) - 1;
  const MPM::Shape_space& space = model.types[std::size_t(type)].space;
  Eigen::VectorXd along_first_mode = Eigen::VectorXd::Zero(space.number_of_modes());
  if(space.number_of_modes() > 0) along_first_mode[0] = 2. * std::sqrt(space.variances[0]);
  Mesh part;
  auto part_seams = get(CGAL::dynamic_vertex_property_t<int>(), part);
  MPM::copy_part_shape(model, type, along_first_mode, part, MPM::parameters::vertex_is_seam_map(part_seams));
  int part_seam_vertices = 0;
  for(vertex_descriptor v : vertices(part)) part_seam_vertices += get(part_seams, v) ? 1 : 0;

  std::cout << name << ": " << cut.regions << " parts, " << model.types.size() << " part types; deformed in "
            << deformed.report.iterations << " iterations (highest vertex now at y = " << get(vpm, high).y()
            << "); assembled " << num_vertices(assembled) << " vertices (" << seam_vertices << " on seams), "
            << num_faces(assembled) << " faces (";
  for(std::size_t t = 0; t < faces_of_type.size(); ++t)
    std::cout << (t ? ", " : "") << faces_of_type[t] << " " << model.types[t].name;
  std::cout << "), energy per part " << assembly.energy_per_part() << "; " << model.types[std::size_t(type)].name
            << " at +2 sigma on its first mode: " << num_vertices(part) << " vertices (" << part_seam_vertices
            << " on seams)\n";
}

int main(int argc, char** argv)
{
  if(argc != 4) {
    std::cerr << "usage: " << argv[0] << " mesh.off cuts.json annotation.json\n";
    return 1;
  }
  try {
    const MPM::Cut_specification cuts = MPM::read_cut_specification(argv[2]);
    const MPM::Annotation annotation = MPM::read_annotation(argv[3]);
    run<CGAL::Surface_mesh<Kernel::Point_3>>("Surface_mesh", argv[1], cuts, annotation);
    run<CGAL::Polyhedron_3<Kernel>>("Polyhedron_3", argv[1], cuts, annotation);
#ifdef MPM_HAS_OPENMESH
    run<OpenMesh::TriMesh_ArrayKernelT<>>("OpenMesh", argv[1], cuts, annotation);
#endif
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
