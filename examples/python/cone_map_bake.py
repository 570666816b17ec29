# SPDX-License-Identifier: BSD-3-Clause
"""Bake cone maps from Python and check them with NumPy: a depth map (procedural, or any image
file) -> vtkConeMapFilter (relaxed and conservative cones, Dummer 2006; Policarpo & Oliveira 2007)
-> float RGBA EXR files (normal x, y; cone ratio; depth), as `mesolight cone` writes them.

    scripts/python.sh examples/python/cone_map_bake.py OUT_DIR [--depth FILE [--height]]
        [--size N] [--check-texels K]

The check is independent of the filter's search: a conservative cone contains no point of the
surface, so at every texel p its ratio is at most dist(p, q) / (d_p - d_q) for every texel q
shallower than p (texel centres lie on the bilinear surface the cones are defined on); NumPy
computes that bound by brute force over all pairs (vtk_to_numpy on the filter's output), or, on
maps of more than K texels (default 4096), for K texels drawn at random against every texel:
the pairs grow as the square of the texels, and a 512 x 512 map would take hours.
A cone that contains no surface also satisfies the relaxed definition (entered at most once),
so the exact relaxed cone is at least as wide at every texel; the filter's cones are within
1.25x of exact (its search's tolerance, docs/cone-maps.md), so a relaxed cone is checked to be at
least the conservative one over 1.25 (real maps come near: brick_wall01_b 1.24x at 77 texels).
"""
import argparse
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from mesolight import (vtkConeMapFilter, vtkOIIOImageReader, vtkOIIOImageWriter,
                       vtkProceduralReliefSource)


# Each cone is within [exact / SEARCH_TOLERANCE, exact] (ConeMapOptions::Tolerance 0.25).
SEARCH_TOLERANCE = 1.25


def cone_map(depth_port, cone_type):
    """The cone map of a depth map as float RGBA (x, y normals; ratio; depth), H x W x 4."""
    cones = vtkConeMapFilter()
    cones.SetInputConnection(depth_port)
    if cone_type == "conservative":
        cones.SetConeTypeToConservative()
    else:
        cones.SetConeTypeToRelaxed()
    cones.Update()
    image = cones.GetOutput()
    width, height, _ = image.GetDimensions()
    return cones, vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, 4)


def conservative_violation(rgba, texels):
    """max over the checked texels (`texels` indices into the flattened map) of ratio /
    (brute-force bound over every texel): <= 1 when no cone contains a texel centre that is
    shallower than its apex. Distances in texture widths, as the filter's."""
    height, width, _ = rgba.shape
    ratio = rgba[:, :, 2].astype(np.float64).ravel()
    depth = rgba[:, :, 3].astype(np.float64).ravel()
    j, i = np.mgrid[0:height, 0:width]
    x = (i.ravel() + 0.5) / width
    y = (j.ravel() + 0.5) / width
    worst = 0.0
    rows = max(1, 2**22 // depth.size)  # rows of the pair matrix a block: about 32 MB
    for start in range(0, texels.size, rows):
        p = texels[start:start + rows]
        rise = depth[p, None] - depth[None, :]  # d_p - d_q > 0: q is shallower
        dist = np.hypot(x[p, None] - x[None, :], y[p, None] - y[None, :])
        with np.errstate(divide="ignore", invalid="ignore"):
            bound = np.where(rise > 0.0, dist / rise, np.inf).min(axis=1)
        worst = max(worst, float(np.max(ratio[p] / bound)))
    return worst


def height_as_depth(reader):
    """A height map (light = high) as the depth map the filter reads (light = deep is wrong):
    its first channel scaled to [0, 1] by its type's range and turned over, d = 1 - h."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    reader.Update()
    image = reader.GetOutput()
    values = vtk_to_numpy(image.GetPointData().GetScalars())
    values = values.reshape(values.shape[0], -1)[:, 0]
    top = np.iinfo(values.dtype).max if np.issubdtype(values.dtype, np.integer) else 1.0
    depth = vtkImageData()
    depth.SetDimensions(image.GetDimensions())
    depth.GetPointData().SetScalars(
        numpy_to_vtk(1.0 - values.astype(np.float32) / np.float32(top), deep=True))
    return depth


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir", help="where cone-relaxed.exr and cone-conservative.exr go")
    parser.add_argument("--depth", help="a depth image (any OpenImageIO format); default bricks")
    parser.add_argument("--height", action="store_true",
                        help="the file is a height map (light = high), as `mesolight --height`")
    parser.add_argument("--size", type=int, default=48, help="procedural map size (48)")
    parser.add_argument("--check-texels", type=int, default=4096,
                        help="texels checked against every texel on larger maps (4096)")
    args = parser.parse_args()

    if args.depth:
        depth = vtkOIIOImageReader()
        depth.SetFileName(args.depth)
        if args.height:
            from vtkmodules.vtkCommonExecutionModel import vtkTrivialProducer
            producer = vtkTrivialProducer()
            producer.SetOutput(height_as_depth(depth))
            depth = producer
    else:
        depth = vtkProceduralReliefSource()
        depth.SetPatternToBricks()
        depth.SetResolution(args.size, args.size)
    os.makedirs(args.out_dir, exist_ok=True)

    ok = True
    ratios = {}
    for cone_type in ("relaxed", "conservative"):
        cones, rgba = cone_map(depth.GetOutputPort(0), cone_type)
        path = os.path.join(args.out_dir, f"cone-{cone_type}.exr")
        writer = vtkOIIOImageWriter()
        writer.SetInputConnection(cones.GetOutputPort())
        writer.SetFileName(path)
        writer.Write()
        print(f"wrote {path}")
        ratios[cone_type] = rgba[:, :, 2].astype(np.float64)
        if cone_type == "conservative":
            count = rgba.shape[0] * rgba.shape[1]
            texels = np.arange(count)
            if count > args.check_texels:
                texels = np.random.default_rng(1).choice(count, args.check_texels, replace=False)
            worst = conservative_violation(rgba, texels)
            # The same check on cones made twice as wide must fail: it can see a wrong map.
            doubled = rgba.copy()
            doubled[:, :, 2] *= 2.0
            wrong = conservative_violation(doubled, texels)
            print(f"conservative cones ({texels.size} of {count} texels checked): largest "
                  f"ratio / brute-force bound {worst:.4f} (<= 1 expected); doubled cones "
                  f"{wrong:.4f} (> 1 expected)")
            ok = ok and worst <= 1.0 + 1e-5 and wrong > 1.0
    narrower = np.count_nonzero(ratios["relaxed"] < ratios["conservative"] * (1.0 - 1e-6))
    too_narrow = np.count_nonzero(
        ratios["relaxed"] < ratios["conservative"] / SEARCH_TOLERANCE * (1.0 - 1e-6))
    print(f"median cone ratio: relaxed {np.median(ratios['relaxed']):.4f}, conservative "
          f"{np.median(ratios['conservative']):.4f}; relaxed narrower at {narrower} texels, "
          f"narrower than conservative / {SEARCH_TOLERANCE} at {too_narrow} (0 expected)")
    ok = ok and too_narrow == 0
    print("cone maps OK" if ok else "cone maps WRONG")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
