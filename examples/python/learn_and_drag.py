"""Learn the synthetic hand, drag a finger tip, plot the energy.

Run from the repository root after building:
    PYTHONPATH=build/python python3 examples/python/learn_and_drag.py [out_dir]
"""
import sys
import numpy as np
import cgal_mpm as mpm

out = sys.argv[1] if len(sys.argv) > 1 else "."
hand = mpm.synthesize("hand", vertices=23000)          # a palm and 5 fingers of 3 segments
model = mpm.learn(hand)                                # shape spaces + grammar
for t in model.types:
    print("%-9s %2d instances, %d modes, sigmas %s" % (t["name"], t["instances"], t["modes_kept"], np.round(t["sigmas"], 3)))

editor = mpm.Editor(model)                             # factored once
vertices, targets = mpm.handles_per_part(model, 1)     # one handle per part, at rest
tip = len(vertices) - 1                                # the last part: a finger tip
editor.set_handles(vertices, targets)
targets[tip] += [0.0, -4.0, 3.0]                       # drag the tip down and forward
editor.move_handles(targets)                           # no refactorization
energies = []
report = editor.solve(callback=lambda i, e: energies.append(e))
print("%d iterations, converged: %s, energy %.4g -> %.4g, %.1f ms"
      % (report["iterations"], report["converged"], energies[0], energies[-1], report["solve_ms"]))
mpm.write_mesh(out + "/dragged_hand.ply", editor.positions, editor.F)
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    plt.semilogy(range(1, len(energies) + 1), energies, "o-")
    plt.xlabel("iteration"), plt.ylabel("energy"), plt.savefig(out + "/energy.png", dpi=80)
except ImportError:
    print("matplotlib is not installed: no plot")
