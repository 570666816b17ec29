# SPDX-License-Identifier: BSD-3-Clause
"""Mesolight Geometry Image To Mesh in ParaView (Gu et al. 2002): a cylinder written as a
geometry image (Mesolight Geometry Image) sampled every 16 pixels gives 2 x 8 x 8 triangles with
Normals and texture coordinates at texel centres; adaptive sampling of a bump needs fewer
triangles than the full resolution; NaN holes drop triangles; the mesh shown as a Relief Surface
draws the relief (differs from the plain surface); a depth image (one component) is refused with
a message. The comparison against the dense displaced mesh runs in the main build
(ctest -R GeometryImage)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
import numpy as np  # noqa: E402

t.load_plugin()
out = t.output_dir()
failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


# 1. Regular sampling: counts, arrays, texel-centre coordinates.
cylinder = pvs.MesolightGeometryImage(Surface=1, Resolution=[129, 129])
mesh = pvs.MesolightGeometryImageToMesh(Input=cylinder, Stride=16)
data = servermanager.Fetch(mesh)
check(data.GetNumberOfCells() == 2 * 8 * 8, "stride 16 on 129 x 129: 128 triangles (got %d)"
      % data.GetNumberOfCells())
tcoords = data.GetPointData().GetTCoords()
check(tcoords is not None and data.GetPointData().GetNormals() is not None,
      "the mesh has texture coordinates and normals")
if tcoords is not None:
    i = vtk_to_numpy(tcoords)[:, 0] * 129 - 0.5
    check(np.allclose(i, np.round(i), atol=1e-4) and np.all(np.round(i) % 16 == 0),
          "texture coordinates are the sampled pixels' texel centres")

# 2. Adaptive sampling and holes.
bump = pvs.MesolightGeometryImage(Surface=4, Resolution=[129, 129])
adaptive = pvs.MesolightGeometryImageToMesh(Input=bump, Tolerance=0.002)
n_adaptive = servermanager.Fetch(adaptive).GetNumberOfCells()
check(0 < n_adaptive < 2 * 32 * 32, "adaptive (tolerance 0.002) on the bump: %d triangles" % n_adaptive)
holes = pvs.MesolightGeometryImage(Surface=1, Resolution=[129, 129], Holes=1)
n_holes = servermanager.Fetch(pvs.MesolightGeometryImageToMesh(Input=holes, Stride=16)).GetNumberOfCells()
check(0 < n_holes < 2 * 8 * 8, "NaN holes drop triangles (%d of 128 left)" % n_holes)

# 3. The coarse cylinder as a Relief Surface against the same mesh as a plain Surface.
big = pvs.MesolightGeometryImage(Surface=1, Resolution=[256, 256])
coarse = pvs.MesolightGeometryImageToMesh(Input=big, Stride=16)
relief = t.relief_texture(256)


def render_alone(name, make):
    view = t.make_view()
    make(view)
    return t.capture(view, os.path.join(out, "pv-geometry-image-%s.png" % name))


def plain(view):
    display = pvs.Show(coarse, view)
    display.ColorArrayName = ["POINTS", ""]


flat = render_alone("surface", plain)
drawn = render_alone("relief", lambda v: t.show_relief(coarse, relief, v, SelfShadowing=0))
both = t.covered(flat) & t.covered(drawn)
difference = float(np.abs(flat[both] - drawn[both]).mean()) if both.any() else 0.0
check(int(both.sum()) > t.SIZE[0] * t.SIZE[1] // 8, "the cylinder covers much of the view (%d px)"
      % int(both.sum()))
check(difference > 5.0, "the relief changes the image (mean %.1f levels from the plain surface)"
      % difference)

# 4. Bad input: a depth image is not a geometry image.
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow  # noqa: E402
depth = pvs.MesolightProceduralRelief(Pattern=0, Resolution=[32, 32])
bad = pvs.MesolightGeometryImageToMesh(Input=pvs.OutputPort(depth, 0))
messages = vtkStringOutputWindow()
previous = vtkOutputWindow.GetInstance()
vtkOutputWindow.SetInstance(messages)
bad.UpdatePipeline()
vtkOutputWindow.SetInstance(previous)
check("3 components" in messages.GetOutput(), "a depth image is refused with a clear message")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("OK")
