#!/bin/sh
# Copyright (c) 2026 CGAL-MPM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Writes the manual's pictures of a real segmented hand (doc/MPM/fig/real_*.png)
# with the demo's batch mode: the PSB hand 181 learned with proposed part
# types, symmetrized, exaggerated, with one more thumb segment, and dragged by
# a finger tip next to CGAL's ARAP on the same handles.
#
# usage: demo/MPM/make_real_mesh_figures.sh [PSB_DIR [MPM_DEMO [MPM]]]
#   (defaults: ../shared/data/psb, build/demo/MPM/mpm_demo, build/src/mpm)
# Needs an X display, or xvfb-run (used when DISPLAY is unset).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
psb=${1:-$root/../shared/data/psb}
demo=${2:-$root/build/demo/MPM/mpm_demo}
mpm=${3:-$root/build/src/mpm}
fig=$root/doc/MPM/fig
mkdir -p "$fig"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The proposed part types, as `mpm learn` writes them.
"$mpm" learn "$psb/hand_181.off" --labels "$psb/hand_181.seg" --write-annotation "$work/hand_181.json" \
  -o "$work/hand_181.mpm" > /dev/null

cat > "$work/script.txt" <<SCRIPT
size 640 480
load $psb/hand_181.off $psb/hand_181.seg $work/hand_181.json
view 0 -70
seams on
screenshot $fig/real_hand_rest.png
symmetrize 0.01
screenshot $fig/real_hand_symmetrize.png
caricature 2
screenshot $fig/real_hand_caricature.png
deform
handles per-part 1
drag 8 0.1 0.04 0
arap on
screenshot-window $fig/real_hand_drag_vs_arap.png
arap off
reset
insert 14
screenshot $fig/real_hand_insert.png
SCRIPT

if [ -z "${DISPLAY:-}" ]; then
  xvfb-run -a "$demo" --batch "$work/script.txt"
else
  "$demo" --batch "$work/script.txt"
fi
