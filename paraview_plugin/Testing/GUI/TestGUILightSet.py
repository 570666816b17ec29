# SPDX-License-Identifier: BSD-3-Clause
"""GUI: the README pipeline with a light set (Procedural Environment -> Median Cut Lights,
its second output as Attach Relief Texture's Light Set), every proxy with its panel defaults,
applied as the GUI applies it. The first frame must be exposed, not blown out: fewer than
MAX_WHITE of the relief's pixels white (all channels >= 250) and its mean level within
[MIN_MEAN, MAX_MEAN]. Must fail (so the measure can fail): the old defaults (tone mapping
off), and tone mapping on at exposure 16."""
import os
import sys

# run-gui-test.sh puts this directory on PYTHONPATH (paraview --script defines no __file__).
import mesolight_guitest as g  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402

MAX_WHITE = 0.02
MIN_MEAN, MAX_MEAN = 40.0, 215.0


def exposure_stats(frame, mask):
    pixels = frame[mask]
    white = float(np.all(pixels >= 250, axis=1).mean()) if len(pixels) else 1.0
    mean = float(pixels.mean()) if len(pixels) else 0.0
    return white, mean


def well_exposed(white, mean):
    return white < MAX_WHITE and MIN_MEAN <= mean <= MAX_MEAN


def main():
    failures = []
    view = g.gui_view()
    p = g.readme_pipeline(view, lights=True)
    display = pvs.GetDisplayProperties(p["attached"], view)
    if display.Representation != "Relief Surface":
        failures.append("Apply should show Relief Surface, not %r" % display.Representation)
    frame = g.grab(view, "gui-light-set.png")
    display.Visibility = 0
    background = g.grab(view, "gui-light-set-background.png")
    display.Visibility = 1
    mask = g.covered(frame, background)
    coverage = float(mask.mean())
    white, mean = exposure_stats(frame, mask)
    print("defaults (Exposure %g, Tone Mapping %d): relief covers %.3f of the view, %.4f of it "
          "white, mean level %.1f" % (display.Exposure, display.ToneMapping, coverage, white, mean))
    if coverage < 0.25:
        failures.append("the relief should be framed (covers %.3f)" % coverage)
    if not well_exposed(white, mean):
        failures.append("the default light-set frame is not well exposed: %.4f white (max %.2f), "
                        "mean %.1f (range [%g, %g])" % (white, MAX_WHITE, mean, MIN_MEAN, MAX_MEAN))
    defaults = (display.ToneMapping, display.Exposure)
    for name, settings in (("old defaults (tone mapping off)", {"ToneMapping": 0}),
                           ("exposure 16", {"Exposure": 16.0})):
        for key, value in settings.items():
            setattr(display, key, value)
        bad = g.grab(view, "gui-light-set-%s.png" % "-".join("%s%s" % kv for kv in settings.items()))
        display.ToneMapping, display.Exposure = defaults
        bad_white, bad_mean = exposure_stats(bad, mask)
        print("%s: %.4f white, mean level %.1f" % (name, bad_white, bad_mean))
        if well_exposed(bad_white, bad_mean):
            failures.append("negative check: %s should count as badly exposed" % name)
    return failures


g.run(main)
