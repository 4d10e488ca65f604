# Every array and object crosses the boundary and comes back unchanged.
import pickle

import numpy as np
import pytest

import cgal_mpm as mpm


@pytest.mark.parametrize("extension,binary", [(".off", False), (".obj", False), (".ply", False), (".ply", True),
                                              (".stl", True)])
def test_mesh_files_round_trip(hand, tmp_path, extension, binary):
    path = str(tmp_path / ("hand" + extension))
    mpm.write_mesh(path, hand.V, hand.F, binary=binary)
    V, F = mpm.read_mesh(path)
    assert V.dtype == np.float64 and V.shape == hand.V.shape
    assert F.dtype == np.int32 and F.shape == hand.F.shape
    if extension == ".stl":  # STL stores float32 triangle corners; vertices are merged again
        assert np.abs(V[F] - hand.V[hand.F]).max() < 1e-5
    else:
        assert np.abs(V - hand.V).max() <= 1e-12 * np.abs(hand.V).max()
        assert (F == hand.F).all()


@pytest.mark.parametrize("dtype", [np.int32, np.int64, np.uint32])
def test_faces_and_labels_of_any_integer_type(hand, tmp_path, dtype):
    path = str(tmp_path / "m.off")
    mpm.write_mesh(path, hand.V.astype(np.float32).astype(np.float64), hand.F.astype(dtype))
    labels_path = str(tmp_path / "m.seg")
    mpm.write_labels(labels_path, hand.labels.astype(dtype))
    assert (mpm.read_labels(labels_path) == hand.labels).all()
    V, F, labels = mpm.read_labeled_mesh(path, labels_path)
    assert (F == hand.F).all() and (labels == hand.labels).all()


def test_returned_arrays_own_the_library_buffers(hand):
    # Moved out of C++, not copied: numpy does not own the memory, a capsule does.
    for a in (hand.V, hand.F, hand.labels):
        assert not a.flags["OWNDATA"] and a.base is not None
    assert hand.V.flags["F_CONTIGUOUS"] and hand.F.flags["C_CONTIGUOUS"]


def test_c_and_fortran_ordered_inputs_agree(hand, hand_model):
    components_c = mpm.connected_components(np.ascontiguousarray(hand.V), np.ascontiguousarray(hand.F))
    components_f = mpm.connected_components(np.asfortranarray(hand.V), np.asfortranarray(hand.F))
    assert (components_c == components_f).all() and components_c.max() == 0


def test_annotation_round_trip(hand, tmp_path):
    path = str(tmp_path / "hand.json")
    mpm.write_annotation(path, hand.annotation)
    assert mpm.read_annotation(path) == hand.annotation
    by_label = {p["label"]: p["type"] for p in hand.annotation["parts"]}
    mpm.write_annotation(path, by_label)
    assert {p["label"]: p["type"] for p in mpm.read_annotation(path)["parts"]} == by_label


def test_model_round_trips_through_file_bytes_and_pickle(hand_model, tmp_path):
    path = str(tmp_path / "hand.mpm")
    hand_model.save(path)
    for copy in (mpm.load_model(path), mpm.Model.from_bytes(hand_model.to_bytes()),
                 pickle.loads(pickle.dumps(hand_model))):
        assert copy.to_bytes() == hand_model.to_bytes()
        assert [t["name"] for t in copy.types] == [t["name"] for t in hand_model.types]
        assert np.array_equal(copy.types[1]["modes"], hand_model.types[1]["modes"])


def test_part_graph_round_trips_through_json(hand_model):
    graph = mpm.part_graph(hand_model)
    again = mpm.PartGraph.from_json(graph.to_json(hand_model), hand_model)
    assert again.to_json(hand_model) == graph.to_json(hand_model)
    assert len(again.nodes) == 16 and len(again.edges) == 15
    for a, b in zip(again.nodes, graph.nodes):
        assert a["type_index"] == b["type_index"] and np.allclose(a["coordinates"], b["coordinates"], rtol=0, atol=1e-15)


def test_model_inspection_is_plain_data(hand_model):
    types = hand_model.types
    middle = types[hand_model.find_type("middle")]
    n, d = middle["vertices"], middle["modes_kept"]
    assert middle["mean"].shape == (n, 3) and middle["modes"].shape == (3 * n, d)
    assert middle["sigmas"].shape == (d,) and middle["instance_coordinates"].shape == (d, middle["instances"])
    # Orthonormal modes, decreasing sigmas.
    assert np.abs(middle["modes"].T @ middle["modes"] - np.eye(d)).max() < 1e-10
    assert (np.diff(middle["sigmas"]) <= 0).all()
    rule = hand_model.rules[0]
    assert rule["kind"] == "boundary" and rule["seam"].shape[1] == 2
    assert rule["first"]["type"] in [t["name"] for t in types]
    assert hand_model.parameters["sigma_sub"] > 0
