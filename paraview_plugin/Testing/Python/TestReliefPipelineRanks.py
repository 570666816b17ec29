# SPDX-License-Identifier: BSD-3-Clause
"""The README's relief pipeline as a user types it, on one rank and under `mpiexec -n 2`.

Mesolight Procedural Relief (or the Mesolight Image Reader on a file) -> Relief Texture ->
Relief Plane -> Attach Relief Texture, shown as a Relief Surface and rendered straight away,
with no UpdatePipeline first. Under two ranks each rank asks for its piece: an image source that
cannot split runs for piece 0 only, and every other rank used to get an empty image. Relief
Texture, Relief Plane and Attach then failed there, and the representation's exchange between
the ranks aborted pvbatch (MPI_ERR_TRUNCATE). Every whole-image filter now asks for piece 0 of
1, and Relief Plane's quad is piece 0's. ctest fails the test on any error line ("ERR|").

Run once serially with --write-reference REF.png, then under `mpiexec -n 2 pvbatch` with
--compare REF.png: the two images must agree, and the relief must cover the view's middle.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--write-reference")
parser.add_argument("--compare")
args, _ = parser.parse_known_args()

t.load_plugin()
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
depth = pvs.MesolightProceduralRelief(Pattern=0, Resolution=[128, 128])
relief = pvs.MesolightReliefTexture(Input=pvs.OutputPort(depth, 0))
plane = pvs.MesolightReliefPlane(Input=relief)
attached = pvs.MesolightAttachReliefTexture(Input=plane, ReliefTexture=relief)
view = t.make_view()
display = pvs.Show(attached, view)
display.SetRepresentationType("Relief Surface")
view.CameraPosition = [0.0, -0.6, 1.6]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
pvs.Render(view)
out = t.output_dir()
path = args.write_reference or os.path.join(out, "pipeline-%d-ranks.png" % ranks)
pvs.SaveScreenshot(path, view, ImageResolution=t.SIZE, TransparentBackground=0)
frame = t.capture_file(path)

failures = []
h, w, _ = frame.shape
middle = t.covered(frame)[h // 3:2 * h // 3, w // 3:2 * w // 3]
print("%d rank(s): the relief covers %.1f%% of the view's middle ninth"
      % (ranks, 100.0 * middle.mean()))
if middle.mean() < 0.99:
    failures.append("the relief should cover the view's middle")
if args.write_reference and ranks != 1:
    failures.append("the reference must be rendered by one process")
if args.compare:
    reference = t.capture_file(args.compare)
    diff = np.abs(frame - reference).max(axis=2)
    mean, differing = float(np.abs(frame - reference).mean()), 100.0 * float((diff > 16).mean())
    print("%d ranks vs one: mean difference %.3f levels, %.3f%% of the pixels by > 16 levels"
          % (ranks, mean, differing))
    if ranks < 2:
        failures.append("the comparison must run on two ranks")
    if mean > 0.05 or differing > 0.05:
        failures.append("the image differs from the one-rank image")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
