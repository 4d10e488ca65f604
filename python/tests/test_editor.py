# The Editor keeps a prefactored solver: repeated drags from Python, with
# per-iteration energies, without leaks, and without holding the GIL.
import sys
import threading
import time

import numpy as np

import cgal_mpm as mpm


def resident_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def drag(editor, targets, frame, step):
    targets[0] += (1 if (frame // 10) % 2 == 0 else -1) * step
    editor.move_handles(targets)
    report = editor.solve()
    return editor.positions, report


def test_energies_decrease_and_each_iteration_is_reported(hand_model, pose_handles):
    editor = mpm.Editor(hand_model)
    editor.set_handles(*pose_handles)
    seen = []
    report = editor.solve(callback=lambda i, e: seen.append((i, e)))
    assert [i for i, _ in seen] == list(range(1, report["iterations"] + 1))
    energies = report["energies"]
    assert len(energies) == report["iterations"] and report["converged"]
    # Every energy but the last comes from the reduced solver's blocks and
    # never rises; the last is evaluated at the positions (a sum of another
    # rounding, see Solve_report).
    assert (np.diff(energies[:-1]) <= 0).all()
    assert np.allclose([e for _, e in seen][:-1], energies[:-1], rtol=1e-12)
    # Converged to the tolerance: solving on lowers the energy by less.
    assert energies[-1] - editor.solve()["energies"][-1] <= 1e-6 * energies[-1]


def test_moving_targets_gives_what_a_new_solver_gives(hand_model, pose_handles):
    vertices, targets = pose_handles
    editor = mpm.Editor(hand_model)
    editor.set_handles(vertices, targets * 0 + editor.rest_V[vertices])
    editor.solve()
    editor.move_handles(targets)
    editor.reset()
    editor.solve()
    fresh, _ = mpm.deform(hand_model, vertices, targets, unfold=False)
    assert np.abs(editor.positions - fresh).max() <= 1e-9 * np.ptp(fresh, axis=0).max()


def test_predicted_rotations_land_where_plain_drags_land_in_fewer_iterations(hand_model, pose_handles):
    vertices, targets = pose_handles
    predicted, plain = mpm.Editor(hand_model), mpm.Editor(hand_model, predict_rotations=False)
    start = targets * 0 + predicted.rest_V[vertices]
    predicted.set_handles(vertices, start.copy())
    plain.set_handles(vertices, start.copy())
    step = 0.004 * np.ptp(predicted.rest_V, axis=0).max()
    moved = start.copy()
    iterations = {"predicted": 0, "plain": 0}
    for frame in range(8):
        a, report_a = drag(predicted, moved.copy(), 0, 0.0)
        b, report_b = drag(plain, moved.copy(), 0, 0.0)
        assert report_a["converged"] and report_b["converged"]
        assert np.abs(a - b).max() <= 1e-4 * np.ptp(b, axis=0).max()
        if frame >= 2:
            iterations["predicted"] += report_a["iterations"]
            iterations["plain"] += report_b["iterations"]
        moved[0] += step
    assert iterations["predicted"] < iterations["plain"]


def test_a_thousand_drags_do_not_leak(hand_model):
    vertices, targets = mpm.handles_per_part(hand_model, 1)
    editor = mpm.Editor(hand_model)
    editor.set_handles(vertices, targets)
    targets = targets.copy()
    step = 0.01 * np.linalg.norm(np.ptp(editor.rest_V, axis=0)) / np.sqrt(3.0)
    for frame in range(100):
        drag(editor, targets, frame, step)
    before = resident_bytes()
    iterations = 0
    for frame in range(100, 1100):
        positions, report = drag(editor, targets, frame, step)
        iterations += report["iterations"]
    grown = resident_bytes() - before
    # One leaked position array per drag would be 72 kB x 1000.
    assert grown < 4 * 2**20, "resident memory grew by %d bytes over 1000 drags" % grown
    assert iterations >= 1000 and np.isfinite(positions).all()


def test_the_gil_is_released_while_solving(hand_model, pose_handles):
    # With a switch interval far longer than the solve, another thread runs
    # during it only if the solve let go of the GIL.
    editor = mpm.Editor(hand_model, global_step="direct")
    editor.set_handles(*pose_handles)
    started = threading.Event()
    times = {}

    def solve():
        started.set()
        editor.solve()
        times["solve_done"] = time.perf_counter()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(60.0)
    try:
        worker = threading.Thread(target=solve)
        worker.start()
        started.wait()
        times["main_ran"] = time.perf_counter()
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert times["main_ran"] < times["solve_done"]


def test_cancel_from_another_thread(hand_model, pose_handles):
    editor = mpm.Editor(hand_model, global_step="direct", max_iterations=10000, tolerance=0)
    editor.set_handles(*pose_handles)
    outcome = {}

    def solve():
        try:
            editor.solve()
            outcome["result"] = "finished"
        except mpm.Cancelled as error:
            outcome["result"] = str(error)

    worker = threading.Thread(target=solve)
    worker.start()
    time.sleep(0.2)
    editor.cancel()
    worker.join(timeout=60)
    assert outcome["result"] == "solve cancelled"
