# SPDX-License-Identifier: BSD-3-Clause
"""An OBJ + MTL scene read back as the tool reads scenes (vtkOBJSceneReader, the core reader of
`vlf propagate` and `trace --scene`), its figures computed here with NumPy: triangles, emitting
triangles, area, emitted power (pi x area x Ke per channel: a Lambertian emitter of radiance Ke).
Exit 0 when they are the expected ones (area and power within 1e-5 relative), else 1.

    scripts/python.sh ObjSceneFigures.py SCENE.obj TRIANGLES EMITTING AREA R,G,B
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from mesolight import vtkOBJSceneReader


def main():
    path, triangles, emitting, area = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(
        sys.argv[4])
    power = np.array([float(x) for x in sys.argv[5].split(",")])
    reader = vtkOBJSceneReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    points = vtk_to_numpy(poly.GetPoints().GetData()).astype(np.float64)
    cells = vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    a, b, c = points[cells[:, 0]], points[cells[:, 1]], points[cells[:, 2]]
    areas = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    ke = vtk_to_numpy(poly.GetCellData().GetArray("Emission")).astype(np.float64)
    read_power = np.pi * (areas[:, None] * ke).sum(axis=0)
    read_emitting = int((ke.max(axis=1) > 0.0).sum())
    print(f"{path}: {len(cells)} triangles ({read_emitting} emitting), area {areas.sum():.9g}, "
          f"emitted power {','.join(f'{p:.9g}' for p in read_power)}")
    ok = (len(cells) == triangles and read_emitting == emitting
          and abs(areas.sum() - area) <= 1e-5 * area
          and np.all(np.abs(read_power - power) <= 1e-5 * np.abs(power).max()))
    print("SAME" if ok else "DIFFERENT")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
