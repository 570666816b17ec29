#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The figures docs/paraview.md gives for elevation maps from GIS tools: which of the DEMs of
# scripts/fetch-dems.sh name a no-data value (GDAL_NODATA) and what pixel size on the ground
# their GeoTIFF tags give (beside GDAL's spacing), and how far elev.tif's relief read
# through GDAL Raster Reader (cells, read at their corners) lies from the one read through the
# Mesolight Image Reader (scripts/compare-dem-readers.py). Needs the plugin
# (scripts/setup-paraview.sh).
#
# Usage: scripts/compare-dem-readers.sh
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
library="$("$here/scripts/fetch-dems.sh")"
"$here/scripts/pvbatch.sh" "$here/scripts/compare-dem-readers.py" "$library"
