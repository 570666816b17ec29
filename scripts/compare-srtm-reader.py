# SPDX-License-Identifier: BSD-3-Clause
"""A real DEM in the SRTM tile layout, read back: scripts/python.sh scripts/compare-srtm-reader.py
DEM.tif [OUT_DIR]

Debian ships no SRTM tile (.hgt), so this writes one from a real elevation map: DEM.tif's int16
metres (e.g. r-cran-terra's elev.tif, scripts/fetch-dems.sh), padded to a square with voids
(-32768) along the south edge, big-endian, the northernmost row first. It then bakes both files
with vtkReliefTextureFilter's defaults for elevations (Invert Input, Normalize Range; each file's
own no-data value: the GeoTIFF's GDAL_NODATA, the tile's voids) and prints the largest depth
difference over the DEM's texels (0 when the tile reader reads the same metres, rows and voids)."""
import os
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from mesolight import vtkOIIOImageReader, vtkReliefTextureFilter


def bake(path):
    reader = vtkOIIOImageReader()
    reader.SetFileName(path)
    relief = vtkReliefTextureFilter()
    relief.SetInputConnection(reader.GetOutputPort())
    relief.InvertInputOn()
    relief.NormalizeRangeOn()
    relief.Update()
    image = relief.GetOutput()
    w, h, _ = image.GetDimensions()
    depth = vtk_to_numpy(image.GetPointData().GetScalars())[:, 3].reshape(h, w)
    return reader, relief, depth


def main(dem, out_dir):
    reader, relief, dem_depth = bake(dem)
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    metres = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w)  # bottom row first
    if metres.dtype != np.int16:
        sys.exit(f"{dem}: int16 elevations expected, got {metres.dtype}")
    side = max(w, h)
    tile = np.full((side, side), -32768, dtype=np.int16)  # VTK order: south rows padded
    tile[side - h:, :w] = metres
    if reader.GetHasNoDataValue():
        tile[tile == int(reader.GetNoDataValue())] = -32768
    path = os.path.join(out_dir, "N49E006.hgt")
    tile[::-1].astype(">i2").tofile(path)  # the northernmost row first, big-endian
    _, tile_relief, tile_depth = bake(path)
    overlap = tile_depth[side - h:, :w]
    print(f"{dem}: {w} x {h} int16, no-data value "
          f"{reader.GetNoDataValue() if reader.GetHasNoDataValue() else 'none'} "
          f"({relief.GetNumberOfNoDataTexels()} texels)")
    print(f"{path}: {side} x {side} tile, voids {tile_relief.GetNumberOfNoDataTexels()} "
          f"({side * side - w * h} of them padding)")
    print(f"largest depth difference over the DEM's texels: {np.abs(overlap - dem_depth).max():.3g}")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2] if len(sys.argv) == 3 else tempfile.mkdtemp())
