# SPDX-License-Identifier: BSD-3-Clause
"""What splitting the relief's visible-share map over MPI ranks saves ParaView's Relief Surface lit
by a Virtual Light Field (vtkLightFieldReliefSurface): the map alone (a depth scale change
recomputes it and keeps the probes), timed by the first rank (its rows and the two sums over the
ranks: LightFieldVisibleShareSeconds, and the processor seconds of its process, all threads:
LightFieldVisibleShareCpuSeconds, what the split saves each rank on a loaded machine), on the
Cornell box's field (513 directions, 32 rays, 4 iterations, no gather) and a 380 mm patch in
front of its back wall, bricks of 256 x 256 texels (the map's cap). Run it once per rank count
in the same session and compare the medians:

    bash scripts/xvfb.sh mpiexec -n N bash scripts/pvbatch.sh \\
        scripts/bench-relief-share-mpi.py [OUT.csv] [REPEATS] [--no-silhouettes]   # N = 1, 2

(--no-silhouettes: the relief walled at its border, as with Silhouettes off in the panel; the
map then holds the side walls' shares too.)

(OpenMPI on a machine with fewer cores than ranks, or as root, needs
OMPI_MCA_rmaps_base_oversubscribe=1, OMPI_ALLOW_RUN_AS_ROOT=1 and
OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1, as the plugin tests set). Prints one line per map and the
median; appends "ranks,threads,side,silhouettes,median_seconds,median_cpu_seconds,repeats" to
OUT.csv (default docs/measurements/paraview/relief-share-mpi.csv; threads: VTK_SMP_MAX_THREADS,
else "auto", the machine's cores split between the ranks on it).
"""
import os
import statistics
import sys

import paraview.simple as pvs
from paraview import servermanager

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from relief_share_timing import relief_on_back_wall, visible_share_maps  # noqa: E402
silhouettes = "--no-silhouettes" not in sys.argv[1:]
args = [a for a in sys.argv[1:] if a != "--no-silhouettes"]
out = args[0] if len(args) > 0 else os.path.join(
    here, "..", "docs", "measurements", "paraview", "relief-share-mpi.csv")
repeats = int(args[1]) if len(args) > 1 else 5
SIDE = 256

pvs.LoadPlugin(os.environ["MESOLIGHT_PLUGIN"], remote=False, ns=pvs.__dict__)
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
box = pvs.MesolightCornellBox()
field = pvs.MesolightVirtualLightField(Input=box, Directions=513, RaysPerSide=32, Iterations=4,
                                       FinalGather=0)
view, relief = relief_on_back_wall(pvs, field, SIDE, silhouettes)
times, cpu_times = [], []
for run, (seconds, cpu, split) in enumerate(visible_share_maps(pvs, view, relief, repeats)):
    times.append(seconds)
    cpu_times.append(cpu)
    print("ranks %d, run %d, bricks %d x %d: visible-share map %.3f s, %.3f processor s on the "
          "first rank (split over %d rank(s))" % (ranks, run, SIDE, SIDE, seconds, cpu, split))
median, cpu_median = statistics.median(times), statistics.median(cpu_times)
print("ranks %d: median %.3f s, %.3f processor s on the first rank over %d maps"
      % (ranks, median, cpu_median, repeats))
HEADER = "ranks,threads,side,silhouettes,median_seconds,median_cpu_seconds,repeats"
new = not os.path.exists(out)
if not new:
    with open(out) as existing:
        if existing.readline().strip() != HEADER:
            sys.exit("%s has other columns than %s: give a new file" % (out, HEADER))
with open(out, "a") as csv:
    if new:
        csv.write(HEADER + "\n")
    csv.write("%d,%s,%d,%d,%.4f,%.4f,%d\n" % (
        ranks, os.environ.get("VTK_SMP_MAX_THREADS", "auto"), SIDE, 1 if silhouettes else 0,
        median, cpu_median, repeats))
print("appended to %s" % out)
