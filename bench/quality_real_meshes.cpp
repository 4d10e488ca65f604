// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quality_real_meshes: learns a model from every segmented mesh of a
// directory (NAME.off + NAME.seg; part types proposed from the segmentation,
// or from NAME.json in --annotations)
// and checks what the user would see: is the learned example one closed
// surface like the input, do symmetrize, caricature and a drag of every
// tip converge with closed seams and no flipped faces, do segments keep
// their length. Prints a Markdown table.
#include <CGAL/MPM/IO/Annotation_io.h>
#include <CGAL/MPM/Assembly/Assembly.h>
#include <CGAL/MPM/Assembly/Free_site_capping.h>
#include <CGAL/MPM/Assembly/Part_graph_editing.h>
#include <CGAL/MPM/IO/Part_graph_io.h>
#include <CGAL/MPM/Editing/Editing.h>
#include <CGAL/MPM/Editing/Limb_bending.h>
#include <CGAL/MPM/Solver/Embedding_solver.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/IO/Mesh_io.h>
#include <CGAL/MPM/Model/Part_adjacency_graph.h>
#include <CGAL/MPM/Learning/Part_type_proposal.h>
#include <CGAL/MPM/Editing/Surface_soundness.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include "quality_common.h"
#include <CGAL/MPM/internal/Bounding_box.h>
#include <CGAL/MPM/internal/Edge_graph_distance.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iterator>

