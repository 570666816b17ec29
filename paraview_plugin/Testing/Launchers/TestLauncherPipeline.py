# SPDX-License-Identifier: BSD-3-Clause
"""Run by scripts/pvpython.sh and scripts/pvbatch.sh without a display (run-launcher-test.sh):
the README's relief pipeline, LoadPlugin beside the launcher's auto-load, one rendered frame
that must show the relief. Prints OK or raises."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403 (the README's usage)
import paraview.simple as pvs
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

# Already auto-loaded (PV_PLUGIN_PATH): must not print "Plugin load failed".
LoadPlugin(os.environ["MESOLIGHT_PLUGIN"], ns=globals())
depth = MesolightProceduralRelief()
relief = MesolightReliefTexture(Input=depth)
plane = Plane()
attached = MesolightAttachReliefTexture(Input=plane, ReliefTexture=relief)
view = CreateRenderView()
view.ViewSize = [240, 240]
view.UseColorPaletteForBackground = 0  # else ParaView 5.11 ignores Background
view.Background = [0.0, 0.0, 0.0]
view.OrientationAxesVisibility = 0
display = Show(attached, view)
display.SetRepresentationType("Relief Surface")
ResetCamera(view)
out = os.environ.get("MESOLIGHT_TEST_OUTPUT", ".")
os.makedirs(out, exist_ok=True)
path = os.path.join(out, "launcher-%s.png" % os.environ.get("MESOLIGHT_LAUNCHER", "x"))
SaveScreenshot(path, view, ImageResolution=[240, 240], TransparentBackground=0)
reader = vtkPNGReader()
reader.SetFileName(path)
reader.Update()
pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)
lit = (pixels.max(axis=1) > 8).mean()
levels = len(set(pixels[:, 0].astype(int)))
print("relief covers %.3f of the frame, %d red levels" % (lit, levels))
if lit < 0.3 or levels < 20:
    raise SystemExit("FAILED: no shaded relief in the frame")
print("OK")
sys.stdout.flush()
