# SPDX-License-Identifier: BSD-3-Clause
"""An elevation map (DEM) as GIS tools write one, read and turned into a relief texture in
ParaView: an int16 GeoTIFF in metres with -32768 where there is no data, opened with the Mesolight
Image Reader (int16 kept as stored) into Relief Texture with Invert Input, Normalize Range, Use
No Data Value and No Data Value -32768. The relief's depths must be the elevations' own range
(-100..300 m, below sea level included) and the no-data texels the lowest ground (depth 1),
computed here from the elevations. Must fail: the same without Use No Data Value (-32768 takes
part in the range and every elevation lies within 1.3% of the top). The same file with GDAL's
GDAL_NODATA tag needs neither Use No Data Value nor the value (Use Input No Data Value, the
default); with that turned off it must fail the same way. So must the file through GDAL Raster
Reader (pixels as cells, the no-data ones hidden), against the cells' corner means. Cone Map
reads both files with the same properties and must give the same depths. So must the DEM as an
SRTM height tile (.hgt), opened with File > Open."""
import importlib.util
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402
from vtkmodules.vtkIOImage import vtkTIFFWriter  # noqa: E402

t.load_plugin()
out = t.output_dir()
failures = []
check = t.checker(failures)

# Elevations in metres, VTK row order (row 0 at the bottom), no data outside a disc.
W, H = 48, 40
y, x = np.mgrid[0:H, 0:W].astype(np.float64)
elevation = np.round(-100.0 + 400.0 * (x / (W - 1)) * (0.5 + 0.5 * np.sin(y / 6.0)))
elevation[0, 0], elevation[-1, -1] = -100.0, 300.0
outside = np.hypot(x - W / 2, y - H / 2) > 0.45 * H
outside[0, 0] = outside[-1, -1] = False
# int16 through a float TIFF in OpenImageIO's units (x / 32767; -32768 is -1.0000305) and
# oiiotool, as ParaView's own VTK writes no signed 16-bit TIFF.
stored = np.where(outside, -32768.0, elevation)
image = vtkImageData()
image.SetDimensions(W, H, 1)
image.GetPointData().SetScalars(numpy_to_vtk((stored / 32767.0).astype(np.float32).ravel(), deep=1))
writer = vtkTIFFWriter()
writer.SetInputData(image)
floats = os.path.join(out, "dem-float.tif")
dem = os.path.join(out, "dem-int16.tif")
writer.SetFileName(floats)
writer.Write()
subprocess.run(["oiiotool", floats, "-d", "int16", "-o", dem], check=True)

reader = pvs.MesolightImageReader(FileName=dem)
relief = pvs.MesolightReliefTexture(Input=reader, InvertInput=1, NormalizeRange=1,
                                    UseNoDataValue=1, NoDataValue=-32768)


def depths():
    relief.UpdatePipeline()
    data = servermanager.Fetch(relief)
    return vtk_to_numpy(data.GetPointData().GetScalars())[:, 3].reshape(H, W)


read = servermanager.Fetch(reader)
scalars = read.GetPointData().GetScalars()
check(scalars.GetDataType() == 4, "the int16 file read as VTK_SHORT (got %s)"
      % scalars.GetDataTypeAsString())
check(np.array_equal(vtk_to_numpy(scalars).reshape(H, W), stored.astype(np.int16)),
      "the elevations read as stored")

expected = np.where(outside, 1.0, 1.0 - (elevation + 100.0) / 400.0)
got = depths()
error = np.abs(got - expected).max()
print("with no data: largest depth difference %.2e over %d texels (%d without data)"
      % (error, W * H, outside.sum()))
check(error < 1e-6, "depths = the elevations' own range, no data at depth 1 (max diff %.2e)" % error)

relief.UseNoDataValue = 0
got = depths()
top = got[~outside].max()
print("without Use No Data Value: the deepest elevation at depth %.4f" % top)
check(top < 0.013, "without Use No Data Value -32768 is an elevation (the negative case)")
check(np.abs(got - expected).max() > 0.5, "without Use No Data Value the depths differ")

# The same DEM as GDAL writes it names its no-data value (GDAL_NODATA): Relief Texture applies
# it untouched (Use Input No Data Value, on by default); turned off, -32768 is an elevation again.
spec = importlib.util.spec_from_file_location("add_gdal_no_data", os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "tests", "cli", "AddGdalNoData.py"))
add_gdal_no_data = importlib.util.module_from_spec(spec)
spec.loader.exec_module(add_gdal_no_data)
tagged = os.path.join(out, "dem-int16-gdal-nodata.tif")
add_gdal_no_data.main(dem, tagged, "-32768")
reader = pvs.MesolightImageReader(FileName=tagged)
relief = pvs.MesolightReliefTexture(Input=reader, InvertInput=1, NormalizeRange=1)
check(relief.UseInputNoDataValue == 1 and relief.UseNoDataValue == 0,
      "Use Input No Data Value on and Use No Data Value off by default")
