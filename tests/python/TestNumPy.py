# SPDX-License-Identifier: BSD-3-Clause
"""NumPy on the filters' outputs, as a VTK Python user reads them (vtk_to_numpy,
numpy_to_vtk): a depth map made in NumPy goes in, the relief texture comes out, and its normals
and depth are checked against NumPy's own finite differences of the same map.

vtkReliefTextureFilter writes RGBA: normals packed (n + 1) / 2 in RGB, depth in A. On a depth map
d(x, y) = s x (a ramp), the normal is (-k, 0, 1) / |.| with k the depth slope in texture widths
times the depth scale; a wrong slope, sign or packing moves it far beyond the tolerance.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData

from mesolight import vtkReliefTextureFilter


def main():
    width = height = 64
    depth_scale = 0.04
    slope = 0.5  # depth units per texture width
    x = (np.arange(width) + 0.5) / width
    depth = np.tile(slope * x, (height, 1)).astype(np.float32)  # row-major, VTK row order

    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    scalars = numpy_to_vtk(depth.ravel(), deep=True)
    scalars.SetName("depth")
    image.GetPointData().SetScalars(scalars)

    relief = vtkReliefTextureFilter()
    relief.SetInputData(image)
    relief.SetDepthScale(depth_scale)
    relief.Update()
    out = relief.GetOutput()
    rgba = vtk_to_numpy(out.GetPointData().GetScalars()).reshape(height, width, -1)
    rgba = rgba.astype(np.float64)
    if np.issubdtype(vtk_to_numpy(out.GetPointData().GetScalars()).dtype, np.integer):
        rgba /= 255.0
    print(f"relief texture {width}x{height}, {rgba.shape[2]} components, "
          f"type {out.GetScalarTypeAsString()}")

    normals = rgba[:, :, :3] * 2.0 - 1.0
    # Away from the clamped borders, where the finite differences are exact on a ramp.
    inner = normals[4:-4, 4:-4].reshape(-1, 3)
    # Depth grows with x: the height -depth * scale falls to the right, so the surface leans
    # toward +x, n ~ (-dh/dx, -dh/dy, 1) = (k, 0, 1) (the gradient NumPy's ramp defines).
    k = slope * depth_scale
    expected = np.array([k, 0.0, 1.0]) / np.hypot(k, 1.0)
    error = np.abs(inner - expected).max(axis=1)
    mirrored = np.abs(inner - expected * np.array([-1.0, 1.0, 1.0])).max(axis=1)
    depth_error = np.abs(rgba[4:-4, 4:-4, 3] - depth[4:-4, 4:-4]).max()
    print(f"normal vs NumPy's (+{k:.3f}, 0, 1)/|.|: max error {error.max():.4f}; against the "
          f"mirrored normal {mirrored.max():.4f}; depth max error {depth_error:.2e}")
    ok = error.max() < 0.01 and mirrored.min() > 0.01 and depth_error < 1e-3
    print("OK" if ok else "WRONG")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
