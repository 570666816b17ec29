#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Compares mesolight's path-traced Cornell box with Blender Cycles: mean radiance per wall
# region within a tolerance. Exits 77 (ctest SKIP_RETURN_CODE) when blender is not installed.
#   compare-with-cycles.sh MESOLIGHT WORKDIR [SIZE] [SAMPLES] [TOLERANCE]
set -eu
. "$(cd "$(dirname "$0")" && pwd)/cycles-reference.sh"
"$mesolight" trace --scene cornell --offscreen --width "$size" --height "$size" --samples "$samples" \
  --out "$workdir/mesolight.png" --exr "$workdir/mesolight.exr" \
  --compare-exr "$workdir/cycles.exr" --tolerance "$tolerance"
