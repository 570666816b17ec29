#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Compares mesolight's path-traced Cornell box with Blender Cycles: mean radiance per wall
# region within a tolerance. Exits 77 (ctest SKIP_RETURN_CODE) when blender is not installed.
#   compare-with-cycles.sh MESOLIGHT WORKDIR [SIZE] [SAMPLES] [TOLERANCE]
set -eu
mesolight="$1"
workdir="$2"
size="${3:-96}"
samples="${4:-256}"
tolerance="${5:-0.05}"
if ! command -v blender >/dev/null 2>&1; then
  echo "blender is not installed: skipping the Cycles comparison"
  exit 77
fi
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$workdir"
# The export never replaces a file: clear the previous run's.
rm -f "$workdir/cornell.obj" "$workdir/cornell.mtl"
"$mesolight" trace --scene cornell --export-obj "$workdir/cornell.obj"
blender -b --factory-startup --python "$here/cornell_cycles.py" -- \
  "$workdir/cornell.obj" "$workdir/cycles.exr" "$size" "$size" "$samples"
"$mesolight" trace --scene cornell --offscreen --width "$size" --height "$size" --samples "$samples" \
  --out "$workdir/mesolight.png" --exr "$workdir/mesolight.exr" \
  --compare-exr "$workdir/cycles.exr" --tolerance "$tolerance"
