# SPDX-License-Identifier: BSD-3-Clause
"""Mesolight Depth Hallucination in ParaView: path-traced photographs of a known height field
(the main build's `mesolight bench hallucinate --photos`) read with the Mesolight reader, the
proxy's albedo and depth against `mesolight hallucinate` on the same files (the same filter:
equal to float precision) and against the true depth (deep must come out deep); swapped
photographs give an error and empty outputs."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
import numpy as np  # noqa: E402

t.load_plugin()
failures = []
out = os.path.join(os.environ.get("MESOLIGHT_TEST_OUTPUT", "."), "hallucination")
os.makedirs(out, exist_ok=True)
tool = os.environ["MESOLIGHT_TOOL"]
subprocess.run([tool, "bench", "hallucinate", "--maps", "HemisphereTorus", "--size", "64",
                "--samples", "8", "--photos", out], check=True)
photo = {k: os.path.join(out, "HemisphereTorus-%s.exr" % k)
         for k in ("diffuse", "flash", "calibration", "true-depth")}
cli_depth = os.path.join(out, "cli-depth.exr")
cli_albedo = os.path.join(out, "cli-albedo.exr")
for stale in (cli_depth, cli_albedo):
    if os.path.exists(stale):
        os.remove(stale)
subprocess.run([tool, "hallucinate", photo["diffuse"], photo["flash"], "--calibration",
                photo["calibration"], "--albedo", cli_albedo, "--depth", cli_depth], check=True)


def read(path):
    reader = pvs.MesolightImageReader(FileName=path)
    reader.UpdatePipeline()
    return reader


def values(proxy, port=0):
    data = proxy.GetClientSideObject().GetOutputDataObject(port)
    scalars = data.GetPointData().GetScalars() if data else None
    return None if scalars is None else vtk_to_numpy(scalars).astype(np.float64)


diffuse, flash, card = read(photo["diffuse"]), read(photo["flash"]), read(photo["calibration"])
hallucination = pvs.MesolightDepthHallucination(Input=diffuse, Flash=flash, Calibration=card)
hallucination.UpdatePipeline()
depth = values(hallucination, 1)
albedo = values(hallucination, 0)
truth = values(read(photo["true-depth"]))
cli = values(read(cli_depth))
if depth is None or albedo is None or depth.size != 64 * 64:
    failures.append("no depth or albedo output")
else:
    difference = np.abs(depth - cli).max()
    albedo_difference = np.abs(albedo - values(read(cli_albedo))).max()
    correlation = np.corrcoef(depth, truth.reshape(-1))[0, 1]
    scale = hallucination.GetClientSideObject().GetOutputDataObject(1).GetFieldData().GetArray(
        "MesolightDepthScale")
    print("depth vs mesolight hallucinate: max difference %.3g; albedo %.3g; correlation with "
          "the true depth %.3f; MesolightDepthScale %s" % (difference, albedo_difference,
                                                           correlation,
                                                           scale.GetTuple1(0) if scale else None))
    if difference > 1e-6 or albedo_difference > 1e-6:
        failures.append("the proxy's result differs from mesolight hallucinate")
    if not correlation > 0.3:
        failures.append("the depth does not follow the true depth (correlation %.3f)" % correlation)
    if scale is None or not scale.GetTuple1(0) > 0:
        failures.append("no MesolightDepthScale on the depth output")

# Swapped photographs: an error, empty outputs.
swapped = pvs.MesolightDepthHallucination(Input=flash, Flash=diffuse)
swapped.UpdatePipeline()
data = swapped.GetClientSideObject().GetOutputDataObject(1)
if data is not None and data.GetNumberOfPoints() != 0:
    failures.append("swapped photographs gave a depth map")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
