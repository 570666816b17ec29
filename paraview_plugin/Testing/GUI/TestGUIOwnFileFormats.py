# SPDX-License-Identifier: BSD-3-Clause
"""GUI: the README pipeline on a user's own depth image in each format (16-bit PNG, 8-bit JPEG,
float TIFF, float OpenEXR; the 8-bit PNG is TestGUIOwnFiles.xml's) and own HDR environment
(sky.hdr), each opened by a reader ParaView offers for it (for .png, .jpg and .tif File > Open
asks: the PNG and TIFF Series Readers, and for every one the Mesolight Image Reader, which the
JPEG takes; GDAL Raster Reader, also offered, gives the pixels as cells, which Relief Texture
reads at their corners, docs/paraview.md; .exr and .hdr: OpenDataFile, the reader factory's
choice; the sky also as a float TIFF through GDAL Raster Reader, whose cells Median Cut Lights
reads as the pixels, the rows of such a plain image turned the right way up: the same lights as
through the Mesolight Image Reader; and the depth TIFF through it, the same relief), in
the orders a user may apply the steps, each step applied as the GUI applies it
(mesolight_guitest.apply). After the last Apply the relief must be the only visible data (every
image hidden), in 3D, framed. Must fail: the same run with the plugin's hiding turned off
leaves the images shown (checked by hand, docs/paraview.md)."""
import os

import mesolight_guitest as g
import mesolight_ownfiles as own
import mesolight_xmltest as x
import numpy as np
import paraview.simple as pvs
from vtkmodules.util.numpy_support import vtk_to_numpy

ORDERS = {
    # depth, relief texture, plane, attach (light set given at creation)
    "depth first, lights first": ["sky", "cut", "depth", "relief", "plane", "attach"],
    # plane first, the environment last and attached by a second Apply
    "plane first, lights last": ["plane", "depth", "relief", "attach", "sky", "cut", "light set"],
}


def run_order(view, depth_file, steps, sky_file="sky.hdr"):
    made = {}
    for step in steps:
        if step == "sky" and sky_file.endswith(".tif"):
            made[step] = pvs.GDALRasterReader(FileName=os.path.join(own.directory(), sky_file))
        elif step == "sky":
            made[step] = pvs.OpenDataFile(os.path.join(own.directory(), sky_file))
        elif step == "cut":
            made[step] = pvs.MesolightMedianCutLights(Input=made["sky"], NumberOfLights=16)
        elif step == "depth":
            path = os.path.join(own.directory(), depth_file)
            if depth_file.endswith(".jpg"):
                made[step] = pvs.MesolightImageReader(FileName=path)
            elif depth_file.endswith(".png"):
                made[step] = pvs.PNGSeriesReader(FileNames=[path])
            elif depth_file.endswith(".tif"):
                made[step] = pvs.TIFFSeriesReader(FileNames=[path])
            else:
                made[step] = pvs.OpenDataFile(path)
        elif step == "relief":
            made[step] = pvs.MesolightReliefTexture(Input=made["depth"])
        elif step == "plane":
            made[step] = pvs.Plane()
        elif step == "attach":
            made[step] = pvs.MesolightAttachReliefTexture(Input=made["plane"],
                                                          ReliefTexture=made["relief"])
            if "cut" in made:
                made[step].LightSet = pvs.OutputPort(made["cut"], 1)
        if step == "light set":
            made["attach"].LightSet = pvs.OutputPort(made["cut"], 1)
            pvs.SetActiveSource(made["attach"])
            pvs.Render(view)  # a later Apply: the pipeline updates, nothing new is shown
        else:
            g.apply(made[step], view)
    return made


@x._guarded
def mesolight_reader_offered(extensions):
    """File > Open's file types: the Mesolight Image Reader claims the 8/16-bit formats beside
    ParaView's own readers, so the reader dialog offers it for them (it gives point scalars), and
    SRTM height tiles (.hgt), which no other reader opens."""
    factory = pvs.servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
    factory.UpdateAvailableReaders()
    types = factory.GetSupportedFileTypes(pvs.servermanager.ActiveConnection.Session).split(";;")
    ours = [t for t in types if t.startswith("Images (OpenImageIO, Mesolight)")]
    missing = [e for e in extensions if not ours or "*.%s" % e not in ours[0].split("(")[-1]]
    x._check(not missing, "Mesolight Image Reader's file types %s lack %s" % (ours, missing))


