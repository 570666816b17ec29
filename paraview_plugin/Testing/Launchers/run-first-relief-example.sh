#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The README's "your own files" command, as a user runs it: scripts/pvbatch.sh
# examples/paraview/first-relief.py --height HEIGHT.jpg SKY.hdr, without a display, in a fresh
# directory. A JPEG is what ParaView's OpenDataFile hands to GDAL Raster Reader (pixels as cell
# data, which Relief Texture refused: the script then saved a frame without the relief). Fails
# unless the script exits 0, prints no error and writes relief.png with a shaded relief covering
# part of the frame; unless an elevation map in metres is refused without --normalize and drawn
# with --normalize --no-data; unless an SRTM tile is drawn with --vertical-exaggeration (and a
# map without a georeference refused with it); and unless a missing file ends the script with an
# error and no relief.png.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../../.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
# The relief: many shaded levels over part of the frame (the frame without it is the flat
# background and the orientation axes: under 1% of the pixels off the background).
check_relief() {
  /usr/bin/python3 - relief.png <<'EOF' || exit 1
import sys
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
reader = vtkPNGReader()
reader.SetFileName(sys.argv[1])
reader.Update()
pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
background = np.median(pixels, axis=0)
covered = (np.abs(pixels - background).max(axis=1) > 12).mean()
levels = len(np.unique(pixels[:, 0]))
print("relief covers %.3f of the frame, %d red levels" % (covered, levels))
sys.exit(0 if covered > 0.1 and levels > 20 else "FAILED: no shaded relief in relief.png")
EOF
}
# Runs examples/paraview/first-relief.py ARGS... headless through scripts/pvbatch.sh (from a fresh
# relief.png), shows its output, and leaves it in log.txt and its exit status in $status.
run_first_relief() {
  rm -f relief.png
  env -u DISPLAY timeout 300 bash "$repo/scripts/pvbatch.sh" \
    "$repo/examples/paraview/first-relief.py" "$@" >log.txt 2>&1
  status=$?
  cat log.txt
}
# A user's files: an 8-bit JPEG height map (raised squares) and a small HDR sky.
oiiotool --pattern checker:width=16:height=16:color1=1:color2=0 128x128 1 -d uint8 -o height.jpg &&
  oiiotool --pattern fill:top=4,4,5:bottom=0.5,0.4,0.3 64x32 3 -d float -o sky.hdr || exit 1

run_first_relief --height height.jpg sky.hdr
if [ $status -ne 0 ]; then
  echo "FAILED: first-relief.py exited with $status" >&2
  exit 1
fi
if grep -q "ERR|\|ERROR\|Segmentation\|SIGSEGV" log.txt; then
  echo "FAILED: first-relief.py printed an error" >&2
  exit 1
fi
check_relief

# An elevation map in metres with no-data holes: refused without --normalize (the script stops,
# no relief.png); drawn with --normalize --no-data.
oiiotool --pattern checker:width=16:height=16:color1=1:color2=0 128x128 1 -d float -o has.tif &&
  oiiotool --pattern fill:top=120:bottom=880 128x128 1 has.tif --mul \
    has.tif --subc 1 --mulc 9999 --add -d float -o dem.tif || exit 1
run_first_relief --height dem.tif
if [ $status -eq 0 ] || [ -e relief.png ] || ! grep -q "NormalizeRange" log.txt; then
  echo "FAILED: a map in metres without --normalize must stop the script naming NormalizeRange" >&2
  exit 1
fi
run_first_relief --height --normalize --no-data=-9999 dem.tif
if [ $status -ne 0 ] || grep -q "ERR|" log.txt; then
  echo "FAILED: first-relief.py --height --normalize --no-data=-9999 on the elevation map" >&2
  exit 1
fi
check_relief

# An SRTM tile (georeferenced): --vertical-exaggeration=3 draws three times its true vertical
# scale and says so; the map in metres above, which has no georeference, is refused with it.
/usr/bin/python3 "$repo/tests/cli/WriteSrtmTile.py" N46E007.hgt 121 voids || exit 1
run_first_relief --height --normalize --vertical-exaggeration=3 N46E007.hgt
if [ $status -ne 0 ] || grep -q "ERR|" log.txt || ! grep -q "3 times exaggerated" log.txt; then
  echo "FAILED: first-relief.py --vertical-exaggeration=3 on an SRTM tile" >&2
  exit 1
fi
check_relief
run_first_relief --height --normalize --vertical-exaggeration=3 dem.tif
if [ $status -eq 0 ] || [ -e relief.png ] || ! grep -q "pixel size on the ground" log.txt; then
  echo "FAILED: --vertical-exaggeration on a map without a georeference must stop the script" >&2
  exit 1
fi

run_first_relief missing.png
if [ $status -eq 0 ] || [ -e relief.png ] || ! grep -q "no such file: missing.png" log.txt; then
  echo "FAILED: a missing depth image must end the script with an error and no relief.png" >&2
  exit 1
fi
echo "passed: first-relief.py on a JPEG height map and an HDR sky, on an elevation map with"\
  "no-data holes (refused without --normalize), on an SRTM tile at three times its true"\
  "vertical scale (refused on a map without a georeference); a missing file refused"
