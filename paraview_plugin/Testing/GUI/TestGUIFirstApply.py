# SPDX-License-Identifier: BSD-3-Clause
"""GUI: the README pipeline as a first-time user builds it (every proxy with its panel defaults,
each applied as the GUI applies it), in the view the GUI opened, at the GUI's own view size.

Checks the first frame: the surface is shown as Relief Surface (the filter's hint), the images
and the plane are hidden, and the relief is framed (it covers more than MIN_COVERED of the view,
not a dot). Then the one source of truth for the depth scale: Relief Texture's Depth Scale
changes the image (the representation follows the bake), the representation's Relief Depth
Scale does nothing until Override Depth Scale is on, and then it does. Must fail: the old
README display (the images left visible, as before the hints) covers a dot; the negative case
is built by showing the images again in the same view."""
import os
import sys

# run-gui-test.sh puts this directory on PYTHONPATH (paraview --script defines no __file__).
import mesolight_guitest as g  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402

MIN_COVERED = 0.25      # fraction of the view the framed relief covers (measured ~0.5)
MIN_CHANGED = 0.005     # fraction of the view a depth scale change must change


def changed_fraction(a, b):
    return float(np.any(np.abs(a - b) > 2, axis=2).mean())


def main():
    failures = []
    view = g.gui_view()
    p = g.readme_pipeline(view)
    display = pvs.GetDisplayProperties(p["attached"], view)
    frame = g.grab(view, "gui-first-apply.png")
    print("view %s, representation %r, interaction mode %s"
          % (list(view.ViewSize), display.Representation, view.InteractionMode))
    if display.Representation != "Relief Surface":
        failures.append("Apply should show Attach Relief Texture as Relief Surface, not %r"
                        % display.Representation)
    visible = [rep.Input.GetXMLLabel() for rep in g.visible_data_representations(view)]
    print("visible after the README pipeline: %s" % visible)
    if visible != [p["attached"].GetXMLLabel()]:
        failures.append("only the relief surface should be visible, not %s" % visible)

    display.Visibility = 0
    background = g.grab(view, "gui-first-apply-background.png")
    display.Visibility = 1
    coverage = float(g.covered(frame, background).mean())
    print("relief covers %.3f of the view (threshold %.2f)" % (coverage, MIN_COVERED))
    if coverage < MIN_COVERED:
        failures.append("the relief covers %.3f of the view: not framed" % coverage)

    # Negative check of the coverage measure: the camera reset to the images as well (what a
    # user got before the hints): the unit relief is a dot beside the 255-unit images.
    images = [pvs.OutputPort(p["depth"], 0), pvs.OutputPort(p["depth"], 1), p["relief"]]
    for port in images:
        pvs.Show(port, view)
    pvs.Render(view)
    view.ResetCamera(False)
    g.grab(view, "gui-first-apply-with-images.png")
    for port in images:
        pvs.Hide(port, view)
    relief_only = g.grab(view, "gui-first-apply-images-camera.png")
    display.Visibility = 0
    empty = g.grab(view, "gui-first-apply-images-camera-background.png")
    display.Visibility = 1
    dot = float(g.covered(relief_only, empty).mean())
    print("under the camera framing the images too, the relief covers %.4f of the view "
          "(must be < %.2f)" % (dot, MIN_COVERED))
    if dot >= MIN_COVERED:
        failures.append("negative check: framed with the images the relief should be a dot")

    # One source of truth for the depth scale.
    view.ResetCamera(False)
    view.CameraPosition = [0.0, -1.3, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    base = g.grab(view, "gui-depth-0.05.png")
    p["relief"].DepthScale = 0.15
    baked = g.grab(view, "gui-depth-bake-0.15.png")
    display.ReliefDepthScale = 0.4
    ignored = g.grab(view, "gui-depth-bake-0.15-repr-0.4.png")
    display.OverrideDepthScale = 1
    overridden = g.grab(view, "gui-depth-override-0.4.png")
    c_bake = changed_fraction(base, baked)
    c_ignored = changed_fraction(baked, ignored)
    c_override = changed_fraction(baked, overridden)
    print("Relief Texture Depth Scale 0.05 -> 0.15 changes %.4f of the view; Relief Depth "
          "Scale 0.4 without override %.4f, with override %.4f" % (c_bake, c_ignored, c_override))
    if c_bake < MIN_CHANGED:
        failures.append("Relief Texture's Depth Scale should change the image")
    if c_ignored != 0.0:
        failures.append("Relief Depth Scale should do nothing without Override Depth Scale")
    if c_override < MIN_CHANGED:
        failures.append("Relief Depth Scale with Override Depth Scale should change the image")
    return failures


g.run(main)
