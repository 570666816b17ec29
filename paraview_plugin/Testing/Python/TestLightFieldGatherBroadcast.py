# SPDX-License-Identifier: BSD-3-Clause
"""Light Field Gather under MPI: the field is made once, by all ranks together.

Run serially with --write-reference FILE.npz (the gathered points and irradiance), then under
`mpiexec -n 2 pvbatch` with --compare FILE.npz, for the default field (its directions split over
the ranks, each rank keeping its own) and for DistributeDirections off (rank 0 makes it alone):
- FieldPropagations is 1 after the first update, whatever the number of ranks (each rank
  propagating its own copy would give 2);
- the distributed field is never sent (FieldBroadcasts 0: each rank gathers from its own
  directions, one sum); with DistributeDirections off rank 0 sends it once (FieldBroadcasts 1);
  an update that does not change the field (Reflectance) neither propagates nor sends it again;
- the irradiance gathered on two ranks equals the serial run's at every point (matched by
  position: the sphere is split across the ranks), within 1e-5 relative.
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

ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
print("ranks: %d" % ranks)
box = pvs.MesolightCornellBox()
ball = pvs.Sphere(Center=[278.0, 250.0, 280.0], Radius=60.0, ThetaResolution=24,
                  PhiResolution=12)
reference = np.load(args.compare) if args.compare else None
if args.compare:
    check(ranks == 2, "runs on two ranks")

for distribute in (1, 0):
    label = "distributed field" if distribute else "DistributeDirections off"
    field = pvs.MesolightVirtualLightField(Input=box, Directions=513, RaysPerSide=24,
                                           Iterations=3, DistributeDirections=distribute)
    gather = pvs.MesolightLightFieldGather(Input=ball, LightField=field)
    sent = 1 if ranks > 1 and not distribute else 0

    def counters():
        gather.UpdatePipeline()
        gather.UpdatePropertyInformation()
        return (gather.GetProperty("FieldPropagations").GetElement(0),
                gather.GetProperty("FieldBroadcasts").GetElement(0))

    propagations, broadcasts = counters()
    print("%s, after the first update: %d field(s) made on all ranks, %d broadcast(s)"
          % (label, propagations, broadcasts))
    check(propagations == 1, "%s: one field made over %d rank(s) (%d)"
          % (label, ranks, propagations))
    check(broadcasts == sent, "%s: the field sent %d time(s) (%d)" % (label, sent, broadcasts))
    data = servermanager.Fetch(gather)
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    irradiance = vtk_to_numpy(data.GetPointData().GetArray("Irradiance")).astype(np.float64)
    print("%d points gathered, irradiance %.4f..%.4f" % (len(points), irradiance.min(),
                                                        irradiance.max()))

    gather.Reflectance = [0.5, 0.5, 0.5]
    propagations, broadcasts = counters()
    print("after changing Reflectance: %d field(s), %d broadcast(s)" % (propagations, broadcasts))
    check(propagations == 1 and broadcasts == sent,
          "%s: an update that keeps the field neither propagates nor sends it again" % label)

    if args.write_reference and distribute:
        np.savez(args.write_reference, points=points, irradiance=irradiance)
        print("wrote %s" % args.write_reference)
    if reference is not None:
        key = {tuple(np.round(p, 3)): e
               for p, e in zip(reference["points"], reference["irradiance"])}
        worst, missing = 0.0, 0
        for p, e in zip(points, irradiance):
            r = key.get(tuple(np.round(p, 3)))
            if r is None:
                missing += 1
                continue
            worst = max(worst, float(np.max(np.abs(e - r) / np.maximum(np.abs(r), 1e-6))))
        print("%s, two ranks vs serial: %d points, %d without a serial twin, worst relative "
              "difference %.3g" % (label, len(points), missing, worst))
        check(missing == 0, "%s: every point of the two-rank run is a point of the serial run"
              % label)
        check(worst <= 1e-5, "%s: the two-rank irradiance equals the serial one (worst %.3g)"
              % (label, worst))
    pvs.Delete(gather)
    pvs.Delete(field)

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
