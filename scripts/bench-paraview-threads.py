# SPDX-License-Identifier: BSD-3-Clause
"""What the plugin's own threads give ParaView users: ParaView's VTK runs vtkSMPTools on its
Sequential backend by default (Debian's 5.11: STDThread is built in but not selected), so
mesolight::ParallelFor starts its own threads there (common/ParallelForThreads.h). Times, in
pvbatch, the plugin's long filters at their defaults, each updated alone (wall seconds, the median
of REPEATS updates after one unmeasured): Virtual Light Field on the Cornell box (the automatic
directions and rays, final gather on) and on examples/data/town.obj, Light Field Gather of a sphere
in the box's field, Cone Map of a 512 x 512 procedural stone relief and of a real height map
(redeclipse-data's dq_stones01_b, when installed), Median Cut Lights (64, variance minimizing) of a
2048 x 1024 procedural sky, and the Relief Surface's visible-share map (256 x 256 bricks) lit by
the box's field. Run it with
one thread (what the plugin did before: every core on one thread) and with the default, in the same
session, and compare:

    VTK_SMP_MAX_THREADS=1 bash scripts/xvfb.sh bash scripts/pvbatch.sh scripts/bench-paraview-threads.py [OUT.csv] [REPEATS]
    bash scripts/xvfb.sh bash scripts/pvbatch.sh scripts/bench-paraview-threads.py [OUT.csv] [REPEATS]

Prints one line per filter; appends "threads,backend,cores,filter,median_seconds,repeats" to OUT.csv
(default docs/measurements/paraview/threads.csv; threads: VTK_SMP_MAX_THREADS, else "auto").
"""
import os
import statistics
import sys
import time

import paraview.simple as pvs
from vtkmodules.vtkCommonCore import vtkSMPTools

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from relief_share_timing import relief_on_back_wall, visible_share_maps  # noqa: E402
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    here, "..", "docs", "measurements", "paraview", "threads.csv")
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3
threads = os.environ.get("VTK_SMP_MAX_THREADS", "auto")
backend = vtkSMPTools.GetBackend()
cores = os.cpu_count()
pvs.LoadPlugin(os.environ["MESOLIGHT_PLUGIN"], remote=False, ns=pvs.__dict__)
print("vtkSMPTools backend %s, VTK_SMP_MAX_THREADS %s, %d hardware threads"
      % (backend, threads, cores))
rows = []


def timed(name, proxy, change):
    """Median wall seconds of `repeats` updates of proxy, each after change(run) modified it."""
    proxy.UpdatePipeline()  # its inputs, unmeasured
    seconds = []
    for run in range(repeats):
        change(run)
        start = time.perf_counter()
        proxy.UpdatePipeline()
        seconds.append(time.perf_counter() - start)
    median = statistics.median(seconds)
    print("%-26s %8.3f s  (%s)" % (name, median, ", ".join("%.3f" % s for s in seconds)))
    rows.append((name, median))


box = pvs.MesolightCornellBox()
field = pvs.MesolightVirtualLightField(Input=box)
timed("Virtual Light Field", field,
      lambda run: setattr(field, "ConvergenceTolerance", 0.01 + 0.0001 * (run + 1)))

# A scene unlike the Cornell box: the example town (OBJ, 200 m, buildings and a ground).
town = pvs.MesolightOBJSceneReader(FileName=os.path.join(here, "..", "examples", "data",
                                                         "town.obj"))
town_field = pvs.MesolightVirtualLightField(Input=town)
timed("Virtual Light Field town.obj", town_field,
      lambda run: setattr(town_field, "ConvergenceTolerance", 0.01 + 0.0001 * (run + 1)))

sphere = pvs.Sphere(Center=[278.0, 150.0, 280.0], Radius=80.0, ThetaResolution=32,
                    PhiResolution=32)
gather = pvs.MesolightLightFieldGather(Input=sphere, LightField=field)
timed("Light Field Gather", gather,
      lambda run: setattr(gather, "Reflectance", [0.7, 0.7, 0.6 + 0.01 * run]))

stone = pvs.MesolightProceduralRelief(Pattern=2, Resolution=[512, 512])
cones = pvs.MesolightConeMap(Input=pvs.OutputPort(stone, 0))
timed("Cone Map 512 x 512", cones,
      lambda run: setattr(cones, "DepthScale", 0.05 + 0.001 * (run + 1)))

# A real height map (white high), when Debian's redeclipse-data is installed
# (MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh).
REAL_MAP = "/usr/share/games/redeclipse/data/dziq/dq_stones01_b.jpg"
if os.path.exists(REAL_MAP):
    real = pvs.MesolightImageReader(FileName=REAL_MAP)
    real_cones = pvs.MesolightConeMap(Input=real, InvertInput=1)
    timed("Cone Map dq_stones01_b 512", real_cones,
          lambda run: setattr(real_cones, "DepthScale", 0.05 + 0.001 * (run + 1)))
else:
    print("skipped the real height map: %s is absent" % REAL_MAP)

sky = pvs.MesolightProceduralEnvironment(Resolution=[2048, 1024])
lights = pvs.MesolightMedianCutLights(Input=sky)
timed("Median Cut Lights 2048 x 1024", lights,
      lambda run: setattr(lights, "NumberOfLights", 64 + run + 1))

view, relief = relief_on_back_wall(pvs, field)
maps = [seconds for seconds, _, _ in visible_share_maps(pvs, view, relief, repeats)]
print("%-26s %8.3f s  (%s)" % ("Visible-share map 256^2", statistics.median(maps),
                               ", ".join("%.3f" % s for s in maps)))
rows.append(("Visible-share map 256^2", statistics.median(maps)))

new = not os.path.exists(out)
with open(out, "a") as csv:
    if new:
        csv.write("threads,backend,cores,filter,median_seconds,repeats\n")
    for name, median in rows:
        csv.write("%s,%s,%d,%s,%.4f,%d\n" % (threads, backend, cores, name, median, repeats))
print("appended to %s" % out)
