#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the Cycles comparisons: reads MESOLIGHT WORKDIR [SIZE] [SAMPLES] [TOLERANCE] from
# the caller's arguments, exits 77 (ctest SKIP_RETURN_CODE) when blender is not installed, and
# renders the built-in Cornell box (exported as OBJ + MTL by `mesolight trace --export-obj`)
# with Blender Cycles to $workdir/cycles.exr, the Cornell camera's view, linear radiance. The
# Blender side is the one OBJ renderer of the Cycles cross-checks, scripts/cycles/obj_cycles.py,
# given mesolight's CornellCamera.
mesolight="$1"
workdir="$2"
size="${3:-96}"
samples="${4:-256}"
tolerance="${5:-0.05}"
if ! command -v blender >/dev/null 2>&1; then
  echo "blender is not installed: skipping the Cycles comparison"
  exit 77
fi
repository="$(cd "$(dirname "$0")/../../.." && pwd)"
mkdir -p "$workdir"
# The OBJ writer never replaces a file: clear the previous run's export.
rm -f "$workdir/cornell.obj" "$workdir/cornell.mtl"
"$mesolight" trace --scene cornell --export-obj "$workdir/cornell.obj"
blender -b --factory-startup --python "$repository/scripts/cycles/obj_cycles.py" -- \
  "$workdir/cornell.obj" "$workdir/cycles.exr" "$size" "$size" "$samples" 0 \
  278,273,-800,278,273,0 0,1,0 39.3077
