# SPDX-License-Identifier: BSD-3-Clause
"""Long Mesolight filters report progress to ParaView's progress handler (what drives the GUI's
progress bar) and can be aborted: a cone map aborted from a progress observer stops early and
leaves an empty output; after the abort, a changed setting runs it to the end again (ParaView
5.11's VTK leaves the abort flag set, and every later run stopped at once)."""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402

t.load_plugin()
failures = []

# 1. Progress reaches the session's progress handler, named after the filter.
handler = servermanager.ActiveConnection.Session.GetProgressHandler()
handler.SetProgressInterval(0.0)  # report every update, not at most twice a second
seen = []


def on_progress(caller, event):
    seen.append((caller.GetLastProgressText(), caller.GetLastProgress()))


handler.AddObserver("ProgressEvent", on_progress)
depth = pvs.MesolightProceduralRelief(Pattern=1, Resolution=[256, 256])
cones = pvs.MesolightConeMap(Input=pvs.OutputPort(depth, 0))
start = time.time()
cones.UpdatePipeline()
full_time = time.time() - start
cone_reports = [p for text, p in seen if "ConeMap" in (text or "")]
print("cone map: %.2f s, %d progress reports from the handler, values %s"
      % (full_time, len(cone_reports), sorted(set(cone_reports))[:12]))
print("all reports: %s" % sorted(set(text for text, _ in seen)))
if not [p for p in cone_reports if 0 < p < 100]:
    failures.append("no intermediate progress of the cone map reached ParaView's progress handler")

# 2. Abort from a progress observer on the filter itself.
algorithm = cones.GetClientSideObject()
fractions = []


def abort_early(caller, event):
    fractions.append(caller.GetProgress())
    if caller.GetProgress() > 0.05:
        caller.SetAbortExecute(1)


algorithm.AddObserver("ProgressEvent", abort_early)
cones.ConeType = 1  # a change, so the filter runs again
start = time.time()
cones.UpdatePipeline()
aborted_time = time.time() - start
output = algorithm.GetOutputDataObject(0)
points = output.GetNumberOfPoints() if output else 0
# The executive reports 1.0 when the (aborted) execution returns: look at the filter's own.
own = [f for f in fractions if f < 1.0]
print("aborted cone map: %.2f s, progress reports %s, output points %d"
      % (aborted_time, ["%.3f" % f for f in fractions], points))
if not own or max(own) > 0.5 or points != 0:
    failures.append("the aborted cone map should stop early and output nothing")

# 3. After the abort, the next run (a setting changed) is not aborted by the stale flag.
algorithm.RemoveAllObservers()
cones.ConeType = 0
start = time.time()
cones.UpdatePipeline()
output = algorithm.GetOutputDataObject(0)
points = output.GetNumberOfPoints() if output else 0
print("cone map after the abort: %.2f s, output points %d, abort flag %d"
      % (time.time() - start, points, algorithm.GetAbortExecute()))
if points != 256 * 256:
    failures.append("after an abort the cone map never ran to the end again")
field = pvs.MesolightVirtualLightField(Input=pvs.MesolightCornellBox(), Directions=513,
                                       RaysPerSide=32)
field_algorithm = field.GetClientSideObject()
field_algorithm.AddObserver("ProgressEvent", abort_early)
field.UpdatePipeline()
if field.GetDataInformation().GetNumberOfCells() != 0:
    failures.append("the aborted light field should output nothing")
field_algorithm.RemoveAllObservers()
field.RaysPerSide = 16
field.UpdatePipeline()
cells = field.GetDataInformation().GetNumberOfCells()
print("light field after an abort and a change: %d cells" % cells)
if cells == 0:
    failures.append("after an abort the light field never propagated again")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
