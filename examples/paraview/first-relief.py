# SPDX-License-Identifier: BSD-3-Clause
"""The README pipeline in ParaView's Python, on your own files or the procedural ones:
    scripts/pvpython.sh examples/paraview/first-relief.py [OPTIONS] [DEPTH_IMAGE [ENVIRONMENT.hdr]]
    scripts/pvbatch.sh  examples/paraview/first-relief.py [OPTIONS] [DEPTH_IMAGE [ENVIRONMENT.hdr]]
    scripts/paraview.sh --script=examples/paraview/first-relief.py   (the GUI, procedural)
DEPTH_IMAGE: 0 = the surface, 1 = the deepest (8/16-bit PNG, JPEG, TIFF, EXR...); with --height a
height map instead (white = high, as game textures' height channels and DEMs); an elevation map
in metres (a DEM) also takes --normalize and --no-data=VALUE (with "=": the launchers read a
lone -32768 as an option of their own; a GeoTIFF that names its no-data value needs none, and
--no-data=none draws those texels as elevations); a georeferenced one (GeoTIFF, SRTM .hgt) takes
--vertical-exaggeration=E, E times its true vertical scale. Writes relief.png.
The plugin is auto-loaded by the launchers (LoadPlugin is not needed)."""
import argparse
import os
import sys

from paraview.simple import *  # noqa: F401,F403


def open_image(path):
    # The Mesolight Image Reader (OpenImageIO: PNG, JPEG, TIFF, EXR, HDR...) gives the pixels
    # themselves as point scalars; OpenDataFile picks GDAL Raster Reader for .png, .jpg and .tif,
    # whose pixels are cells, which Relief Texture reads at their corners (a half-texel resample)
    # and the lights' filter refuses.
    if not os.path.isfile(path):
        sys.exit("first-relief.py: no such file: %s" % path)
    return MesolightImageReader(FileName=path)


def check(proxy, what):
    # A failed filter leaves an empty output (its error is printed above): stop rather than
    # save an image without the relief.
    proxy.UpdatePipeline()
    if proxy.GetDataInformation().GetNumberOfPoints() == 0:
        sys.exit("first-relief.py: %s produced nothing (see the error above)" % what)


parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("depth", nargs="?", help="the depth image (default: a procedural wall)")
parser.add_argument("environment", nargs="?", help="a lat-long HDR environment to light it")
parser.add_argument("--height", action="store_true", help="the image is a height map")
parser.add_argument("--normalize", action="store_true",
                    help="stretch the image's values to [0, 1] (elevations in metres)")
parser.add_argument("--no-data", metavar="VALUE",
                    help="texels holding this value have no data (e.g. -32768 in an int16 DEM; "
                    "default: the value a GeoTIFF names; none: not even that one)")
parser.add_argument("--vertical-exaggeration", metavar="E", type=float,
                    help="a georeferenced elevation map (GeoTIFF, SRTM .hgt) at E times its true "
                    "vertical scale (with --normalize)")
args = parser.parse_args(sys.argv[1:])  # the GUI's --script passes none
depth = open_image(args.depth) if args.depth else MesolightProceduralRelief()
relief = MesolightReliefTexture(Input=depth, InvertInput=int(args.height),
                                NormalizeRange=int(args.normalize))
if args.no_data is not None and args.no_data.lower() == "none":
    relief.UseInputNoDataValue = 0
elif args.no_data is not None:
    try:
        relief.NoDataValue = float(args.no_data)
    except ValueError:
        sys.exit("first-relief.py: --no-data takes a number, nan or none, not %r" % args.no_data)
    relief.UseNoDataValue = 1
if args.vertical_exaggeration is not None:
    relief.UseTrueDepthScale = 1
    relief.VerticalExaggeration = args.vertical_exaggeration
check(relief, "the relief texture of %s" % (args.depth or "the procedural map"))
if "MesolightTrueDepthScale" in relief.FieldData.keys():
    true_scale = relief.FieldData["MesolightTrueDepthScale"].GetRange()[0]
    drawn = relief.FieldData["MesolightDepthScale"].GetRange()[0]
    print("%s is georeferenced: its true vertical scale is depth scale %.3g; drawn at %.3g, %.3g "
          "times exaggerated" % (args.depth, true_scale, drawn, drawn / true_scale))
# A plane in the map's proportions (a georeferenced map's on the ground), not the square Plane.
plane = MesolightReliefPlane(Input=relief)
attached = MesolightAttachReliefTexture(Input=plane, ReliefTexture=relief)
if args.environment:
    lights = MesolightMedianCutLights(Input=open_image(args.environment))
    check(lights, "the median-cut lights of %s" % args.environment)
    attached.LightSet = OutputPort(lights, 1)  # the LightTexture, not the Lights points
view = GetActiveViewOrCreate("RenderView")
display = Show(attached, view)
display.SetRepresentationType("Relief Surface")
view.CameraPosition = [0.9, -1.2, 1.4]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
out = os.path.abspath("relief.png")
SaveScreenshot(out, view, ImageResolution=[800, 600])
print("wrote", out)
