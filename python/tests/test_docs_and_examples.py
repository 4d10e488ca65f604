# Every function, class, method and property of the module says what it
# does, and the example scripts of examples/python run.
import inspect
import os
import subprocess
import sys

import pytest

import cgal_mpm as mpm


def described(obj):
    doc = inspect.getdoc(obj) or ""
    # pybind11 puts the signatures first; a description must follow them.
    name = getattr(obj, "__name__", "?")
    text = "\n".join(line for line in doc.splitlines()
                     if not line.startswith(name + "(") and not line.startswith("Overloaded function"))
    return len(text.strip()) >= 15


def public(names):
    return [n for n in names if not n.startswith("_")]


def test_every_function_and_class_has_a_docstring():
    missing = []
    for name in public(dir(mpm)):
        obj = getattr(mpm, name)
        if not described(obj):
            missing.append(name)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            for member in public(vars(obj)):
                attribute = getattr(obj, member)
                if not described(attribute):
                    missing.append(name + "." + member)
    assert not missing, "no docstring: " + ", ".join(missing)
    assert "Learns a morphable part model" in mpm.learn.__doc__


def run_example(script, *args, tmp_path):
    source = os.environ.get("MPM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, os.path.join(source, "examples", "python", script), *args, str(tmp_path)],
                          check=True, capture_output=True, text=True, env=env).stdout


def test_learn_and_drag_example(tmp_path):
    out = run_example("learn_and_drag.py", tmp_path=tmp_path)
    assert "converged: True" in out
    assert (tmp_path / "dragged_hand.ply").exists()


def test_real_mesh_example(psb_dir, tmp_path):
    out = run_example("real_mesh.py", os.path.join(psb_dir, "hand_181.off"), os.path.join(psb_dir, "hand_181.seg"),
                      tmp_path=tmp_path)
    assert "1 component(s), 0 open edges" in out and "17 parts, converged: True" in out
