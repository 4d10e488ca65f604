# The module computes what the C++ API computes: the same learned shape
# spaces and the same deformation, entry by entry, on the synthetic hand.
import numpy as np

import cgal_mpm as mpm
from conftest import HAND_VERTICES, POSE_SEED, relative_difference


def test_learned_shape_spaces_equal_the_cpp_ones(hand_model, reference):
    cpp = reference("hand", HAND_VERTICES, POSE_SEED)
    types = hand_model.types
    assert [t["name"] for t in types] == [t["name"] for t in cpp["types"]]
    for t, c in zip(types, cpp["types"]):
        assert t["modes"].size == len(c["modes"]), t["name"]
        if c["sigmas"]:
            assert relative_difference(t["sigmas"], c["sigmas"]) <= 1e-12, t["name"]
            assert relative_difference(t["modes"].ravel(), c["modes"]) <= 1e-12, t["name"]
        assert relative_difference(t["mean"].ravel(), c["mean"]) <= 1e-12, t["name"]
    # The hand's fingers vary: the test compares modes, not empty arrays.
    assert sum(t["modes_kept"] for t in types) >= 6


def test_deformation_equals_the_cpp_one(hand_model, pose_handles, reference):
    cpp = reference("hand", HAND_VERTICES, POSE_SEED)
    vertices, targets = pose_handles
    assert vertices.tolist() == cpp["handles"]
    editor = mpm.Editor(hand_model)
    editor.set_handles(vertices, targets)
    report = editor.solve()
    assert report["iterations"] == cpp["iterations"]
    assert relative_difference(report["energies"], cpp["energies"]) <= 1e-12
    positions = editor.positions
    assert relative_difference(positions.ravel(), cpp["positions"]) <= 1e-12
    # The edit moved the hand: equal results are not two copies of the rest.
    assert np.abs(positions - editor.rest_V).max() > 1e-3 * np.ptp(editor.rest_V, axis=0).max()
