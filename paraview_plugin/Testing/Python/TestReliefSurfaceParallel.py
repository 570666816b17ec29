# SPDX-License-Identifier: BSD-3-Clause
"""The relief plane split across MPI ranks renders as in one process (IceT compositing).

Run once serially with --write-reference REF.png, then under `mpiexec -n 2 pvbatch` with
--compare REF.png. The scene: the relief plane (16 x 16 quads, redistributed so each rank has
a part) and a sphere poking through the relief, so the composited image depends on the relief's
written depth. The serial run also checks that the depth matters: without WriteDepth the image
must differ from the reference beyond the tolerance used for the MPI comparison.
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
out = t.output_dir()
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
relief = t.relief_texture(128)
split = pvs.RedistributeDataSet(Input=t.unit_square(16))
view = t.make_view()
attached, display = t.show_relief(split, relief, view)
sphere = pvs.Sphere(Center=[0.5, 0.55, -0.1], Radius=0.125, ThetaResolution=48, PhiResolution=48)
sphere_display = pvs.Show(sphere, view)
sphere_display.AmbientColor = sphere_display.DiffuseColor = [0.9, 0.4, 0.2]

# Which rank holds which cells of the plane (each rank also has the whole relief texture).
ranked = pvs.ProgrammableFilter(Input=attached)
ranked.Script = """
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkCommonCore import vtkIntArray
data = self.GetInputDataObject(0, 0)
out = self.GetOutputDataObject(0)
out.ShallowCopy(data)
rank = vtkIntArray()
rank.SetName("Rank")
rank.SetNumberOfTuples(data.GetNumberOfCells())
rank.Fill(vtkMultiProcessController.GetGlobalController().GetLocalProcessId())
out.GetCellData().AddArray(rank)
if data.GetFieldData().GetArray("MesolightReliefTexture") is None:
    raise RuntimeError("a piece lacks the relief texture")
"""
pieces = []
for rank in range(ranks):
    piece = servermanager.Fetch(ranked, rank)  # the piece of that rank alone
    values = piece.GetCellData().GetArray("Rank") if piece else None
    pieces.append((piece.GetNumberOfCells() if piece else 0, values.GetRange() if values else None))
print("ranks %d, (cells, rank values) per rank: %s" % (ranks, pieces))
split_ok = ranks > 1
for k, (cells, values) in enumerate(pieces):
    split_ok = split_ok and cells > 0 and values == (k, k)

# MPI against serial is exact here; without depth write about 0.2% of the pixels differ.
TOLERANCE_MEAN = 0.05      # mean absolute difference, 8-bit levels, whole image
TOLERANCE_PIXELS = 0.05    # percent of pixels differing by more than 16 levels


def difference(a, b):
    diff = np.abs(a - b).max(axis=2)
    return float(np.abs(a - b).mean()), 100.0 * float((diff > 16).sum()) / diff.size


failures = []
if args.write_reference:
    if ranks != 1:
        failures.append("the reference must be rendered by one process")
    reference = t.capture(view, args.write_reference)
    display.WriteDepth = 0
    no_depth = t.capture(view, os.path.join(out, "pv-parallel-no-depth-write.png"))
    display.WriteDepth = 1
    mean, pixels = difference(no_depth, reference)
    print("serial, WriteDepth off vs on: mean difference %.3f levels, %.3f%% pixels differ"
          % (mean, pixels))
    if mean <= TOLERANCE_MEAN and pixels <= TOLERANCE_PIXELS:
        failures.append("without depth write the image should differ (the sphere's outline)")
if args.compare:
    if not split_ok:
        failures.append("the plane should be split across the ranks")
    frame = t.capture(view, os.path.join(out, "pv-parallel-%d-ranks.png" % ranks))
    # Each rank drew its own piece and IceT composited them (no gathering to one rank).
    distributed = view.GetClientSideObject().GetUseDistributedRenderingForRender()
    print("distributed rendering (IceT compositing): %s" % bool(distributed))
    if not distributed:
        failures.append("the render should be distributed across the ranks")
    reference = t.capture_file(args.compare)
    mean, pixels = difference(frame, reference)
    print("%d ranks vs serial: mean difference %.3f levels, %.3f%% pixels differ by > 16 levels"
          % (ranks, mean, pixels))
    if mean > TOLERANCE_MEAN or pixels > TOLERANCE_PIXELS:
        failures.append("the parallel image differs from the serial one")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
