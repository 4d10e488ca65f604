#!/bin/sh
# Copyright (c) 2026 CGAL-MPM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Runs the Qt demo under a virtual X server in batch mode: a picked handle
# dragged by synthetic mouse events, a scripted drag, every limb bent, a symmetrize and a
# segment insertion on a small synthetic hand, screenshots
# after each, checked (by the demo's own check-image and compare-images
# commands) to be not blank and to differ from one another. Then the start
# from a mesh nobody has segmented: the hand's surface opened raw, cut at
# proposed joints, one cut removed by Alt+click, part types listed, learned.
# Then checks that a script error fails with the script's line named.
#
# usage: demo_batch_test.sh MPM_DEMO OUTPUT_DIRECTORY
set -eu
demo=$1
out=$2
mkdir -p "$out"
rm -f "$out"/*.png
run() {
  xvfb-run -a -s "-screen 0 1024x768x24" "$demo" --batch "$1"
}

cat > "$out/edit.txt" <<SCRIPT
# small pictures keep the checks fast
size 320 240
synth hand 1500
parts
view 0 30
screenshot $out/rest.png
# the window's own path: Shift+click picks a vertex (AABB-tree ray), Ctrl+drag
# moves its handle in 20 mouse moves, Alt+click selects a part
click 120 150 shift
mouse-drag 0 40 -30
screenshot $out/mouse.png
click 160 130 alt
handles per-part 1
drag 0 0.15 0.1 0.05
screenshot $out/drag.png
# every frame of a drag is solved and painted, with its latency measured
profile-drag 5
# every finger bent about its attachment to the palm
handles bend-limbs 0.1
screenshot $out/bend.png
symmetrize 0.01
screenshot $out/symmetrize.png
deform
insert 3
screenshot $out/insert.png
check-image $out/rest.png
compare-images $out/rest.png $out/mouse.png
compare-images $out/mouse.png $out/drag.png
compare-images $out/rest.png $out/drag.png
compare-images $out/rest.png $out/bend.png
compare-images $out/drag.png $out/bend.png
compare-images $out/drag.png $out/symmetrize.png
compare-images $out/symmetrize.png $out/insert.png
compare-images $out/rest.png $out/insert.png
SCRIPT
run "$out/edit.txt" | tee "$out/edit.log"
if ! grep -q "5 frames of [0-9]* vertices: solver .* ms, on the screen .* ms after the drag" "$out/edit.log"; then
  echo "FAIL: profile-drag did not report its frames" >&2
  exit 1
fi

cat > "$out/cut.txt" <<SCRIPT
size 320 240
synth hand 3000
save-mesh $out/raw_hand.off
open $out/raw_hand.off
view 0 30
screenshot $out/raw.png
cut-auto
screenshot $out/cut.png
click 160 130 alt
types
learn
screenshot $out/learned.png
check-image $out/raw.png
compare-images $out/raw.png $out/cut.png
compare-images $out/raw.png $out/learned.png
SCRIPT
run "$out/cut.txt" | tee "$out/cut.log"
proposed=$(sed -n 's/^  \([0-9]*\) cuts, \([0-9]*\) parts$/\1/p' "$out/cut.log" | head -1)
if [ -z "$proposed" ] || [ "$proposed" -lt 10 ]; then
  echo "FAIL: cut-auto proposed '$proposed' cuts on the hand (at least 10 expected)" >&2
  exit 1
fi
if ! grep -q "label [0-9]*: .* type " "$out/cut.log" || ! grep -q "part types" "$out/cut.log"; then
  echo "FAIL: the part types were not listed or nothing was learned" >&2
  exit 1
fi

printf 'size 128 128\nsynth hand 1500\nfrobnicate 1 2\n' > "$out/bad.txt"
if run "$out/bad.txt" 2> "$out/bad.err"; then
  echo "FAIL: an unknown command did not make the batch fail" >&2
  exit 1
fi
if ! grep -q "bad.txt:3: frobnicate: unknown command" "$out/bad.err"; then
  echo "FAIL: the error does not name the line:" >&2
  cat "$out/bad.err" >&2
  exit 1
fi
echo "demo batch test passed"
