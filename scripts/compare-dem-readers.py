# SPDX-License-Identifier: BSD-3-Clause
"""scripts/compare-dem-readers.sh runs this under pvbatch: DIRECTORY holds GeoTIFF DEMs (the tree
scripts/fetch-dems.sh unpacks).

1. For every .tif below DIRECTORY: the no-data value the Mesolight Image Reader finds in its
   GDAL_NODATA tag (field data MesolightNoDataValue), or none.
2. terra/ex/elev.tif drawn as examples/paraview/first-relief.py draws it with --height
   --normalize (Relief Texture with Invert Input and Normalize Range, a Plane, Attach Relief
   Texture, the Relief Surface representation, the same camera, 800 x 600), once opened with the
   Mesolight Image Reader (the pixels as texels) and once with GDAL Raster Reader (the pixels as
   cells, which Relief Texture reads at their corners): the share of pixels that differ by more
   than 8 levels in a channel, and the mean difference."""
import glob
import os
import sys
import tempfile

import numpy as np
from paraview import servermanager
from paraview.simple import (CreateRenderView, Delete, GDALRasterReader,
                             MesolightAttachReliefTexture, MesolightImageReader,
                             MesolightReliefTexture, Plane, ResetCamera, SaveScreenshot, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

directory = sys.argv[1]
print("GDAL_NODATA as the Mesolight Image Reader reads it:")
for path in sorted(glob.glob(os.path.join(directory, "**", "*.tif"), recursive=True)):
    reader = MesolightImageReader(FileName=path)
    named = servermanager.Fetch(reader).GetFieldData().GetArray("MesolightNoDataValue")
    print("  %-28s %s" % (os.path.basename(path), named.GetValue(0) if named else "none"))
    Delete(reader)


def render(reader, png):
    relief = MesolightReliefTexture(Input=reader, InvertInput=1, NormalizeRange=1)
    attached = MesolightAttachReliefTexture(Input=Plane(), ReliefTexture=relief)
    view = CreateRenderView()
    Show(attached, view).SetRepresentationType("Relief Surface")
    view.CameraPosition = [0.9, -1.2, 1.4]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    SaveScreenshot(png, view, ImageResolution=[800, 600])
    png_reader = vtkPNGReader()
    png_reader.SetFileName(png)
    png_reader.Update()
    return vtk_to_numpy(png_reader.GetOutput().GetPointData().GetScalars()).astype(np.float64)


elev = os.path.join(directory, "terra", "ex", "elev.tif")
out = tempfile.mkdtemp(prefix="compare-dem-readers-")
texels = render(MesolightImageReader(FileName=elev), os.path.join(out, "mesolight-reader.png"))
cells = render(GDALRasterReader(FileName=elev), os.path.join(out, "gdal-raster-reader.png"))
largest = np.abs(texels - cells).max(axis=1)
print("elev.tif, Mesolight Image Reader vs GDAL Raster Reader (800 x 600, %s):" % out)
print("  pixels differing by > 8 levels: %d of %d (%.2f%%); mean difference %.2f levels"
      % ((largest > 8).sum(), largest.size, 100.0 * (largest > 8).mean(),
         np.abs(texels - cells).mean()))
