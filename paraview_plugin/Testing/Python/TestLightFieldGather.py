# SPDX-License-Identifier: BSD-3-Clause
"""Light Field Gather in ParaView (Wither 2005 §3.6), through the plugin's proxies:

- furnace: a closed cube emitting Le = 1 with albedo 0.5 everywhere (an OBJ + MTL written here,
  read by the Mesolight OBJ Scene Reader), 3 iterations: the radiance everywhere inside is
  Le (1 + 0.5 + 0.25 + 0.125), so the irradiance gathered on a sphere inside is pi times that at
  every point and in every direction, within 1% (an answer that does not come from the field);
  negative: the field of 1 iteration must fail the same check;
- Radiance = Reflectance / pi x Irradiance;
- a sphere inside the Cornell box's field: finite, the top (facing the light) brighter than the
  bottom, and the side facing the red wall (+x) redder than the side facing the green one;
- a Light Field input that is not a light field is an error message, not a crash;
- drawn as Light Field, the sphere moved by a Transform after the gather is warned about (its
  light was gathered where it was); the gather and a Clip after it are not.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

t.load_plugin()
failures = []
check = t.checker(failures)

def arrays(proxy):
    proxy.UpdatePipeline()
    data = servermanager.Fetch(proxy)
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    pd = data.GetPointData()
    e = pd.GetArray("Irradiance")
    radiance = pd.GetArray("Radiance")
    normals = pd.GetNormals()
    if e is None or radiance is None:
        return points, None, None, None
    return (points, vtk_to_numpy(e).astype(np.float64), vtk_to_numpy(radiance).astype(np.float64),
            vtk_to_numpy(normals).astype(np.float64) if normals is not None else None)


# --- Furnace -----------------------------------------------------------------------------------
output = os.environ.get("MESOLIGHT_TEST_OUTPUT", ".")
os.makedirs(output, exist_ok=True)
obj = os.path.join(output, "gather-furnace.obj")
with open(os.path.join(output, "gather-furnace.mtl"), "w") as f:
    f.write("newmtl furnace\nKd 0.5 0.5 0.5\nKs 0 0 0\nKe 1 1 1\n")
with open(obj, "w") as f:
    f.write("mtllib gather-furnace.mtl\nusemtl furnace\n")
    for x in (-1, 1):
        for y in (-1, 1):
            for z in (-1, 1):
                f.write("v %d %d %d\n" % (x, y, z))
    # Vertex index = 1 + 4 (x > 0) + 2 (y > 0) + (z > 0); the faces below are counter-clockwise
    # seen from outside, so written reversed: fronts face the centre.
    faces = [(1, 2, 4, 3), (5, 7, 8, 6),   # x = -1, x = +1
             (1, 5, 6, 2), (3, 4, 8, 7),   # y = -1, y = +1
             (1, 3, 7, 5), (2, 6, 8, 4)]   # z = -1, z = +1
    for face in faces:
        f.write("f %d %d %d %d\n" % tuple(reversed(face)))

reader = pvs.MesolightOBJSceneReader(FileName=obj)
sphere = pvs.Sphere(Center=[0.1, -0.05, 0.0], Radius=0.3, ThetaResolution=16, PhiResolution=10)
expected = math.pi * (1.0 + 0.5 + 0.25 + 0.125)
for iterations, should_pass in ((3, True), (1, False)):
    # FinalGather off: the gather adds a bounce to the iterations this check counts.
    field = pvs.MesolightVirtualLightField(Input=reader, Directions=513, RaysPerSide=24,
                                           Iterations=iterations, FinalGather=0)
    gather = pvs.MesolightLightFieldGather(Input=sphere, LightField=field)
    points, e, radiance, normals = arrays(gather)
    if e is None:
        check(False, "furnace: the output has Irradiance and Radiance")
        continue
    worst = float(np.max(np.abs(e - expected) / expected))
    print("furnace, %d iterations: irradiance %.4f..%.4f, expected %.4f, worst %.4f"
          % (iterations, e.min(), e.max(), expected, worst))
    if should_pass:
        check(worst < 0.01, "furnace (3 iterations): irradiance pi Le sum rho^i within 1%% "
              "at every point (worst %.4f)" % worst)
        check(np.allclose(radiance, 0.7 / math.pi * e, rtol=1e-5, atol=1e-7),
              "Radiance = 0.7 / pi x Irradiance")
        gather.Reflectance = [0.35, 0.35, 0.35]
        _, e2, radiance2, _ = arrays(gather)
        check(np.allclose(radiance2, 0.35 / math.pi * e2, rtol=1e-5, atol=1e-7),
              "Reflectance 0.35: Radiance = 0.35 / pi x Irradiance")
    else:
        check(worst > 0.05, "negative: a 1-iteration field fails the 3-iteration furnace "
              "(worst %.4f)" % worst)
    pvs.Delete(gather)
    pvs.Delete(field)

# --- A sphere in the Cornell box ----------------------------------------------------------------
box = pvs.MesolightCornellBox()
field = pvs.MesolightVirtualLightField(Input=box, Directions=513, RaysPerSide=32, Iterations=3)
ball = pvs.Sphere(Center=[200.0, 300.0, 150.0], Radius=60.0, ThetaResolution=24,
                  PhiResolution=12)
gather = pvs.MesolightLightFieldGather(Input=ball, LightField=field)
points, e, radiance, normals = arrays(gather)
check(e is not None and normals is not None and np.all(np.isfinite(e)) and e.shape[1] == 3,
      "Cornell sphere: finite RGB Irradiance at every point")
if e is not None and normals is not None:
    lum = e @ np.array([0.2126, 0.7152, 0.0722])
    top = lum[normals[:, 1] > 0.7].mean()
    bottom = lum[normals[:, 1] < -0.7].mean()
    check(top > 2.0 * bottom, "Cornell sphere: the top (toward the light) is brighter than the "
          "bottom (%.3f vs %.3f)" % (top, bottom))
    red_side = e[normals[:, 0] > 0.7]
    green_side = e[normals[:, 0] < -0.7]
    ratio_red = (red_side[:, 0] / red_side[:, 1]).mean()
    ratio_green = (green_side[:, 0] / green_side[:, 1]).mean()
    check(ratio_red > 1.2 * ratio_green, "Cornell sphere: colour bleeding, the side facing the "
          "red wall is redder (R/G %.3f vs %.3f)" % (ratio_red, ratio_green))

# --- Moved after the gather: said when drawn ------------------------------------------------------
# A Transform after the gather moves the sphere away from where its light was gathered and turns
# its Radiance as a vector (rotated about y, its blue channel becomes minus its red); drawn as
# Light Field it is warned about. The gather itself, and a Clip after it (its cut points
# interpolated, the gathered positions alike), are not.
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.vtkCommonCore import (VTK_STRING, vtkCommand, vtkOutputWindow,  # noqa: E402
                                      vtkStringOutputWindow)

view = pvs.CreateView("RenderView")
view.ViewSize = [200, 200]


def warnings_drawing(source):
    said = []

    @calldata_type(VTK_STRING)
    def on_warning(caller, event, text):
        said.append(text)

    window = vtkOutputWindow.GetInstance()
    tag = window.AddObserver(vtkCommand.WarningEvent, on_warning)
    shown = pvs.Show(source, view)
    shown.SetRepresentationType("Light Field")
    pvs.ResetCamera(view)  # framed, so that it is drawn (an object out of view is culled)
    pvs.SaveScreenshot(os.path.join(t.output_dir(), "pv-gather-moved.png"), view)
    window.RemoveObserver(tag)
    pvs.Hide(source, view)
    return sum("moved after Light Field Gather" in w for w in said), shown


turned = pvs.Transform(Input=gather)
turned.Transform.Rotate = [0.0, 90.0, 0.0]
_, _, turned_radiance, _ = arrays(turned)
print("Radiance ranges (R, G, B): gathered %s, after a Transform (Rotate 0, 90, 0) %s"
      % ([(round(float(c.min()), 4), round(float(c.max()), 4)) for c in radiance.T],
         [(round(float(c.min()), 4), round(float(c.max()), 4)) for c in turned_radiance.T]))
check(turned_radiance[:, 2].max() < 0.0, "a Transform after the gather turns its Radiance as a "
      "vector (blue negative): what the warning below is for")
clipped = pvs.Clip(Input=gather, ClipType="Plane")
clipped.ClipType.Origin = [200.0, 300.0, 150.0]
clipped.Crinkleclip = 0
clipped_poly = pvs.ExtractSurface(Input=clipped)
for name, source, expected in (("the gather", gather, 0), ("a Clip after it", clipped_poly, 0),
                               ("a Transform after it", turned, 1)):
    count, shown = warnings_drawing(source)
    print("drawn as Light Field, %s: %d warning(s) of a move" % (name, count))
    check(count == expected, "%s: %d warning(s) of a move after the gather (%d expected)"
          % (name, count, expected))

# --- Bad input ------------------------------------------------------------------------------
plane = pvs.Plane()
bad = pvs.MesolightLightFieldGather(Input=ball, LightField=plane)
messages = vtkStringOutputWindow()
previous = vtkOutputWindow.GetInstance()
vtkOutputWindow.SetInstance(messages)
bad.UpdatePipeline()
vtkOutputWindow.SetInstance(previous)
text = messages.GetOutput()
check("Virtual Light Field" in text, "a Light Field input that is not a light field is an error "
      "message")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
