# Shared fixtures of the cgal_mpm test suite. Run by ctest (`python_tests`),
# which puts the built module on PYTHONPATH and names the C++ reference
# program (MPM_PYTHON_REFERENCE) and the segmented meshes (MPM_PSB_DIR).
import json
import os
import subprocess

import numpy as np
import pytest

import cgal_mpm as mpm

# Small enough for a fast suite, large enough for every part to have modes.
HAND_VERTICES = 3000
POSE_SEED = 7


@pytest.fixture(scope="session")
def hand():
    return mpm.synthesize("hand", vertices=HAND_VERTICES)


@pytest.fixture(scope="session")
def hand_model(hand):
    return mpm.learn(hand)


@pytest.fixture(scope="session")
def pose_handles(hand, hand_model):
    """One handle per part, pulled to a held-out pose of the hand."""
    return mpm.handles_per_part(hand_model, 1, targets=hand.draw_pose(POSE_SEED))


@pytest.fixture(scope="session")
def reference():
    """Runs the C++ reference program and parses its JSON."""
    program = os.environ.get("MPM_PYTHON_REFERENCE")
    if not program or not os.path.exists(program):
        pytest.skip("MPM_PYTHON_REFERENCE does not name the built mpm_python_reference program")

    def run(*args):
        out = subprocess.run([program, *map(str, args)], check=True, capture_output=True, text=True).stdout
        return json.loads(out)

    return run


@pytest.fixture(scope="session")
def psb_dir():
    d = os.environ.get("MPM_PSB_DIR", "")
    if not d or not os.path.exists(os.path.join(d, "hand_181.off")):
        pytest.skip("the segmented PSB meshes are absent (MPM_PSB_DIR=%r)" % d)
    return d


def relative_difference(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = max(np.abs(b).max(initial=0.0), 1e-300)
    return np.abs(a - b).max(initial=0.0) / scale
