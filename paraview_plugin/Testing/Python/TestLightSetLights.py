# SPDX-License-Identifier: BSD-3-Clause
"""ParaView surfaces lit by a light set (paraview_plugin/python/mesolight_light_set.py).

A white unit sphere, seen along +Y with a parallel camera, lit by three lights of a CSV: every
pixel's colour must be exposure x albedo / pi x (sum E_i max(0, n.d_i) + ambient), n the sphere
normal under the pixel: with all three lights as directional lights (ambient 0), and with one
light and the other two as the constant remainder (sum E / 4). Negative: ParaView's default light
kit, and the lights read with the y and z of their directions swapped, fail the same check. A
malformed CSV raises ValueError naming the line.
"""
import math
import os
import sys

import paraview.simple as pvs
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "python"))
from mesolight_light_set import apply_light_set, read_light_set  # noqa: E402

OUT = os.environ.get("MESOLIGHT_TEST_OUTPUT", ".")
os.makedirs(OUT, exist_ok=True)
SIZE = 200
SCALE = 1.1  # parallel scale: the sphere's radius is SIZE / 2 / SCALE pixels
EXPOSURE = 0.6


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


LIGHTS = [(normalize([0.3, -0.7, 0.6]), [2.0, 1.8, 1.5]),
          (normalize([-0.8, -0.3, 0.2]), [0.6, 0.7, 0.9]),
          (normalize([0.1, -0.2, -0.9]), [0.3, 0.25, 0.2])]

csv = os.path.join(OUT, "light-set-three.csv")
with open(csv, "w") as f:
    f.write("u,v,x,y,z,r,g,b\n")
    for d, e in LIGHTS:
        f.write("0,0,%r,%r,%r,%r,%r,%r\n" % (d[0], d[1], d[2], e[0], e[1], e[2]))

view = pvs.CreateView("RenderView")
view.ViewSize = [SIZE, SIZE]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.UseFXAA = 0
view.CameraPosition = [0.0, -5.0, 0.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = SCALE
sphere = pvs.Sphere(Radius=1.0, ThetaResolution=256, PhiResolution=128)
display = pvs.Show(sphere, view)
display.DiffuseColor = [1.0, 1.0, 1.0]
display.Specular = 0.0
display.Diffuse = 1.0


def render(name):
    path = os.path.join(OUT, name)
    pvs.SaveScreenshot(path, view, ImageResolution=[SIZE, SIZE])
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels[:, :3].astype(float).reshape(SIZE, SIZE, 3)  # rows bottom first


def error(image, lights, ambient):
    """Mean relative error over the sphere's inner pixels against the model."""
    errors = []
    for j in range(SIZE):
        for i in range(SIZE):
            x = ((i + 0.5) / SIZE * 2.0 - 1.0) * SCALE
            z = ((j + 0.5) / SIZE * 2.0 - 1.0) * SCALE
            r2 = x * x + z * z
            if r2 > 0.9:
                continue
            n = [x, -math.sqrt(1.0 - r2), z]
            e = list(ambient)
            for d, irradiance in lights:
                c = max(0.0, sum(n[k] * d[k] for k in range(3)))
                e = [e[k] + c * irradiance[k] for k in range(3)]
            expected = sum(min(255.0, 255.0 * EXPOSURE * e[k] / math.pi) for k in range(3))
            got = image[j, i].sum()
            errors.append(abs(got - expected) / max(expected, 30.0))
    return float(np.mean(errors))


failures = []


def check(name, value, low=None, high=None):
    ok = (low is None or value > low) and (high is None or value < high)
    print("%-44s %.4f %s" % (name, value, "ok" if ok else "FAILED"))
    if not ok:
        failures.append(name)


default = render("light-set-default.png")
check("default light kit vs the 3 lights (negative)", error(default, LIGHTS, [0, 0, 0]), low=0.15)

read = read_light_set(csv)
if len(read) != 3 or any(abs(a - b) > 1e-12 for (d, e), (rd, re) in zip(LIGHTS, read)
                         for a, b in zip(d + e, rd + re)):
    failures.append("read_light_set does not give the written lights back")
apply_light_set(view, csv, count=3, exposure=EXPOSURE, displays=[display])
all3 = render("light-set-three.png")
check("3 directional lights", error(all3, LIGHTS, [0, 0, 0]), high=0.03)

apply_light_set(view, csv, count=1, exposure=EXPOSURE, displays=[display])
one = render("light-set-one-plus-ambient.png")
ambient = [sum(e[k] for _, e in LIGHTS[1:]) / 4.0 for k in range(3)]
check("1 light + constant remainder (its model)", error(one, LIGHTS[:1], ambient), high=0.03)
check("1 light + remainder vs the 3 lights", error(one, LIGHTS, [0, 0, 0]), low=0.03)

flipped = [([d[0], d[2], d[1]], e) for d, e in LIGHTS]
apply_light_set(view, flipped, count=3, exposure=EXPOSURE, displays=[display])
wrong = render("light-set-flipped.png")
check("lights read y-up vs the 3 lights (negative)", error(wrong, LIGHTS, [0, 0, 0]), low=0.15)

bad = os.path.join(OUT, "light-set-bad.csv")
for text, needle in [("", "empty"), ("x,y\n", "line 1"), ("u,v,x,y,z,r,g,b\n0,0,0,0,1,1,1\n", "line 2: 7 fields"),
                     ("u,v,x,y,z,r,g,b\n0,0,0,0,1,nan,1,1\n", "NaN")]:
    with open(bad, "w") as f:
        f.write(text)
    try:
        read_light_set(bad)
        failures.append("accepted %r" % text)
    except ValueError as e:
        if needle not in str(e):
            failures.append("message %r lacks %r" % (str(e), needle))

# The plugin's reader gives the same lights (and the light texture for Attach Relief Texture).
pvs.LoadPlugin(os.environ["MESOLIGHT_PLUGIN"], remote=False, ns=pvs.__dict__)
reader = pvs.MesolightLightSetReader(FileName=csv)
reader.UpdatePipeline()
lights_data = pvs.servermanager.Fetch(reader, idx=0)
texture = pvs.servermanager.Fetch(reader, idx=1)
print("reader: %d lights, texture %s" % (lights_data.GetNumberOfPoints(), texture.GetDimensions()))
if lights_data.GetNumberOfPoints() != 3 or tuple(texture.GetDimensions()[:2]) != (3, 2):
    failures.append("Mesolight Light Set Reader")
else:
    e = lights_data.GetPointData().GetArray("Irradiance").GetTuple3(0)
    if any(abs(e[k] - LIGHTS[0][1][k]) > 1e-6 for k in range(3)):
        failures.append("Mesolight Light Set Reader irradiance %r" % (e,))

if failures:
    print("FAILED:", failures)
    sys.exit(1)
print("all checks passed")
