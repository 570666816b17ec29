# SPDX-License-Identifier: BSD-3-Clause
"""scripts/compare-dem-readers.sh runs this under pvbatch: DIRECTORY holds GeoTIFF DEMs (the tree
scripts/fetch-dems.sh unpacks).

1. For every .tif below DIRECTORY: the no-data value the Mesolight Image Reader finds in its
   GDAL_NODATA tag (field data MesolightNoDataValue), or none; the pixel size on the ground it
   finds in the GeoTIFF tags (MesolightPixelSize, metres), or none, beside GDAL Raster Reader's
   spacing (GDAL's reading of the same tags, in the file's units: metres or degrees).
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
print("GDAL_NODATA and a pixel's size on the ground (metres, along rows x columns) as the "
      "Mesolight Image Reader reads them; GDAL Raster Reader's spacing (the GeoTIFF's own units)")
for path in sorted(glob.glob(os.path.join(directory, "**", "*.tif"), recursive=True)):
    reader = MesolightImageReader(FileName=path)
    fields = servermanager.Fetch(reader).GetFieldData()
    named = fields.GetArray("MesolightNoDataValue")
    size = fields.GetArray("MesolightPixelSize")
    gdal = GDALRasterReader(FileName=path)
    gdal.UpdatePipeline()
    info = gdal.GetDataInformation().DataInformation
    bounds, extent = info.GetBounds(), info.GetExtent()
    spacing = [(bounds[2 * a + 1] - bounds[2 * a]) / max(extent[2 * a + 1] - extent[2 * a], 1)
               for a in (0, 1)]
    print("  %-24s no data %-8s pixel %-22s GDAL spacing %.6g x %.6g"
          % (os.path.basename(path), named.GetValue(0) if named else "none",
             "%.2f x %.2f m" % size.GetTuple2(0) if size else "none", spacing[0], spacing[1]))
    # (Deleting GDAL Raster Readers in a loop crashes ParaView 5.11's pvbatch here, measured
    # without any Mesolight filter: they are kept.)
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
