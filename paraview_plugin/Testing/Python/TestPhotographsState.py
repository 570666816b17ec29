# SPDX-License-Identifier: BSD-3-Clause
"""examples/photographs-to-model.pvsm (two photographs -> depth hallucination -> relief texture on
a geometry image's macro mesh, lit by median-cut lights) loads in pvbatch from this checkout's
photographs (data_directory) and renders the relief model: it covers much of the view, the light
set lights it (exposure 0 must darken it), and the hallucinated depth shows (a relief flattened to
depth 0 must change the image)."""
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
if relief_change < 2.0:
    failures.append("the hallucinated relief should show")
if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
