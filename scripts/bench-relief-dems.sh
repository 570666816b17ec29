#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench relief` on two elevation maps (DEMs) from Debian packages: r-cran-stars'
# olinda_dem_utm25s.tif (111 x 111 float metres) and r-cran-terra's elev.tif (95 x 90 int16
# metres, -32768 for no data), taken out of their .debs by scripts/fetch-dems.sh (nothing is
# installed).
# The elevation options: --height --normalize (elev.tif names its no-data value, -32768, in its
# GDAL_NODATA tag, which the reader applies).
#
# Usage: scripts/bench-relief-dems.sh OUTPUT.txt [extra bench relief options]
#   e.g. scripts/bench-relief-dems.sh docs/measurements/relief-real-maps/dems/default-vs-relief-1.txt \
#          --methods default,relief --steps 32+8 --no-dense --frames 10
#   (the table and summary go to OUTPUT.txt, the rows to OUTPUT.csv)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-}"
if [ -z "$out" ]; then
  echo "usage: $0 OUT.txt [bench relief options]" >&2
  exit 2
fi
shift
library="$("$here/scripts/fetch-dems.sh")"
olinda="$library/stars/tif/olinda_dem_utm25s.tif"
elev="$library/terra/ex/elev.tif"
prefix="${out%.txt}"
mkdir -p "$(dirname "$prefix")"
"$here/scripts/xvfb.sh" "$here/build/bin/mesolight" bench relief --maps file \
  --depth-file "$olinda,$elev" --height --normalize --angles 45,70,85 \
  --csv "$prefix.csv" "$@" > "$prefix.txt"
echo "[mesolight] wrote $prefix.txt and $prefix.csv"
