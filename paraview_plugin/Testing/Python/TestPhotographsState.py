# SPDX-License-Identifier: BSD-3-Clause
"""examples/photographs-to-model.pvsm (two photographs -> depth hallucination -> relief texture on
a geometry image's macro mesh, lit by median-cut lights) loads in pvbatch from this checkout's
photographs (data_directory) and renders the relief model: it covers much of the view, the light
set lights it (exposure 0 must darken it), and the hallucinated depth shows (a relief flattened to
depth 0 must change the image), and the hallucinated albedo colours it (the stone is warm: taking
the Color Texture input away must make the model bluer, by about the albedo's own red/blue ratio)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402

t.load_plugin()
state = os.environ["MESOLIGHT_PHOTOGRAPHS_STATE"]
photographs = os.environ["MESOLIGHT_PHOTOGRAPHS_DIR"]
pvs.LoadState(state, data_directory=photographs)
view = pvs.GetRenderViews()[0]
view.ViewSize = [300, 300]
model = pvs.FindSource("Relief model")
display = pvs.GetDisplayProperties(model, view)
out = t.output_dir()
failures = []
if display.Representation != "Relief Surface":
    failures.append("the state should show the model with the Relief Surface representation")


def shot(name):
    pvs.Render(view)
    path = os.path.join(out, name)
    pvs.SaveScreenshot(path, view, ImageResolution=[300, 300], TransparentBackground=0)
    return t.capture_file(path)


lit = shot("pv-photographs-state.png")
background = lit[2, 2]
covered = np.any(np.abs(lit.astype(int) - background.astype(int)) > 8, axis=2)


def red_over_blue(image):
    pixels = image[covered].astype(float)
    return pixels[:, 0].mean() / max(pixels[:, 2].mean(), 1.0)


albedo = model.ColorTexture
model.ColorTexture = []
uncoloured = shot("pv-photographs-state-no-albedo.png")
model.ColorTexture = albedo


def attached(name):
    model.UpdatePipeline()
    return any(model.FieldData.GetArray(i).Name == name
               for i in range(model.FieldData.GetNumberOfArrays()))


# Emptying an optional input disconnects it (null_on_empty): before, the filter kept the old one.
lights = model.LightSet
model.LightSet = []
if attached("MesolightLightSet"):
    failures.append("emptying Light Set should detach the light set")
model.LightSet = lights
if not attached("MesolightLightSet") or not attached("MesolightColorTexture"):
    failures.append("the light set and albedo should be attached again")
colour_gain = red_over_blue(lit) / red_over_blue(uncoloured) if covered.any() else 0.0
display.OverrideDepthScale = 1
display.ReliefDepthScale = 0.0
flat = shot("pv-photographs-state-flat.png")
display.OverrideDepthScale = 0
display.Exposure = 0.0
dark = shot("pv-photographs-state-exposure0.png")
coverage = 100.0 * covered.mean()
brightness = float(lit[covered].mean()) if covered.any() else 0.0
dark_brightness = float(dark[covered].mean()) if covered.any() else 0.0
relief_change = float(np.abs(lit.astype(int) - flat.astype(int))[covered].mean()) if covered.any() else 0.0
print("model covers %.1f%% of the view; mean level %.1f lit, %.1f at exposure 0; the relief "
      "changes the model by %.2f levels on average" % (coverage, brightness, dark_brightness,
                                                        relief_change))
if coverage < 20.0:
    failures.append("the model should cover much of the view")
if brightness < dark_brightness + 30.0:
    failures.append("the light set should light the model")
print("red/blue of the model with the albedo over without: %.3f (the photographs' mean red/blue: "
      "1.34)" % colour_gain)
if colour_gain < 1.12:
    failures.append("the hallucinated albedo should colour the model (Color Texture input)")
if relief_change < 2.0:
    failures.append("the hallucinated relief should show")
if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
