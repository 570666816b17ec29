# SPDX-License-Identifier: BSD-3-Clause
"""The README pipeline in ParaView's Python, on your own files or the procedural ones:
    scripts/pvpython.sh examples/paraview/first-relief.py [DEPTH_IMAGE [ENVIRONMENT.hdr]]
    scripts/pvbatch.sh  examples/paraview/first-relief.py [DEPTH_IMAGE [ENVIRONMENT.hdr]]
    scripts/paraview.sh --script=examples/paraview/first-relief.py   (the GUI, procedural)
DEPTH_IMAGE: 0 = the surface, 1 = the deepest (8/16-bit PNG, TIFF, EXR...); writes relief.png.
The plugin is auto-loaded by the launchers (LoadPlugin is not needed)."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403


def open_image(path):
    # For .png/.tif ParaView also offers GDAL Raster Reader, whose pixels are cell data.
    if path.lower().endswith(".png"):
        return PNGSeriesReader(FileNames=[path])
    if path.lower().endswith((".tif", ".tiff")):
        return TIFFSeriesReader(FileNames=[path])
    if path.lower().endswith((".exr", ".hdr")):
        return MesolightImageReader(FileName=path)  # OpenImageIO
    return OpenDataFile(path)


args = [a for a in sys.argv[1:] if not a.startswith("-")]
depth = open_image(args[0]) if args else MesolightProceduralRelief()
relief = MesolightReliefTexture(Input=depth)
plane = Plane()
attached = MesolightAttachReliefTexture(Input=plane, ReliefTexture=relief)
if len(args) > 1:
    lights = MesolightMedianCutLights(Input=open_image(args[1]))
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
