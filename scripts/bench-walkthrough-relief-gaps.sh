#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Cost per frame of the walkthrough's reliefs in the object's shadow and in mirrors.
# 1. The movable object's shadow on a walkthrough relief (vtkLightFieldReliefMapper):
# `vlf view --frames` with the cube moving in front of the Cornell box's back wall (its shadow maps
# rebuilt every frame), the back wall flat or a relief, the object's shadows on (field) or off
# (none), the four runs interleaved ROUNDS times in one invocation (the machine is shared: compare
# within a round).
# 2. The relief seen in mirrors (WalkthroughTracer::SetReliefs): the mirror Cornell box
# (examples/data) at 129 directions, the camera looking into the mirror, which shows the back
# wall; `vlf view --frames 20` (the camera turning 2 degrees a frame) in the progressive (moving
# quality: field lookups, the mirror chain followed), coherent (traced) and raytrace modes, the
# back wall flat or a relief, interleaved.
# Prints the figures and writes them as CSV (OUT.csv and OUT-mirror.csv).
# Usage: scripts/bench-walkthrough-relief-gaps.sh [BUILD_DIR] [OUT.csv] [ROUNDS] [SIZE]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
out="${2:-$here/docs/measurements/walkthrough/walkthrough-relief-gaps.csv}"
rounds="${3:-3}"
size="${4:-256x256}"
tool="$build/bin/mesolight"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$tool" vlf propagate --directions 129 --rays 16 --iterations 3 --out "$work/box.vlf" >/dev/null 2>&1
{
  printf 'P2\n16 16\n255\n'
  for _ in $(seq 16); do echo "0 0 0 0 255 255 255 255 0 0 0 0 255 255 255 255"; done
} >"$work/grooves.pgm"
for i in $(seq 0 19); do echo "$((110 + 4 * i)),330,480,0,0,0,80"; done >"$work/path.csv"
echo "round,wall,shadows,mean_frame_ms" >"$out"
for round in $(seq "$rounds"); do
  for wall in flat relief; do
    for shadows in none field; do
      extra=()
      if [ "$wall" = relief ]; then
        extra=(--relief "back=$work/grooves.pgm" --relief-depth-scale 0.01)
      fi
      line=$(bash "$here/scripts/xvfb.sh" "$tool" vlf view "$work/box.vlf" --frames 20 --offscreen \
        --size "$size" --mode progressive --object cube --path "$work/path.csv" \
        --shadows "$shadows" "${extra[@]}" 2>/dev/null | grep 'ms per frame')
      ms=$(sed -E 's/.*mean ([0-9.]+) ms per frame.*/\1/' <<<"$line")
      echo "round $round, $wall wall, shadows $shadows: $ms ms per frame"
      echo "$round,$wall,$shadows,$ms" >>"$out"
    done
  done
done
echo "wrote $out"

mirror_out="${out%.csv}-mirror.csv"
"$tool" vlf propagate "$here/examples/data/cornell-box-mirror.obj" --directions 129 --rays 16 \
  --iterations 3 --out "$work/mirror.vlf" >/dev/null 2>&1
echo "round,mode,wall,mean_frame_ms" >"$mirror_out"
for round in $(seq "$rounds"); do
  for mode in progressive coherent raytrace; do
    for wall in flat relief; do
      extra=()
      if [ "$wall" = relief ]; then
        extra=(--relief "back=$work/grooves.pgm" --relief-depth-scale 0.1)
      fi
      line=$(bash "$here/scripts/xvfb.sh" "$tool" vlf view "$work/mirror.vlf" --frames 20 \
        --offscreen --size "$size" --mode "$mode" --camera 150,300,20,556,300,380 "${extra[@]}" \
        2>/dev/null | grep 'ms per frame')
      ms=$(sed -E 's/.*mean ([0-9.]+) ms per frame.*/\1/' <<<"$line")
      echo "round $round, mirror box, $mode, $wall back wall: $ms ms per frame"
      echo "$round,$mode,$wall,$ms" >>"$mirror_out"
    done
  done
done
echo "wrote $mirror_out"