got = depths()
error = np.abs(got - expected).max()
print("the file's own no-data value: largest depth difference %.2e" % error)
check(error < 1e-6, "the GeoTIFF's no-data value applied by default (max diff %.2e)" % error)
relief.UseInputNoDataValue = 0
top = depths()[~outside].max()
check(top < 0.013, "without Use Input No Data Value -32768 is an elevation (the negative case)")

# The same file through GDAL Raster Reader, which ParaView offers for a GeoTIFF: its pixels
# are cells, the no-data ones hidden. Relief Texture reads a texel at each cell corner, the mean
# of the cells around it with data; the reference is that mean computed here from the reader's
# own cells. This file has no georeference (GDAL leaves its map projection empty), so GDAL gives
# its rows top first, and Relief Texture turns them around (common/vtkRasterRowOrder.h): the
# reference takes the cells' rows the other way round too.
gdal = pvs.GDALRasterReader(FileName=tagged)
relief = pvs.MesolightReliefTexture(Input=gdal, InvertInput=1, NormalizeRange=1)
raster = servermanager.Fetch(gdal)
check(raster.GetFieldData().GetAbstractArray("MAP_PROJECTION").GetValue(0) == "",
      "GDAL reads the tagged DEM as a plain image (no map projection)")
cell_values = vtk_to_numpy(raster.GetCellData().GetScalars()).astype(np.float64).reshape(H, W)
hidden = (vtk_to_numpy(raster.GetCellGhostArray()).reshape(H, W) & 32) != 0
check(np.array_equal(cell_values[::-1], np.where(outside, -32768.0, stored)),
      "GDAL gives the plain image's rows top first")
cell_values, hidden = cell_values[::-1], hidden[::-1]
check(hidden.sum() == outside.sum(), "GDAL hides the %d no-data cells (got %d)"
      % (outside.sum(), hidden.sum()))
total = np.zeros((H + 1, W + 1))
count = np.zeros((H + 1, W + 1))  # the cells around each corner with data
around = np.zeros((H + 1, W + 1))  # all the cells around it
for dj in (0, 1):
    for di in (0, 1):
        total[dj:dj + H, di:di + W] += np.where(hidden, 0.0, cell_values)
        count[dj:dj + H, di:di + W] += ~hidden
        around[dj:dj + H, di:di + W] += 1
corner = np.where(count > 0, total / np.maximum(count, 1), np.nan)
low, high = np.nanmin(corner), np.nanmax(corner)
expected_corners = np.where(count > 0, 1.0 - (corner - low) / (high - low), 1.0)
relief.UpdatePipeline()
got = vtk_to_numpy(servermanager.Fetch(relief).GetPointData().GetScalars())[:, 3]
check(got.size == (H + 1) * (W + 1), "one texel per point of GDAL's grid (%d)" % got.size)
if got.size == (H + 1) * (W + 1):
    error = np.abs(got.reshape(H + 1, W + 1) - expected_corners).max()
    print("GDAL Raster Reader: largest depth difference %.2e over %d texels (%d without data)"
          % (error, got.size, (count == 0).sum()))
    check(error < 1e-6, "the cells' corner means, no data at depth 1 (max diff %.2e)" % error)
relief.UseInputNoDataValue = 0
relief.UpdatePipeline()
got = vtk_to_numpy(servermanager.Fetch(relief).GetPointData().GetScalars())[:, 3]
inside = (count == around).ravel()  # corners among data cells only
print("GDAL Raster Reader, hidden cells as data: the deepest elevation at depth %.4f"
      % got[inside].max())
check(got[inside].max() < 0.013,
      "with Use Input No Data Value off GDAL's hidden cells are elevations (the negative case)")

# Cone Map reads a depth image as Relief Texture does, with the same properties: the tagged DEM
# from either reader gives the depths above in its A channel (the cones are computed from them).
cones = pvs.MesolightConeMap(Input=pvs.MesolightImageReader(FileName=tagged), InvertInput=1,
                             NormalizeRange=1)
cones.UpdatePipeline()
got = vtk_to_numpy(servermanager.Fetch(cones).GetPointData().GetScalars())[:, 3].reshape(H, W)
error = np.abs(got - expected).max()
print("Cone Map, Mesolight Image Reader: largest depth difference %.2e" % error)
check(error < 1e-6, "Cone Map applies the file's no-data value (max diff %.2e)" % error)
cones = pvs.MesolightConeMap(Input=gdal, InvertInput=1, NormalizeRange=1)
cones.UpdatePipeline()
got = vtk_to_numpy(servermanager.Fetch(cones).GetPointData().GetScalars())[:, 3]
check(got.size == (H + 1) * (W + 1), "Cone Map reads GDAL's cells (%d texels)" % got.size)
if got.size == (H + 1) * (W + 1):
    error = np.abs(got.reshape(H + 1, W + 1) - expected_corners).max()
    print("Cone Map, GDAL Raster Reader: largest depth difference %.2e" % error)
    check(error < 1e-6, "Cone Map: the cells' corner means (max diff %.2e)" % error)
