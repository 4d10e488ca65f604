#!/bin/sh
# Pictures of doc/MPM/Cutting.md: joints proposed automatically (mpm cut
# --auto) next to the human segmentation, on three meshes of the Princeton
# Segmentation Benchmark; and the demo's window cutting a raw hand
# (doc/MPM/Demo.md).
# Usage: demo/MPM/make_cutting_figures.sh [PSB_DIR] [MPM_DEMO] [MPM]
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

echo "size 480 360" > "$work/script.txt"
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