namespace {

using namespace CGAL::MPM;

struct Edit_result
{
  bool converged = false;
  int iterations = 0;
  Surface_soundness soundness;
  int inverted_before_unfolding = 0; // in the solver's result, before unfold_faces()
  int new_inverted = 0;      // faces inside out within their part that were not folded at rest
  int unfolded = 0;          // inverted against the rest because the edit unfolded a rest fold
  int new_folds = 0;         // written faces folded over their neighbourhood, not folded at rest
  int new_self_intersections = 0;
  double drift = 0.; // largest move in ten more iterations after the solve, over the diagonal
  double worst_length_change = 0.; // largest |length / rest length - 1| of a part
  int parts_outside_range = 0;     // parts whose length leaves their type's range (+-10%)
  double worst_stretch = 0.;       // the same for the length along the surface
  int parts_stretched_outside_range = 0;
};

// Extent of a point set along its principal axis: a segment's length.
double length_of(const Point_matrix& p)
{
  const Point_matrix c = p.rowwise() - p.colwise().mean();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(c.transpose() * c);
  const Eigen::VectorXd along = c * eig.eigenvectors().col(2);
  return along.maxCoeff() - along.minCoeff();
}

Point_matrix rows(const Point_matrix& p, const std::vector<int>& v, std::size_t n)
{
  Point_matrix r(n, 3);
  for(std::size_t i = 0; i < n; ++i) r.row(i) = p.row(v[i]);
  return r;
}

// A segment's length along its surface: the shortest path along its edges
// between the ends of its longest such path at rest (found by two sweeps),
// measured at `positions`. Bending a segment leaves it as it is, as a
// finger's skin keeps its length when the finger curls; stretching does not.
// The extent along the principal axis (`length_of()`) shortens when a long,
// curling part (an octopus arm) bends.
double surface_length(const Point_matrix& rest, const Point_matrix& positions, const Part_node& node,
                      const Part_type& type)
{
  const std::size_t n = type.number_of_vertices;
  const std::vector<Cluster_edge> edges = internal::mesh_edges(type.triangles);
  const auto farthest = [&](int from) {
    const std::vector<double> d = internal::edge_graph_distances(rows(rest, node.vertices, n), edges, {from});
    int f = from;
    for(std::size_t v = 0; v < d.size(); ++v)
      if(std::isfinite(d[v]) && d[v] > d[std::size_t(f)]) f = int(v);
    return f;
  };
  const int a = farthest(farthest(0));
  const int b = farthest(a);
  return internal::edge_graph_distances(rows(positions, node.vertices, n), edges, {a})[std::size_t(b)];
}

Edit_result evaluate(const Morphable_part_model& model, const Embedding_problem& problem, Embedding_solver& solver,
                     const Surface_soundness& rest, const std::vector<int>& folded_at_rest, const std::vector<int>& held)
{
  Edit_result r;
  const Solve_report report = solver.solve();
  r.converged = report.converged;
  r.iterations = report.iterations;
  Indexed_mesh after = problem.mesh;
  const std::vector<int> labels = to_labeled_mesh(model.examples.front()).face_labels;
  r.inverted_before_unfolding =
    static_cast<int>(inverted_faces(Indexed_mesh{solver.positions(), problem.mesh.triangles}, problem.mesh,
                                    &labels).size());
  // What the user gets, as `mpm` writes it: the folds taken out.
  after.points = unfold_faces(problem.mesh, solver.positions(), held);
  r.soundness = check_surface(after, &problem.mesh, &labels);
  for(int f : inverted_faces(after, problem.mesh, &labels))
    ++(std::binary_search(folded_at_rest.begin(), folded_at_rest.end(), f) ? r.unfolded : r.new_inverted);
  for(int f : locally_inverted_faces(after, problem.mesh))
    r.new_folds += !std::binary_search(folded_at_rest.begin(), folded_at_rest.end(), f);
  r.new_self_intersections = std::max(0, r.soundness.self_intersections - std::max(0, rest.self_intersections));
  const Training_example& ex = model.examples.front();
  // Per measure of length, per type: the range of rest lengths.
  const auto check_lengths = [&](const auto& length, double& worst, int& outside) {
    std::map<int, std::pair<double, double>> range;
    for(const Part_node& node : ex.graph.nodes)
    {
      const double l = length(problem.mesh.points, node);
      auto [it, added] = range.insert({node.type, {l, l}});
      it->second = {std::min(it->second.first, l), std::max(it->second.second, l)};
    }
    for(const Part_node& node : ex.graph.nodes)
    {
      const double before = length(problem.mesh.points, node), now = length(after.points, node);
      worst = std::max(worst, std::abs(now / before - 1.));
      const auto [low, high] = range.at(node.type);
      outside += now < low / 1.1 || now > high * 1.1;
    }
  };
  check_lengths([&](const Point_matrix& p, const Part_node& node) {
    return length_of(rows(p, node.vertices, model.types[node.type].number_of_vertices));
  }, r.worst_length_change, r.parts_outside_range);
  check_lengths([&](const Point_matrix& p, const Part_node& node) {
    return surface_length(problem.mesh.points, p, node, model.types[node.type]);
  }, r.worst_stretch, r.parts_stretched_outside_range);
  // Whether the solve has settled: the tolerance is relative to the energy,
  // which says little when the energy is small or large.
  const double diagonal = internal::bounding_box_diagonal(after.points);
  const Point_matrix solved = solver.positions();
  for(int k = 0; k < 10; ++k) solver.iterate();
  r.drift = (solver.positions() - solved).rowwise().norm().maxCoeff() / diagonal;
  return r;
}

// A segment inserted before the tip of every chain (the edge from a tip
// to its neighbour): how many insertions gave one closed surface, the
// largest residual energy per part among them, how many faces of an
// inserted segment cross another part (one lying on top of an existing
// segment crosses it everywhere), and why any failed.
bool one_closed_surface(const Indexed_mesh& mesh)
{
  const Surface_soundness s = check_surface(mesh);
  return s.components == 1 && s.border_edges == 0 && s.non_manifold_edges == 0;
}

struct Insertions
{
  int tried = 0, closed = 0;
  double worst_energy_per_part = 0.;
  int crossings = 0;
  std::string failure;
};

Insertions insert_into_every_chain(Morphable_part_model model)
{
  Insertions r;
  add_repetition_rules(model);
  const Part_graph example = part_graph_of_example(model, 0);
  const Part_adjacency_graph g = adjacency_graph(example);
  const auto degree = [&](int node) { return boost::out_degree(node, g); };
  for(std::size_t k = 0; k < example.edges.size(); ++k)
  {
    // A chain: a tip docked to a segment that docks to one more part (the
    // abdomen of an ant, docked to the thorax alone, is no chain).
    const Part_edge& e = example.edges[k];
    const bool chain = (degree(e.first) == 1 && degree(e.second) == 2) || (degree(e.second) == 1 && degree(e.first) == 2);
    if(!chain) continue;
    ++r.tried;
    try
    {
      Part_graph graph = example;
      const int inserted = insert_segment(model, graph, int(k));
      choose_segment_shape(model, graph, inserted);
      const Assembly a = assemble(model, graph);
      if(one_closed_surface(a.mesh)) ++r.closed;
      r.crossings += crossings_of_node(a, inserted);
      r.worst_energy_per_part = std::max(r.worst_energy_per_part, a.energy_per_part());
    }
    catch(const std::exception& error)
    {
      r.failure += std::string(r.failure.empty() ? "" : "; ") + error.what();
    }
  }
  return r;
}

// Every segment removed (a node docked twice, its neighbours bridged) and
// every limb removed with its hole capped, one at a time: how many gave
// one closed surface.
struct Removals
{
  int segments = 0, segments_closed = 0, limbs = 0, limbs_closed = 0;
  std::string failure;
};

Removals remove_every_segment_and_limb(Morphable_part_model model)
{
  Removals r;
  add_bridging_rules(model);
  const Part_graph example = part_graph_of_example(model, 0);
  const Part_adjacency_graph g = adjacency_graph(example);
  const int root = root_node(example);
  for(int node = 0; node < int(example.nodes.size()); ++node)
  {
    if(node == root) continue;
    const bool segment = boost::out_degree(node, g) == 2, limb = boost::edge(node, root, g).second;
    for(const bool whole_limb : {false, true})
    {
      if(!(whole_limb ? limb : segment)) continue;
      ++(whole_limb ? r.limbs : r.segments);
      try
      {
        Part_graph graph = example;
        if(whole_limb) remove_branch(model, graph, node, root);
        else remove_segment(model, graph, node);
        Assembly a = assemble(model, graph);
        cap_free_sites(model, a);
        if(one_closed_surface(a.mesh)) ++(whole_limb ? r.limbs_closed : r.segments_closed);
      }
      catch(const std::exception& error)
      {
        r.failure += std::string(r.failure.empty() ? "" : "; ") + error.what();
      }
    }
  }
  return r;
}

std::string edit_cells(const Edit_result& r)
{
  std::ostringstream s;
  s << (r.converged ? "yes " : "no ") << r.iterations << " | " << std::setprecision(2) << 100. * r.drift << " | "
    << r.soundness.border_edges << " | "
    << r.soundness.flipped_faces << " | " << r.inverted_before_unfolding << " | " << r.new_inverted << " (" << r.unfolded << ") | " << r.new_folds << " | " << r.new_self_intersections << " | " << std::fixed << std::setprecision(0)
    << 100. * r.worst_length_change << "% (" << r.parts_outside_range << ") | " << 100. * r.worst_stretch << "% ("
    << r.parts_stretched_outside_range << ")";
  return s.str();
}

} // namespace

