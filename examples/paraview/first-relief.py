# SPDX-License-Identifier: BSD-3-Clause
"""The README pipeline in ParaView's Python, on your own files or the procedural ones:
    scripts/pvpython.sh examples/paraview/first-relief.py [--height] [DEPTH_IMAGE [ENVIRONMENT.hdr]]
    scripts/pvbatch.sh  examples/paraview/first-relief.py [--height] [DEPTH_IMAGE [ENVIRONMENT.hdr]]
    scripts/paraview.sh --script=examples/paraview/first-relief.py   (the GUI, procedural)
DEPTH_IMAGE: 0 = the surface, 1 = the deepest (8/16-bit PNG, JPEG, TIFF, EXR...); with --height a
height map instead (white = high, as game textures' height channels and DEMs). Writes relief.png.
The plugin is auto-loaded by the launchers (LoadPlugin is not needed)."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403


def open_image(path):
    # The Mesolight Image Reader (OpenImageIO: PNG, JPEG, TIFF, EXR, HDR...) gives the pixels as
    # point scalars, what the Mesolight filters read; OpenDataFile picks GDAL Raster Reader for
    # .png, .jpg and .tif, whose pixels are cell data.
    if not os.path.isfile(path):
        sys.exit("first-relief.py: no such file: %s" % path)
    return MesolightImageReader(FileName=path)


def check(proxy, what):
    # A failed filter leaves an empty output (its error is printed above): stop rather than
    # save an image without the relief.
    proxy.UpdatePipeline()
    if proxy.GetDataInformation().GetNumberOfPoints() == 0:
        sys.exit("first-relief.py: %s produced nothing (see the error above)" % what)


args = [a for a in sys.argv[1:] if not a.startswith("-")]
options = [a for a in sys.argv[1:] if a.startswith("-")]
if set(options) - {"--height"} or len(args) > 2:
    sys.exit(__doc__)
depth = open_image(args[0]) if args else MesolightProceduralRelief()
relief = MesolightReliefTexture(Input=depth)
relief.InvertInput = int("--height" in options)
check(relief, "the relief texture of %s" % (args[0] if args else "the procedural map"))
plane = Plane()
attached = MesolightAttachReliefTexture(Input=plane, ReliefTexture=relief)
if len(args) > 1:
    lights = MesolightMedianCutLights(Input=open_image(args[1]))
    check(lights, "the median-cut lights of %s" % args[1])
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
