# Bad input raises ValueError (InputError for what the library checks) with
# a message naming the argument and the element; the interpreter survives.
import numpy as np
import pytest

import cgal_mpm as mpm


def triangle():
    return np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]]), np.array([[0, 1, 2]])


@pytest.mark.parametrize("V,message", [
    (np.zeros((3, 2)), r"V: expected a float64 array of shape \(n, 3\), got an array of dtype float64 and shape \(3, 2\)"),
    (np.zeros(9), r"shape \(9,\)"),
    (np.array([["a", "b", "c"]] * 3), "dtype <U1"),
    (np.zeros((3, 3), dtype=complex), "dtype complex128"),
    ([[0, 0, 0], [1, 0], [0, 1, 0]], "V: expected"),
])
def test_wrong_vertex_arrays(V, message):
    with pytest.raises(ValueError, match=message):
        mpm.connected_components(V, triangle()[1])


@pytest.mark.parametrize("F,message", [
    (np.array([[0, 1, 2.0]]), r"F: expected an int32 or int64 array of shape \(m, 3\), got an array of dtype float64"),
    (np.array([[0, 1]]), r"shape \(1, 2\)"),
    (np.array([[0, 1, 3]]), r"F: face 0: vertex index 3 is out of range \[0, 3\)"),
    (np.array([[0, -1, 2]]), "F: face 0: vertex index -1 is out of range"),
])
def test_wrong_face_arrays(F, message):
    with pytest.raises(ValueError, match=message):
        mpm.connected_components(triangle()[0], F)


def test_non_finite_coordinates_name_the_vertex():
    V, F = triangle()
    V[2, 1] = np.nan
    with pytest.raises(ValueError, match=r"V: row 2: coordinate 1 is not finite \(nan\)"):
        mpm.connected_components(V, F)
    V[2, 1] = np.inf
    with pytest.raises(ValueError, match="row 2: coordinate 1 is not finite"):
        mpm.learn((V, F, [0]))


def test_label_arrays(hand):
    with pytest.raises(ValueError, match="labels: has 6007 entries, expected 6008"):
        mpm.learn((hand.V, hand.F, hand.labels[:-1]))
    with pytest.raises(ValueError, match="labels: expected a one-dimensional integer array"):
        mpm.learn((hand.V, hand.F, hand.labels.astype(float)))
    bad = hand.labels.copy()
    bad[5] = -2
    with pytest.raises(ValueError, match="labels: entry 5: -2 is out of range"):
        mpm.learn((hand.V, hand.F, bad))


def test_library_errors_are_input_errors_with_the_cpp_message(hand, tmp_path):
    missing = str(tmp_path / "missing.off")
    with pytest.raises(mpm.InputError, match="missing.off") as error:
        mpm.read_mesh(missing)
    assert isinstance(error.value, ValueError)
    # A segment that is not connected: the library's message names it.
    labels = hand.labels.copy()
    labels[labels == 3] = 1
    with pytest.raises(mpm.InputError, match="segment 1"):
        mpm.propose_part_types(hand.V, hand.F, labels)
    with pytest.raises(mpm.InputError, match=r"annotation.*parts\[0\]\.label"):
        mpm.learn(hand, annotations={"parts": [{"label": -1, "type": "x"}]})


def test_editor_arguments(hand_model):
    editor = mpm.Editor(hand_model)
    with pytest.raises(ValueError, match="targets: has 1 rows for 2 handle vertices"):
        editor.set_handles([0, 1], [[0.0, 0, 0]])
    with pytest.raises(ValueError, match=r"vertices: entry 0: 99999999 is out of range \[0, 3006\)"):
        editor.set_handles([99999999], [[0.0, 0, 0]])
    with pytest.raises(mpm.InputError, match="handles: handle 1: vertex 4 has two handles"):
        editor.set_handles([4, 4], [[0.0, 0, 0], [0, 0, 0]])
    with pytest.raises(ValueError, match="targets: row 0: coordinate 2 is not finite"):
        editor.set_handles([4], [[0.0, 0, np.nan]])
    with pytest.raises(ValueError, match="set_handles"):
        editor.move_handles([[0.0, 0, 0]])
    with pytest.raises(ValueError, match='unknown solver option "tolerence"'):
        mpm.Editor(hand_model, tolerence=1e-3)
    with pytest.raises(ValueError, match='global_step: unknown value "fast"'):
        mpm.Editor(hand_model, global_step="fast")
    with pytest.raises(ValueError, match="example: 3 does not exist"):
        mpm.Editor(hand_model, example=3)
    with pytest.raises(ValueError, match="the caricature edit needs a factor"):
        mpm.Editor(hand_model, edit="caricature")
    with pytest.raises(IndexError):
        editor.coordinates(10000)


def test_a_raising_callback_stops_the_computation_and_its_exception_comes_back(hand, hand_model, pose_handles):
    editor = mpm.Editor(hand_model)
    editor.set_handles(*pose_handles)
    calls = []

    def stop(iteration, energy):
        calls.append(iteration)
        raise KeyboardInterrupt("stop after one iteration")

    with pytest.raises(KeyboardInterrupt, match="stop after one iteration"):
        editor.solve(callback=stop)
    assert calls == [1]
    assert editor.solve()["converged"]  # the editor is still usable

    def fail(stage, fraction):
        raise RuntimeError("no learning today")

    with pytest.raises(RuntimeError, match="no learning today"):
        mpm.learn(hand, progress=fail)