int main(int argc, char** argv)
{
  const mpm_quality::Options options(
    argc, argv, {{"data", "../shared/data/psb"}, {"annotations", ""}, {"meshes", ""}},
    "usage: quality_real_meshes [--data DIR] [--annotations DIR] [--meshes a,b,...]\n"
    "Learns every DIR/NAME.off with DIR/NAME.seg (part types proposed, or from ANNOTATIONS/NAME.json)\n"
    "and prints the soundness of the learned example and of symmetrize, caricature and a tip drag.\n");
  const std::vector<std::string> names = options.meshes();
  std::cout << "| mesh | types (corresponded) | learn s | example pieces | open edges | folded faces | new self-int. | Hausdorff % | "
               "insertions closed / tried (largest energy per part) | faces of inserted segments crossing other parts | segments removed, closed / tried; limbs removed and capped, closed / tried | edit | converged, iterations | moves in 10 more iterations, % diagonal | open edges | turned > 90 deg | inverted in part, solver's result | new inverted in part, written (rest folds unfolded) | new folds, written | new self-int. | "
               "worst length change (parts out of range) | worst change of length along the surface (parts out of range) |\n"
               "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for(const std::string& name : names)
  {
    try
    {
      const std::string base = options.text("data") + "/" + name;
      Training_input input;
      input.mesh = read_labeled_mesh(base + ".off", base + ".seg");
      if(!options.text("annotations").empty())
        input.annotation = read_annotation(options.text("annotations") + "/" + name + ".json");
      else
        input.annotation = propose_part_types(input.mesh).annotation;
      const auto start = std::chrono::steady_clock::now();
      const Morphable_part_model model = learn_morphable_part_model({input});
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const Indexed_mesh learned = to_labeled_mesh(model.examples.front()).mesh;
      const Surface_soundness input_soundness = check_surface(input.mesh.mesh);
      const Surface_soundness rest = check_surface(learned);
      const std::vector<int> folded = folded_faces(learned, input.mesh.mesh),
                             spikes = spike_faces(learned, CGAL_PI / 3., 2);
      std::vector<int> rest_faults;
      std::set_union(folded.begin(), folded.end(), spikes.begin(), spikes.end(), std::back_inserter(rest_faults));
      int corresponded = 0;
      for(const Part_type& t : model.types) corresponded += t.space.number_of_instances() >= 2;
      const Insertions inserted = insert_into_every_chain(model);
      std::ostringstream head;
      head << "| " << name << " | " << model.types.size() << " (" << corresponded << ") | " << std::setprecision(2)
           << seconds << " | " << rest.components << " | "
           << rest.border_edges << " | " << folded.size() << " | "
           << std::max(0, rest.self_intersections - std::max(0, input_soundness.self_intersections)) << " | "
           << std::setprecision(2) << 100. * relative_hausdorff_distance(learned, input.mesh.mesh) << " | "
           << inserted.closed << " / " << inserted.tried << " (" << std::setprecision(2)
           << inserted.worst_energy_per_part << ") | " << inserted.crossings << " | ";
      if(!inserted.failure.empty()) std::cerr << name << ": an insertion failed: " << inserted.failure << "\n";
      const Removals removed = remove_every_segment_and_limb(model);
      head << removed.segments_closed << " / " << removed.segments << "; " << removed.limbs_closed << " / "
           << removed.limbs << " | ";
      if(!removed.failure.empty()) std::cerr << name << ": a removal failed: " << removed.failure << "\n";
      struct Edit
      {
        const char* name;
        Embedding_problem problem;
        bool drag;
      };
      std::vector<Edit> edits;
      edits.push_back({"symmetrize", make_symmetrization_problem(model), false});
      edits.push_back({"caricature 2", make_caricature_problem(model, 2.), false});
      edits.push_back({"tip drag", make_deformation_problem(model), true});
      for(Edit& e : edits)
      {
        Embedding_solver solver(e.problem);
        std::vector<int> held;
        if(e.drag)
        {
          const Handle_set handles = limb_bending_handles(model, 0, 0.1);
          solver.set_handles(handles.vertices, handles.targets);
          held = handles.vertices;
        }
        std::cout << (e.name == edits.front().name ? head.str() : "| | | | | | | | | | | | ") << e.name << " | "
                  << edit_cells(evaluate(model, e.problem, solver, rest, rest_faults, held)) << " |\n"
                  << std::flush;
      }
    }
    catch(const std::exception& error)
    {
      std::cout << "| " << name << " | failed: " << error.what() << " |\n";
    }
  }
  return 0;
}
