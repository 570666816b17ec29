# SPDX-License-Identifier: BSD-3-Clause
"""What the relief's occlusion costs vtkLightFieldReliefSurface (ParaView's Relief Surface lit by a
Virtual Light Field, the walkthrough's reliefs): the visible-share map alone (a depth scale change
recomputes it and keeps the probes) against the 8 x 8 probes with the scene's visibility of the
emitter lights (SceneOcclusion: a new surface gathers them again and keeps the map), in the same
run, interleaved, on the Cornell box's field (513 directions, 32 rays, 4 iterations, no gather)
and a 380 mm patch in front of its back wall, bricks of 64, 128 and 256 texels a side.

    scripts/python.sh scripts/bench-relief-surface-occlusion.py [OUT.csv] [REPEATS]

Prints one line per run and the medians; writes the medians as CSV (default
docs/measurements/paraview/relief-surface-occlusion.csv).
"""
import os
import statistics
import sys
import time

from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from mesolight import (vtkCornellBoxSource, vtkLightFieldReliefSurface, vtkProceduralReliefSource,
                       vtkReliefTextureFilter, vtkVirtualLightField)

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "docs", "measurements", "paraview",
    "relief-surface-occlusion.csv")
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3

box = vtkCornellBoxSource()
field = vtkVirtualLightField()
field.SetInputConnection(box.GetOutputPort())
field.SetDirections(513)
field.SetRaysPerSide(32)
field.SetIterations(4)
field.FinalGatherOff()
field.Update()
patch = vtkPlaneSource()
patch.SetOrigin(90.0, 90.0, 558.0)
patch.SetPoint1(90.0, 470.0, 558.0)
patch.SetPoint2(470.0, 90.0, 558.0)
patch.Update()

textures = {}
for side in (64, 128, 256):
    depth = vtkProceduralReliefSource()
    depth.SetPattern(0)  # bricks, deep mortar
    depth.SetResolution(side, side)
    texture = vtkReliefTextureFilter()
    texture.SetInputConnection(depth.GetOutputPort())
    texture.Update()
    textures[side] = texture.GetOutput()

surface = vtkLightFieldReliefSurface()
surface.SetLightFieldConnection(field.GetOutputPort())
surface.SceneOcclusionOn()
times = {side: {"map": [], "probes": []} for side in textures}
for run in range(repeats):
    for side, texture in textures.items():
        piece = vtkPolyData()
        piece.DeepCopy(patch.GetOutput())
        surface.SetSurfaceData(piece)
        surface.SetReliefTextureData(texture)
        surface.SetReliefDepthScale(0.05)
        surface.Update()  # both, unmeasured
        surface.SetReliefDepthScale(0.1 if run % 2 == 0 else 0.07)
        start = time.perf_counter()
        surface.Update()  # the map alone
        map_seconds = time.perf_counter() - start
        piece = vtkPolyData()
        piece.DeepCopy(patch.GetOutput())
        surface.SetSurfaceData(piece)
        start = time.perf_counter()
        surface.Update()  # the probes and the lights' visibility alone
        probe_seconds = time.perf_counter() - start
        times[side]["map"].append(map_seconds)
        times[side]["probes"].append(probe_seconds)
        print("run %d, bricks %d x %d: visible-share map %.3f s, probes with light visibility "
              "%.3f s" % (run, side, side, map_seconds, probe_seconds))

with open(out, "w") as csv:
    csv.write("texels_per_side,map_seconds,probes_seconds,map_over_probes\n")
    for side in textures:
        m = statistics.median(times[side]["map"])
        p = statistics.median(times[side]["probes"])
        print("bricks %d x %d: medians map %.3f s, probes %.3f s, map / probes %.2f"
              % (side, side, m, p, m / p))
        csv.write("%d,%.4f,%.4f,%.3f\n" % (side, m, p, m / p))
print("wrote %s (%d runs)" % (out, repeats))
