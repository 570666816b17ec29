#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Writes the figures of a `mesolight` build that must not change when code is only moved:
# cone maps and a relief texture (pixel for pixel), median-cut light sets, light-field energies
# and snapshot, and the deterministic columns of a small relief sweep (samples per pixel, hit
# and colour errors). Compare two builds with scripts/compare-figures.sh.
#   scripts/deterministic-figures.sh MESOLIGHT_BINARY OUTDIR
# Inputs are made with oiiotool (openimageio-tools, installed by install-deps.sh).
set -u
bin="$(realpath "$1")"
out="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mkdir -p "$out/input"
cd "$out"
oiiotool --pattern noise:type=uniform:min=0:max=1:seed=7 96x96 1 --blur 5x5 -d uint16 -o input/depth-noise.png
oiiotool --pattern fill:topleft=0:topright=1:bottomleft=0.5:bottomright=0.2 80x64 1 -d float -o input/depth-ramp.exr
run() { echo "+ $*" >> commands.txt; "$@"; }
for t in relaxed conservative; do
  run "$bin" cone input/depth-noise.png --out cone-noise-$t.exr --type $t > cone-noise-$t.log 2>&1
  run "$bin" cone input/depth-ramp.exr --out cone-ramp-$t.exr --type $t --border wrap > cone-ramp-$t.log 2>&1
done
run "$bin" bake input/depth-noise.png --out bake-noise.exr > bake.log 2>&1
run "$bin" lights procedural:sun --count 64 --out lights-sun-64.csv > lights1.log 2>&1
run "$bin" lights procedural:sky --count 256 --variance --out lights-sky-256-var.csv > lights2.log 2>&1
env_map=/usr/share/blender/datafiles/studiolights/world/courtyard.exr
if [ -f "$env_map" ]; then
  run "$bin" lights "$env_map" --count 128 --out lights-courtyard-128.csv > lights3.log 2>&1
fi
run "$bin" vlf propagate --out field.vlf --directions 513 --rays 16 --iterations 3 > vlf-propagate.log 2>&1
run "$bin" vlf render field.vlf --out field.png --size 128x128 > vlf-render.log 2>&1
run bash "$here/xvfb.sh" "$bin" bench relief --maps Bricks,HemisphereTorus --angles 0,70,85 \
  --size 192x192 --frames 1 --resolution 128 --csv relief-sweep.csv > relief-sweep.log 2>&1
echo "figures in $out"
