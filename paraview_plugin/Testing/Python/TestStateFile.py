# SPDX-License-Identifier: BSD-3-Clause
"""examples/relief-environment.pvsm loads in pvbatch (after LoadPlugin) and renders a relief
surface lit by the median-cut lights of the default environment: the relief covers much of the
view, and it is lit by the light set (no light kit in that state), so switching the light set
off (Exposure 0) must darken it."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402

t.load_plugin()
state = os.environ.get("MESOLIGHT_STATE_FILE") or sys.argv[-1]
pvs.LoadState(state)
view = pvs.GetRenderViews()[0]
view.ViewSize = [400, 300]
attached = pvs.FindSource("Relief surface")
display = pvs.GetDisplayProperties(attached, view)
out = t.output_dir()
failures = []
if display.Representation != "Relief Surface":
    failures.append("the state should show the relief with the Relief Surface representation")


def shot(name):
    pvs.Render(view)
    path = os.path.join(out, name)
    pvs.SaveScreenshot(path, view, ImageResolution=[400, 300], TransparentBackground=0)
    return t.capture_file(path)


lit = shot("pv-state.png")
background = lit[2, 2]  # a corner: the view's background
relief = np.any(np.abs(lit - background) > 8, axis=2)
display.Exposure = 0.0
dark = shot("pv-state-exposure0.png")
coverage = 100.0 * relief.mean()
brightness = float(lit[relief].mean()) if relief.any() else 0.0
dark_brightness = float(dark[relief].mean()) if relief.any() else 0.0
print("relief covers %.1f%% of the view; mean level %.1f lit by the environment, %.1f at exposure 0"
      % (coverage, brightness, dark_brightness))
if coverage < 30.0:
    failures.append("the relief should cover much of the view")
if brightness < dark_brightness + 30.0:
    failures.append("the environment's light set should light the relief")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
