#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Compares the virtual light field of the built-in Cornell box (its total diffuse textures seen
# through the Cornell camera, `mesolight vlf render`) with Blender Cycles: mean radiance per wall
# region within a tolerance. Negative test: a field after one iteration (direct light only) must
# differ. Exits 77 (ctest SKIP_RETURN_CODE) when blender is not installed.
#   compare-light-field-with-cycles.sh MESOLIGHT WORKDIR [SIZE] [SAMPLES] [TOLERANCE]
set -eu
. "$(cd "$(dirname "$0")" && pwd)/cycles-reference.sh"
# vlf propagate and vlf render never replace a file either.
rm -f "$workdir"/field*.vlf "$workdir"/field*.png
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
