#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Mesolight's path tracer (`mesolight trace --scene FILE.obj`) against Blender Cycles on two OBJ
# scenes unlike the Cornell box (scripts/cycles/make_scenes.py: a room lit indirectly by a hidden
# uplight, boxes on a floor under a square light), same camera, same settings
# (scripts/cycles/obj_cycles.py). Each renderer renders each view twice with independent seeds;
# scripts/cycles/compare_exr.py reports the per-pixel relative error (mean, p95), each one's noise
# and the time each needs to reach 1% noise, one CSV row per scene.
#   scripts/cycles-crosscheck.sh MESOLIGHT WORKDIR [SIZE] [CYCLES_SPP] [OURS_SPP] [CSV]
# Not a ctest test: Cycles takes minutes per frame. Defaults: 200 x 200 pixels, 256 Cycles
# samples and 1024 path-tracer paths per pixel per render, docs/measurements/ray-tracing/
# cycles-crosscheck.csv.
set -e
mesolight="$(realpath "$1")"
work="$2"
size="${3:-200}"
cycles_spp="${4:-256}"
ours_spp="${5:-1024}"
here="$(cd "$(dirname "$0")" && pwd)"
csv="${6:-$here/../docs/measurements/ray-tracing/cycles-crosscheck.csv}"
mkdir -p "$work"
python3 "$here/cycles/make_scenes.py" "$work"
rm -f "$csv"
# name camera(eye,focal) up fov
for view in "room 3.6,1.5,4.8,1.5,1.1,0.5 0,1,0 60" "boxes 0,2.5,6,0,0.3,0 0,1,0 45"; do
  set -- $view
  name="$1" camera="$2" up="$3" fov="$4"
  cycles_total=0
  ours_total=0
  for seed in 1 2; do
    blender -b --factory-startup --python "$here/cycles/obj_cycles.py" -- "$work/$name.obj" \
      "$work/$name-cycles$seed.exr" "$size" "$size" "$cycles_spp" "$seed" "$camera" "$up" "$fov" \
      > "$work/$name-cycles$seed.log" 2>&1
    seconds=$(sed -n 's/^cycles seconds //p' "$work/$name-cycles$seed.log")
    cycles_total=$(echo "$cycles_total + $seconds" | bc)
    rm -f "$work/$name-ours$seed.png" "$work/$name-ours$seed.exr"
    "$mesolight" trace --scene "$work/$name.obj" --camera "$camera,$up" --fov "$fov" \
      --width "$size" --height "$size" --samples "$ours_spp" --seed "$seed" --offscreen \
      --out "$work/$name-ours$seed.png" --exr "$work/$name-ours$seed.exr" > "$work/$name-ours$seed.log"
    seconds=$(sed -n 's/.* paths per pixel in \([0-9.]*\) s .*/\1/p' "$work/$name-ours$seed.log")
    ours_total=$(echo "$ours_total + $seconds" | bc)
    echo "$name seed $seed: Cycles total $cycles_total s, path tracer total $ours_total s"
  done
  blender -b --factory-startup --python "$here/cycles/compare_exr.py" -- "$name" \
    "$work/$name-cycles1.exr" "$work/$name-cycles2.exr" "$cycles_total" \
    "$work/$name-ours1.exr" "$work/$name-ours2.exr" "$ours_total" "$csv" 2>&1 | grep '^crosscheck'
done
echo "wrote $csv"
