#!/bin/sh
# Copyright (c) 2026 CGAL-MPM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Writes the manual's pictures of a real segmented hand (doc/MPM/fig/real_*.png)
# with the demo's batch mode: the PSB hand 181 learned with proposed part
# types, symmetrized, exaggerated, with one more thumb segment, and dragged by
# a finger tip next to CGAL's ARAP on the same handles; and the pictures of
# doc/MPM/Cutting.md and Demo.md: joints proposed automatically (mpm cut
# --auto) next to the human segmentation on three PSB meshes
# (fig/auto_cut_*.png, fig/human_cut_*.png), and the demo's window cutting a
# raw hand (fig/demo_cutting.png).
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
size 480 360
view 0 0
SCRIPT
for mesh in hand_190 ant_81 octopus_137; do
  "$mpm" cut "$psb/$mesh.off" --auto -o "$work/$mesh" > /dev/null
  cat >> "$work/script.txt" <<SCRIPT
load $work/$mesh.off $work/$mesh.seg
seams on
screenshot $fig/auto_cut_$mesh.png
load $psb/$mesh.off $psb/$mesh.seg
seams on
screenshot $fig/human_cut_$mesh.png
SCRIPT
done
cat >> "$work/script.txt" <<SCRIPT
window-size 1100 640
open $psb/hand_190.off
cut-auto
screenshot-window $fig/demo_cutting.png
SCRIPT

if [ -z "${DISPLAY:-}" ]; then
  xvfb-run -a "$demo" --batch "$work/script.txt"
else
  "$demo" --batch "$work/script.txt"
fi