cones.UseInputNoDataValue = 0
cones.UpdatePipeline()
got = vtk_to_numpy(servermanager.Fetch(cones).GetPointData().GetScalars())[:, 3]
check(got.size == (H + 1) * (W + 1) and got[inside].max() < 0.013,
      "Cone Map with Use Input No Data Value off: hidden cells are elevations (the negative case)")

# An SRTM height tile (.hgt: big-endian int16, the northernmost row first, voids at -32768), which
# neither OpenImageIO nor ParaView's own readers read: File > Open offers the Mesolight Image Reader,
# and Relief Texture's defaults give the depths above (the voids, and the rows padding the DEM to
# a square tile, at depth 1).
tile = np.full((W, W), -32768, dtype=np.int16)  # VTK order: the padding is the south rows
tile[W - H:, :] = stored.astype(np.int16)
tile_path = os.path.join(out, "N49E006.hgt")
tile[::-1].astype(">i2").tofile(tile_path)
srtm = pvs.OpenDataFile(tile_path)
check(srtm is not None and srtm.GetXMLName() == "MesolightImageReader",
      "File > Open reads a .hgt tile with the Mesolight Image Reader (got %s)"
      % (srtm.GetXMLName() if srtm else None))
if srtm is not None:
    relief = pvs.MesolightReliefTexture(Input=srtm, InvertInput=1, NormalizeRange=1)
    relief.UpdatePipeline()
    got = vtk_to_numpy(servermanager.Fetch(relief).GetPointData().GetScalars())[:, 3]
    check(got.size == W * W, "one texel per height of the tile (%d)" % got.size)
    if got.size == W * W:
        got = got.reshape(W, W)
        error = max(np.abs(got[W - H:, :] - expected).max(), np.abs(got[:W - H, :] - 1.0).max())
        print("SRTM tile: largest depth difference %.2e" % error)
        check(error < 1e-6, "the tile's heights and voids as the DEM's (max diff %.2e)" % error)
    relief.UseInputNoDataValue = 0
    relief.UpdatePipeline()
    got = vtk_to_numpy(servermanager.Fetch(relief).GetPointData().GetScalars())[:, 3]
    check(got.size == W * W and got.reshape(W, W)[W - H:, :][~outside].max() < 0.013,
          "with Use Input No Data Value off the voids are elevations (the negative case)")
    # The tile is georeferenced (a degree from 49 N, 47 pixels across): Use True Depth Scale
    # draws it as deep, relative to its width, as the terrain is, times Vertical Exaggeration.
    relief.UseInputNoDataValue = 1
    relief.UseTrueDepthScale = 1
    relief.VerticalExaggeration = 2
    relief.UpdatePipeline()
    fields = servermanager.Fetch(relief).GetFieldData()
    degree = 6371008.8 * np.pi / 180.0
    pixel = degree * np.cos(np.radians(49.5)) / (W - 1)
    true_scale = 400.0 / (W * pixel)  # -100..300 m over W pixels
    drawn = fields.GetArray("MesolightDepthScale").GetValue(0)
    print("SRTM tile: true depth scale %.6f, drawn at %.6f" % (true_scale, drawn))
    check(abs(drawn - 2 * true_scale) < 1e-6 * true_scale + 1e-7,
          "Use True Depth Scale and Vertical Exaggeration 2: depth scale %.6f (expected %.6f)"
          % (drawn, 2 * true_scale))
    check(abs(fields.GetArray("MesolightTrueDepthScale").GetValue(0) - true_scale) < 1e-9,
          "the true depth scale travels with the texture")
    # Relief Plane: the tile on its ground proportions, cos(49.5 degrees) as wide as tall (its
    # pixels are a degree / (W - 1) of longitude by one of latitude); Sources > Plane is square.
    plane = pvs.MesolightReliefPlane(Input=relief)
    plane.UpdatePipeline()
    bounds = plane.GetDataInformation().GetBounds()
    width, height = bounds[1] - bounds[0], bounds[3] - bounds[2]
    print("Relief Plane of the tile: %.4f x %.4f" % (width, height))
    check(abs(width - 1.0) < 1e-6 and abs(height - 1.0 / np.cos(np.radians(49.5))) < 1e-5,
          "Relief Plane: 1 x %.4f (expected 1 x %.4f, the tile's ground proportions)"
          % (height, 1.0 / np.cos(np.radians(49.5))))
    # Without a georeference (the int16 DEM above): its texels' proportions, H / W.
    plain = pvs.MesolightReliefPlane(Input=reader)
    plain.UpdatePipeline()
    bounds = plain.GetDataInformation().GetBounds()
    check(abs(bounds[3] - bounds[2] - H / W) < 1e-6,
          "Relief Plane without a georeference: 1 x %.4f (expected 1 x %.4f)"
          % (bounds[3] - bounds[2], H / W))

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
