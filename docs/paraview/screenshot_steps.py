# SPDX-License-Identifier: BSD-3-Clause
"""Builds the GUI state of one walk-through step (MESOLIGHT_SCREENSHOT_STEP: 1, 2 or 3) in the
running `paraview` (run by screenshots.sh with --script), then writes MESOLIGHT_SCREENSHOT_READY
so the window can be grabbed once Qt has painted it. Apply as the GUI tests do it
(paraview_plugin/Testing/GUI/mesolight_guitest.py)."""
import os

import mesolight_guitest as g
import paraview.simple as pvs

step = int(os.environ.get("MESOLIGHT_SCREENSHOT_STEP", "1"))
view = g.gui_view()
if step == 1:
    depth = pvs.MesolightProceduralRelief()
    g.apply(depth, view)
else:
    p = g.readme_pipeline(view, lights=(step == 3))
    display = pvs.GetDisplayProperties(p["attached"], view)
    if step == 3:
        # The view is in 3D interaction after the pipeline (the relief's proxy class); the user
        # orbits to an oblique view.
        view.CameraPosition = [0.0, -1.25, 0.9]
        view.CameraFocalPoint = [0.0, 0.0, -0.05]
        view.CameraViewUp = [0.0, 0.0, 1.0]
    pvs.Render(view)
with open(os.environ["MESOLIGHT_SCREENSHOT_READY"], "w") as f:
    f.write("ready\n")
