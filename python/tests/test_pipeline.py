# The whole pipeline from Python: synthesize, cut, propose, learn from
# several meshes, fit, edit, assemble, spawn, compare, on synthetic and
# real segmented meshes.
import os

import numpy as np
import pytest

import cgal_mpm as mpm


def diagonal(V):
    return np.linalg.norm(np.ptp(V, axis=0))


def test_edits_keep_the_hand_whole(hand_model):
    rest = hand_model.examples[0]
    for V, report in (mpm.symmetrize(hand_model), mpm.caricature(hand_model, 1.5)):
        assert report["converged"] and V.shape == rest["V"].shape
        check = mpm.check_surface(V, rest["F"], reference_V=rest["V"], groups=rest["labels"])
        assert check["components"] == 1 and check["border_edges"] == 0 and check["inverted_faces"] == 0


def test_held_out_pose_is_reached_better_than_by_the_baselines(hand, hand_model, pose_handles):
    truth = hand.draw_pose(7)
    errors = {}
    for method in ("mpm", "arap", "laplacian"):
        V, _ = mpm.deform_with(method, hand_model, *pose_handles)
        errors[method] = np.sqrt(((V - truth) ** 2).sum(axis=1).mean()) / diagonal(truth)
    assert errors["mpm"] < errors["arap"] and errors["mpm"] < errors["laplacian"]
    assert errors["mpm"] < 0.02


def test_learning_from_several_meshes_pools_the_instances(hand):
    other = mpm.synthesize("hand", seed=2, vertices=3000)
    model = mpm.learn([hand, other])
    assert len(model.examples) == 2
    assert model.types[model.find_type("middle")]["instances"] == 10


def test_fit_recovers_a_pose_of_the_training_shape(hand, hand_model):
    V = hand.draw_pose(3)
    fit = mpm.fit(hand_model, V, hand.F, hand.labels)
    assert len(fit["segments"]) == 16 and not fit["skipped"]
    assert fit["rms_over_mesh_diagonal"] < 0.01
    fitted_V, fitted_F, fitted_labels = fit["fitted_surface"]
    assert fitted_F.max() < len(fitted_V) and len(fitted_labels) == len(fitted_F)


def test_assembly_grows_a_finger_seamlessly(hand_model):
    model = mpm.Model.from_bytes(hand_model.to_bytes())
    added = mpm.add_repetition_rules(model)
    assert added
    graph = mpm.part_graph(model)
    edge = next(i for i, e in enumerate(graph.edges)
                if graph.node_types(model)[e["first"]]["type"] == "proximal"
                and graph.node_types(model)[e["second"]]["type"] == "middle")
    node = mpm.insert_segment(model, graph, edge)
    assert node == 16 and len(graph.nodes) == 17
    seen = []
    result = mpm.assemble(model, graph, callback=lambda i, e: seen.append(i))
    assert result["converged"] and result["V"].shape[0] > model.examples[0]["V"].shape[0]
    assert seen == list(range(1, result["iterations"] + 1))
    check = mpm.check_surface(result["V"], result["F"])
    assert check["components"] == 1 and check["border_edges"] == 0
    spawned = mpm.spawn(model, mpm.part_graph(model), count=3, seed=4)
    energies = [s["assembly"]["energy_per_part"] for s in spawned]
    assert len(spawned) == 3 and energies == sorted(energies)


def test_bridging_rules_let_a_finger_lose_a_segment(hand_model):
    model = mpm.Model.from_bytes(hand_model.to_bytes())
    graph = mpm.part_graph(model)
    middle = next(i for i, t in enumerate(graph.node_types(model)) if t["type"] == "middle")
    with pytest.raises(mpm.InputError):
        mpm.remove_segment(model, graph, middle)
    assert mpm.add_bridging_rules(model)
    assert not mpm.add_bridging_rules(model)
    mpm.remove_segment(model, graph, middle)
    result = mpm.assemble(model, graph)
    assert result["converged"] and result["V"].shape[0] < model.examples[0]["V"].shape[0]
    check = mpm.check_surface(result["V"], result["F"])
    assert check["components"] == 1 and check["border_edges"] == 0


