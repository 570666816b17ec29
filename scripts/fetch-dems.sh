#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Two Debian packages' elevation maps (DEMs) for the measurements: r-cran-stars' GeoTIFFs
# (olinda_dem_utm25s.tif: 111 x 111 float metres, ...) and r-cran-terra's (elev.tif: 95 x 90
# int16 metres with -32768 for no data, meuse.tif, logo.tif). The .debs are downloaded with
# `apt-get download` and unpacked into build/dems with `dpkg-deb -x`: nothing is installed (the
# packages would pull in R). Prints the directory that holds the GeoTIFFs' trees.
#
# Usage: scripts/fetch-dems.sh   (used by bench-relief-dems.sh and compare-dem-readers.sh)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
dems="$here/build/dems"
if [ ! -f "$dems/usr/lib/R/site-library/stars/tif/olinda_dem_utm25s.tif" ] ||
  [ ! -f "$dems/usr/lib/R/site-library/terra/ex/elev.tif" ]; then
  mkdir -p "$dems/debs"
  (cd "$dems/debs" && apt-get download r-cran-stars r-cran-terra) >&2
  for deb in "$dems"/debs/*.deb; do
    dpkg-deb -x "$deb" "$dems"
  done
fi
echo "$dems/usr/lib/R/site-library"
