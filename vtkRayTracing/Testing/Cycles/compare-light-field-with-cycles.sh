#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Compares the virtual light field of the built-in Cornell box (its total diffuse textures seen
# through the Cornell camera, `mesolight vlf render`) with Blender Cycles: mean radiance per wall
# region within a tolerance. Negative test: a field after one iteration (direct light only) must
# differ. Exits 77 (ctest SKIP_RETURN_CODE) when blender is not installed.
#   compare-light-field-with-cycles.sh MESOLIGHT WORKDIR [SIZE] [SAMPLES] [TOLERANCE]
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
# Nothing here replaces a file (the OBJ writer, vlf propagate and vlf render refuse to): clear
# the previous run's.
rm -f "$workdir/cornell.obj" "$workdir/cornell.mtl" "$workdir"/field*.vlf "$workdir"/field*.png
"$mesolight" trace --scene cornell --export-obj "$workdir/cornell.obj"
blender -b --factory-startup --python "$here/cornell_cycles.py" -- \
  "$workdir/cornell.obj" "$workdir/cycles.exr" "$size" "$size" "$samples"
"$mesolight" vlf propagate --out "$workdir/field.vlf" --directions 2049 --rays 32 --iterations 10
"$mesolight" vlf render "$workdir/field.vlf" --size "${size}x${size}" --out "$workdir/field.png" \
  --compare-exr "$workdir/cycles.exr" --tolerance "$tolerance"
"$mesolight" vlf propagate --out "$workdir/field1.vlf" --directions 2049 --rays 32 --iterations 1
if "$mesolight" vlf render "$workdir/field1.vlf" --size "${size}x${size}" \
  --out "$workdir/field1.png" --compare-exr "$workdir/cycles.exr" --tolerance "$tolerance"; then
  echo "a field of one iteration (no interreflection) agreed with Cycles: the check cannot fail"
  exit 1
fi
echo "light field agrees with Cycles; one iteration does not"
