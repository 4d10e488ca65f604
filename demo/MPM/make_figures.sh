#!/bin/sh
# Copyright (c) 2026 CGAL-MPM contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Writes the manual's pictures (doc/MPM/fig/*.png, 640x480) with the demo's
# batch mode: the synthetic families with parts coloured by type, a drag next
# to CGAL's ARAP, symmetrization and caricature, assembled variants.
#
# usage: demo/MPM/make_figures.sh [MPM_DEMO]   (default: build/demo/MPM/mpm_demo)
# Needs an X display, or xvfb-run (used when DISPLAY is unset).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
demo=${1:-$root/build/demo/MPM/mpm_demo}
fig=$root/doc/MPM/fig
mkdir -p "$fig"
script=$(mktemp)
trap 'rm -f "$script"' EXIT

cat > "$script" <<SCRIPT
size 640 480

# What a first launch shows: the synthetic hand, parts coloured by type,
# seams dark, docking-site vertices white.
synth hand 3000
view 0 20
screenshot $fig/demo_first_launch.png
window-size 1280 800
view 0 20
screenshot-window $fig/demo_window.png
size 640 480

# The synthetic families.
synth spider 3000
view 30 45
screenshot $fig/family_spider.png
synth hexa-grid 3000
view 20 40
screenshot $fig/family_hexa_grid.png
synth facade 3000
view 20 15
screenshot $fig/family_facade.png
synth spine 3000
view 55 25
screenshot $fig/family_spine.png

# A drag: one handle per part except the thumb's two inner segments, the
# thumb's tip pulled up; MPM (left) next to CGAL's ARAP (right) on the same
# handles.
synth hand 3000
handles per-part 1
handle remove 14
handle remove 13
view 0 20
arap on
drag 13 -0.05 0.25 0.05
screenshot $fig/deform_vs_arap.png
arap off

# Partial symmetrization and caricature of the training hand.
handles clear
reset
symmetrize 0.01
screenshot $fig/symmetrize.png
caricature 2
screenshot $fig/caricature.png
caricature -1
screenshot $fig/anti_shape.png
deform

# Assembled variants from the grammar: a longer finger, and a copied finger.
insert 3
insert 3
screenshot $fig/assembled_long_finger.png
synth spider 3000
insert 2
insert 14
view 30 45
screenshot $fig/assembled_spider.png
SCRIPT

if [ -n "${DISPLAY:-}" ]; then
  "$demo" --batch "$script"
else
  xvfb-run -a -s "-screen 0 1280x1024x24" "$demo" --batch "$script"
fi
echo "Wrote the figures to $fig"