@x._guarded
def sky_through_gdal():
    """The float TIFF sky through GDAL Raster Reader (its pixels as cells) and through the
    Mesolight Image Reader (points): Median Cut Lights gives the same lights from both."""
    path = os.path.join(own.directory(), "sky.tif")
    gdal = pvs.GDALRasterReader(FileName=path)
    ours = pvs.MesolightImageReader(FileName=path)
    raster = pvs.servermanager.Fetch(gdal)
    x._check(raster.GetCellData().GetScalars() is not None
             and raster.GetPointData().GetScalars() is None,
             "GDAL Raster Reader gives the sky's pixels as cells")
    found = []
    for reader in (gdal, ours):
        cut = pvs.MesolightMedianCutLights(Input=reader, NumberOfLights=16)
        lights = pvs.servermanager.Fetch(cut)
        found.append((vtk_to_numpy(lights.GetPoints().GetData()),
                      vtk_to_numpy(lights.GetPointData().GetArray("Irradiance"))))
        pvs.Delete(cut)
    (points, irradiance), (points_ours, irradiance_ours) = found
    x._print("sky.tif: %d lights through GDAL Raster Reader, %d through the Mesolight Image "
             "Reader; largest direction difference %.2e"
             % (len(points), len(points_ours),
                np.abs(points - points_ours).max() if points.shape == points_ours.shape else -1))
    x._check(points.shape == (16, 3) and points.shape == points_ours.shape
             and np.allclose(points, points_ours, atol=1e-6)
             and np.allclose(irradiance, irradiance_ours, rtol=1e-5),
             "the same 16 lights from GDAL's cells as from the Mesolight Image Reader's points")
    pvs.Delete(ours)
    pvs.Delete(gdal)


@x._guarded
def depth_through_gdal():
    """A float TIFF depth through GDAL Raster Reader and through the Mesolight Image Reader:
    Relief Texture's texel at each inner cell corner from GDAL's cells is the mean of the four
    texels around it from the Mesolight Image Reader (the same picture the same way up); upside
    down it is not. As a plain image GDAL gives the rows top first (Relief Texture turns them
    around); with a world file (slope.tfw: georeferenced, no map projection) north up, as they
    stay. The user's depth is the same either way up, so this writes one that is not: the depth
    over a slope."""
    depth = own.depth_map() * 0.5 + 0.5 * np.linspace(0.0, 1.0, own.SIZE)[:, None]
    for name, world in (("slope.tif", None), ("slope-world.tif", "slope-world.tfw")):
        path = os.path.join(own.directory(), name)
        own.write_tiff(path, depth)
        if world:
            with open(os.path.join(own.directory(), world), "w") as f:
                f.write("0.5\n0\n0\n-0.5\n1000.25\n2000.25\n")  # 0.5 m pixels, north up
        textures = []
        for reader in (pvs.GDALRasterReader(FileName=path),
                       pvs.MesolightImageReader(FileName=path)):
            relief = pvs.MesolightReliefTexture(Input=reader)
            image = pvs.servermanager.Fetch(relief)
            dims = image.GetDimensions()
            textures.append(vtk_to_numpy(image.GetPointData().GetScalars())[:, 3]
                            .reshape(dims[1], dims[0]))
            pvs.Delete(relief)
            pvs.Delete(reader)
        corners, ours = textures
        means = 0.25 * (ours[:-1, :-1] + ours[1:, :-1] + ours[:-1, 1:] + ours[1:, 1:])
        ok = corners.shape == (ours.shape[0] + 1, ours.shape[1] + 1)
        error = np.abs(corners[1:-1, 1:-1] - means).max() if ok else -1.0
        flipped = np.abs(corners[1:-1, 1:-1] - means[::-1]).max() if ok else -1.0
        x._print("%s through GDAL Raster Reader: largest texel difference %.2e from the "
                 "Mesolight Image Reader's corner means, %.2f upside down" % (name, error, flipped))
        x._check(ok and error < 1e-5 and flipped > 0.1,
                 "Relief Texture reads GDAL's %s the right way up" % name)


def main():
    own.write_files()
    mesolight_reader_offered(["png", "jpg", "jpeg", "tif", "tiff", "exr", "hdr", "hgt"])
    view = g.gui_view()
    readers = {}
    # Each format once, the orders alternating (the suite's time: about 13 s a run here).
    orders = list(ORDERS.items())
    sky_through_gdal()
    depth_through_gdal()
    for k, depth_file in enumerate(("depth16.png", "depth.jpg", "depth.tif", "depth.exr")):
        for name, steps in [orders[k % len(orders)]]:
            # With the TIFF depth the sky is a TIFF too, through GDAL Raster Reader.
            sky_file = "sky.tif" if depth_file == "depth.tif" else "sky.hdr"
            made = run_order(view, depth_file, steps, sky_file)
            readers[depth_file] = made["depth"].GetXMLLabel()
            readers[sky_file] = made["sky"].GetXMLLabel()
            x._print("%s, %s (read by %s, sky by %s):"
                     % (depth_file, name, readers[depth_file], readers[sky_file]))
            own.only_relief_framed()
            own.light_set_port(1)
            for proxy in reversed(list(made.values())):
                pvs.Delete(proxy)
    x._print("readers ParaView picked: %s" % readers)
    return list(x._failures)


g.run(main)