def test_a_removed_finger_leaves_a_capped_palm(hand_model):
    model = mpm.Model.from_bytes(hand_model.to_bytes())
    graph = mpm.part_graph(model)
    root = mpm.root_node(graph)
    finger = next(e["second"] if e["first"] == root else e["first"] for e in graph.edges
                  if root in (e["first"], e["second"]))
    mpm.remove_branch(model, graph, finger, root)
    open_result = mpm.assemble(model, graph)
    assert mpm.check_surface(open_result["V"], open_result["F"])["border_edges"] > 0
    capped = mpm.assemble(model, graph, cap_free_sites=True)
    check = mpm.check_surface(capped["V"], capped["F"])
    assert check["components"] == 1 and check["border_edges"] == 0
    assert len(capped["F"]) > len(open_result["F"]) and len(capped["face_nodes"]) == len(capped["F"])


def test_cut_then_propose_then_learn(hand):
    # Cut the synthetic hand's finger tips off along their seams: a cut
    # through the vertices a tip shares with its middle segment.
    F, labels = hand.F, hand.labels
    tip = hand.instances[-1]
    tip_vertices = set(F[labels == tip["label"]].ravel())
    seam = [v for v in tip_vertices if (labels[(F == v).any(axis=1)] != tip["label"]).any()]
    result = mpm.cut(hand.V, F, [seam[:: max(1, len(seam) // 4)]])
    assert result["regions"] == 2 and len(result["lengths"]) == 1
    proposal = mpm.propose_part_types(hand.V, F, hand.labels)
    assert proposal["root"] == 0 and len(proposal["segments"]) == 16
    assert {s["type"] for s in proposal["segments"]} >= {"root", "tip3"}


def test_a_real_segmented_hand(psb_dir):
    V, F, labels = mpm.read_labeled_mesh(os.path.join(psb_dir, "hand_181.off"), os.path.join(psb_dir, "hand_181.seg"))
    proposal = mpm.propose_part_types(V, F, labels)
    model = mpm.learn((V, F, labels))  # types proposed as by `mpm learn`
    assert sorted(t["name"] for t in model.types) == sorted({s["type"] for s in proposal["segments"]})
    rest = model.examples[0]
    vertices, targets = mpm.handles_per_part(model, 1)
    targets[-1] += 0.05 * diagonal(rest["V"])
    V2, report = mpm.deform(model, vertices, targets)
    assert report["converged"]
    check = mpm.check_surface(V2, rest["F"])
    assert check["components"] == 1 and check["border_edges"] == 0
    assert np.linalg.norm(V2[vertices[-1]] - targets[-1]) < 0.01 * diagonal(rest["V"])


def test_cut_at_joints_from_a_raw_scan(psb_dir):
    # No labels given: the proposed joints cut the octopus's eight arms off its
    # body, and a click at one proposal gives the same cut back.
    V, F, _ = mpm.read_labeled_mesh(os.path.join(psb_dir, "octopus_126.off"), "components")
    proposal = mpm.cut_at_proposed_joints(V, F)
    assert proposal["limbs"] == 8
    bases = [j for j in proposal["joints"] if j["at_base"]]
    assert len(bases) == 8
    assert len(np.unique(proposal["labels"])) == len(proposal["cuts"]) + 1
    first = proposal["cuts"][0]
    again = mpm.cut_at_vertices(V, F, [first["vertex"]])
    assert len(again["cuts"]) == 1 and again["cuts"][0]["vertex"] == first["vertex"]
    assert abs(again["cuts"][0]["length"] - first["length"]) < 0.05 * first["length"]
    with pytest.raises(ValueError, match="sensitivity"):
        mpm.cut_at_proposed_joints(V, F, sensitivity=2.0)
