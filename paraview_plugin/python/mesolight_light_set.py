# SPDX-License-Identifier: BSD-3-Clause
"""Lights a ParaView render view by a Mesolight light set (pvpython / pvbatch / Python Shell).

The light set is the CSV `mesolight lights ENV --count N --out lights.csv` writes (header
"u,v,x,y,z,r,g,b": map coordinates, unit direction toward the light with +Z up, irradiance at
normal incidence). As vtkLightSetLighting does for VTK actors (docs/light-set-actors.md):

- the `count` lights of largest luminance become directional scene lights of the view
  (view.AdditionalLights; colour x intensity = exposure x irradiance / pi), so a white Lambertian
  surface shows exposure x albedo / pi x sum E_i max(0, n.d_i);
- the others become the surfaces' ambient term: their irradiance averaged over all normals
  (sum E_i / 4), as Ambient = 1 and AmbientColor = exposure x DiffuseColor x that / pi. ParaView
  has no per-pixel hook for vtkLightSetLighting's spherical-harmonic remainder (it needs a shader
  uniform updated every frame), so this is its constant model: 22% mean error on a sphere under
  the procedural sky with 8 of 256 lights, against 0.2% for the SH remainder; give more lights
  (count) for less;
- the view's light kit is turned off.

    import sys; sys.path.append("<mesolight>/paraview_plugin/python")
    from mesolight_light_set import apply_light_set
    apply_light_set(GetActiveView(), "lights.csv", count=8, exposure=1.0,
                    displays=[GetDisplayProperties(source)])

apply_light_set again replaces the lights it added before.
"""
import math

HEADER = "u,v,x,y,z,r,g,b"
LIGHT_NAME = "Mesolight light set"  # marks the lights apply_light_set adds (and replaces)


def read_light_set(path):
    """[(direction, irradiance)] of a light-set CSV; ValueError naming the line on bad input."""
    lights = []
    with open(path, "r", encoding="utf-8", errors="replace") as f:
        lines = f.read().splitlines()
    if not lines or not lines[0].strip():
        raise ValueError("%s is empty (expected the header %s)" % (path, HEADER))
    if lines[0].strip() != HEADER:
        raise ValueError("%s, line 1: the header is %r, expected %r" % (path, lines[0].strip()[:80], HEADER))
    for number, line in enumerate(lines[1:], start=2):
        if not line.strip():
            continue
        fields = line.split(",")
        if len(fields) != 8:
            raise ValueError("%s, line %d: %d fields, expected 8" % (path, number, len(fields)))
        try:
            values = [float(x) for x in fields]
        except ValueError:
            raise ValueError("%s, line %d: a field is not a number" % (path, number)) from None
        if not all(math.isfinite(v) for v in values):
            raise ValueError("%s, line %d: NaN or infinite value" % (path, number))
        d = values[2:5]
        length = math.sqrt(sum(c * c for c in d))
        if abs(length - 1.0) > 1e-3:
            raise ValueError("%s, line %d: the direction has length %g" % (path, number, length))
        if min(values[5:8]) < 0.0:
            raise ValueError("%s, line %d: negative irradiance" % (path, number))
        lights.append((d, values[5:8]))
    if not lights:
        raise ValueError("%s has a header but no lights" % path)
    return lights


def _luminance(e):
    return 0.2126 * e[0] + 0.7152 * e[1] + 0.0722 * e[2]  # Rec. 709, as common/Luminance.h


def apply_light_set(view, light_set, count=8, exposure=1.0, displays=()):
    """Lights `view` (and the ambient of `displays`) by a light set: a CSV path or the list
    read_light_set returns. Returns the light proxies added."""
    import paraview.simple as pvs

    lights = read_light_set(light_set) if isinstance(light_set, str) else list(light_set)
    order = sorted(range(len(lights)), key=lambda i: -_luminance(lights[i][1]))
    count = max(0, min(int(count), len(lights)))
    strongest = [lights[i] for i in order[:count]]
    rest = [lights[i] for i in order[count:]]

    for light in list(view.AdditionalLights):
        if light.Name == LIGHT_NAME:
            pvs.RemoveLight(light)
    view.UseLight = 0  # the light kit
    added = []
    for d, e in strongest:
        m = max(e)
        light = pvs.AddLight(view=view)
        light.Type = "Directional"
        light.Coords = "Scene"
        light.Position = list(d)
        light.FocalPoint = [0.0, 0.0, 0.0]
        light.DiffuseColor = [c / m for c in e] if m > 0.0 else [1.0, 1.0, 1.0]
        light.Intensity = exposure * m / math.pi
        light.Name = LIGHT_NAME
        added.append(light)

    average = [sum(e[c] for _, e in rest) / 4.0 for c in range(3)]
    for display in displays:
        colour = display.DiffuseColor
        display.Ambient = 1.0 if rest else 0.0
        display.AmbientColor = [colour[c] * exposure * average[c] / math.pi for c in range(3)]
    return added
