"""Learn a real segmented mesh with proposed part types and edit it.

A mesh of the Princeton Segmentation Benchmark (a scanned hand, octopus or
ant with a person's segmentation, see ../shared/data/psb/README.md):
    PYTHONPATH=build/python python3 examples/python/real_mesh.py \
        ../shared/data/psb/hand_181.off ../shared/data/psb/hand_181.seg [out_dir]
"""
import sys
import numpy as np
import cgal_mpm as mpm

mesh_path, labels_path = sys.argv[1], sys.argv[2]
out = sys.argv[3] if len(sys.argv) > 3 else "."
V, F, labels = mpm.read_labeled_mesh(mesh_path, labels_path)
print("%s: %d vertices, %d faces, %d segments" % (mesh_path, len(V), len(F), len(np.unique(labels))))

# Nobody annotated the mesh: part types come from the segment graph.
proposal = mpm.propose_part_types(V, F, labels)
for s in proposal["segments"]:
    print("  segment %2d  %-14s depth %d, %d seam loops, area %.4g" % (s["label"], s["type"], s["depth"], s["seam_loops"], s["area"]))
model = mpm.learn((V, F, labels), proposal["annotation"])
print(model)

# Symmetrize: instances of a type pulled towards one shape, seams kept closed.
rest = model.examples[0]
symmetric, report = mpm.symmetrize(model)
check = mpm.check_surface(symmetric, rest["F"], reference_V=rest["V"], groups=rest["labels"])
print("symmetrized in %d iterations (converged: %s); %d component(s), %d open edges, %d faces turned inside out"
      % (report["iterations"], report["converged"], check["components"], check["border_edges"], check["inverted_faces"]))
mpm.write_mesh(out + "/symmetrized.off", symmetric, rest["F"])

# Lengthen a chain (a finger, an arm) by one segment: the repetition rules
# dock a chain segment to a copy of itself.
mpm.add_repetition_rules(model)
graph = mpm.part_graph(model)
nodes = graph.node_types(model)
edge = next(i for i, e in enumerate(graph.edges)
            if nodes[e["first"]]["type"].startswith("chain") and nodes[e["second"]]["type"].startswith("chain"))
mpm.insert_segment(model, graph, edge)
assembled = mpm.assemble(model, graph)
check = mpm.check_surface(assembled["V"], assembled["F"])
print("inserted a segment into edge %d: %d parts, converged: %s, %d component(s), %d open edges"
      % (edge, len(graph.nodes), assembled["converged"], check["components"], check["border_edges"]))
mpm.write_mesh(out + "/longer.off", assembled["V"], assembled["F"])
