# SPDX-License-Identifier: BSD-3-Clause
"""The Relief Surface's Surface Curvature checkbox (vtkReliefProperty::SurfaceCurvature, the
command line's `mesolight render --no-surface-curvature`) on a curved surface: a sphere with its
texture map, a relief marched along the sphere's curvature (on, the default) must differ from the
same relief marched as if each pixel's surface were its tangent plane (off): the outline of the
sphere shows the relief's profile only with it. Negative: on a flat surface the checkbox changes
nothing (the flat march is drawn whatever it says)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402

MIN_CHANGED = 200  # pixels differing by more than 8 levels on the sphere

t.load_plugin()
failures = []
check = t.checker(failures)
out = t.output_dir()
view = t.make_view()


def capture(name):
    pvs.Render(view)
    path = os.path.join(out, name)
    pvs.SaveScreenshot(path, view, ImageResolution=t.SIZE, TransparentBackground=0)
    return t.capture_file(path).astype(int)


def changed(a, b):
    return int((np.abs(a - b).max(axis=2) > 8).sum())


sphere = pvs.TextureMaptoSphere(Input=pvs.Sphere(Center=[0.5, 0.45, 0.0], Radius=0.45,
                                                 ThetaResolution=64, PhiResolution=64))
attached, display = t.show_relief(sphere, t.relief_texture(256), view, OverrideDepthScale=1,
                                  ReliefDepthScale=0.08)
check(display.SurfaceCurvature == 1, "Surface Curvature is on by default")
on = capture("pv-curvature-on.png")
display.SurfaceCurvature = 0
off = capture("pv-curvature-off.png")
n = changed(on, off)
print("sphere: %d pixels differ by > 8 levels between Surface Curvature on and off" % n)
check(n >= MIN_CHANGED, "Surface Curvature changes the relief on a sphere (>= %d pixels)"
      % MIN_CHANGED)
display.SurfaceCurvature = 1
pvs.Hide(attached, view)

# Negative: a flat square draws the flat march either way.
flat_attached, flat = t.show_relief(t.unit_square(4), t.relief_texture(256), view)
flat_on = capture("pv-curvature-flat-on.png")
flat.SurfaceCurvature = 0
flat_off = capture("pv-curvature-flat-off.png")
m = changed(flat_on, flat_off)
print("flat square: %d pixels differ" % m)
check(m == 0, "Surface Curvature changes nothing on a flat surface")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
