# SPDX-License-Identifier: BSD-3-Clause
"""Virtual Light Field under `mpiexec -n N pvbatch`: the directions split over the ranks.

Run serially with --write-reference FILE.npz (the output's per-vertex radiance), then on two ranks
with --compare FILE.npz:
- rank 0 shot a share of the directions only (DirectionsPropagated; that the shares add up to
  every direction once is checked by LightField.distributed.*);
- the radiance of every vertex equals the serial run's within 1e-5 relative;
- the snapshot the two ranks wrote (rank 0, gathering the other's maps) resumes, on the same ranks,
  to the same output; with DistributeDirections off (rank 0 alone) the output is the same too.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--write-reference")
parser.add_argument("--compare")
args, _ = parser.parse_known_args()

t.load_plugin()
failures = []
check = t.checker(failures)
# pvbatch runs this script on rank 0 only (the other ranks serve it): no collective calls here.
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
output = os.environ.get("MESOLIGHT_TEST_OUTPUT", ".")
os.makedirs(output, exist_ok=True)
snapshot = os.path.join(output, "distributed-%d.vlf" % ranks)
if os.path.exists(snapshot):
    os.remove(snapshot)

DIRECTIONS = 129
box = pvs.MesolightCornellBox()


def radiance(proxy):
    # Per triangle: on several ranks the output is split into pieces (each rank its share of the
    # triangles, in order), whose shared vertices are repeated, so points would not line up.
    data = servermanager.Fetch(proxy)
    return vtk_to_numpy(data.GetCellData().GetArray("Radiance")).astype(np.float64)


def worst_relative(a, b):
    if a.shape != b.shape:
        return float("inf")
    floor = 1e-9 * float(np.max(np.abs(b)))
    return float(np.max(np.abs(a - b) / np.maximum(np.maximum(np.abs(a), np.abs(b)), floor)))


field = pvs.MesolightVirtualLightField(Input=box, Directions=DIRECTIONS, RaysPerSide=16,
                                       Iterations=3, SnapshotFileName=snapshot)
field.UpdatePipeline()
field.UpdatePropertyInformation()  # rank 0's filter
held = field.GetProperty("DirectionsPropagated").GetElement(0)
print("%d rank(s): rank 0 shot %d of %d directions" % (ranks, held, DIRECTIONS))
if ranks > 1:
    check(0 < held < DIRECTIONS, "rank 0 shot a share (%d of %d)" % (held, DIRECTIONS))
else:
    check(held == DIRECTIONS, "one process shoots every direction (%d)" % held)
values = radiance(field)
print("%d triangles, radiance %.4f..%.4f" % (len(values), values.min(), values.max()))

if args.write_reference:
    np.savez(args.write_reference, radiance=values)
    print("wrote %s" % args.write_reference)
if args.compare:
    reference = np.load(args.compare)["radiance"]
    worst = worst_relative(values, reference)
    print("%d ranks vs serial: worst relative difference %.3g" % (ranks, worst))
    check(worst <= 1e-5, "the distributed field equals the serial one (worst %.3g)" % worst)
    # The comparison can fail: two iterations instead of three differ.
    fewer = pvs.MesolightVirtualLightField(Input=box, Directions=DIRECTIONS, RaysPerSide=16,
                                           Iterations=2)
    check(worst_relative(radiance(fewer), reference) > 1e-3, "two iterations differ from three")
    # Resumed from the snapshot the ranks wrote: nothing left to shoot, the same field.
    resumed = pvs.MesolightVirtualLightField(Input=box, Directions=DIRECTIONS, RaysPerSide=16,
                                             Iterations=3, SnapshotFileName=snapshot,
                                             ResumeFromSnapshot=1)
    check(worst_relative(radiance(resumed), reference) <= 1e-5, "the snapshot resumes alike")
    alone = pvs.MesolightVirtualLightField(Input=box, Directions=DIRECTIONS, RaysPerSide=16,
                                           Iterations=3, DistributeDirections=0)
    check(worst_relative(radiance(alone), reference) <= 1e-5,
          "rank 0 alone (DistributeDirections off) gives the same field")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
