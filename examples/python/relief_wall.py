# SPDX-License-Identifier: BSD-3-Clause
"""A relief wall from Python: examples/cxx/ReliefWall.cxx line for line, optionally lit by an HDR
environment as well (median-cut lights, each shading and self-shadowing).

    scripts/python.sh examples/python/relief_wall.py [out.png] [--environment ENV]

ENV is a lat-long HDR file (EXR, HDR, ...; e.g. Blender's
/usr/share/blender/datafiles/studiolights/world/*.exr) or procedural:sky / procedural:sun. With
out.png it renders offscreen into that file; without, it opens a window. With an environment it
also checks the lights with NumPy: their summed irradiance equals the map's radiance integrated
over the sphere (vtk_to_numpy on both filters' outputs).
"""
import argparse
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer, vtkTexture,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle  # noqa: F401 (the interactor's default style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

from mesolight import (vtkMedianCutLights, vtkOIIOImageReader, vtkProceduralEnvironmentSource,
                       vtkProceduralReliefSource, vtkReliefMapper, vtkReliefTextureFilter)


def environment_source(name):
    """A lat-long HDR environment: a file, or one of the procedural ones."""
    if name.startswith("procedural:"):
        source = vtkProceduralEnvironmentSource()
        if name == "procedural:sun":
            source.SetMapToSunSky()
        elif name == "procedural:sky":
            source.SetMapToSmoothSky()
        else:
            sys.exit(f"unknown environment {name} (procedural:sky or procedural:sun)")
        source.SetResolution(256, 128)
        return source
    reader = vtkOIIOImageReader()
    reader.SetFileName(name)
    return reader


def check_light_energy(environment, lights):
    """The lights' irradiance summed over all lights equals the map's radiance times each
    pixel's solid angle summed over the map (median cut partitions the sphere, Debevec 2005)."""
    image = environment.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).astype(np.float64)
    pixels = pixels.reshape(height, width, -1)[:, :, :3]
    # VTK row order: row j (from the bottom) has v = 1 - (j + 0.5) / H, polar angle pi v.
    theta = np.pi * (1.0 - (np.arange(height) + 0.5) / height)
    solid_angle = (2.0 * np.pi / width) * (np.pi / height) * np.sin(theta)
    expected = (pixels * solid_angle[:, None, None]).sum(axis=(0, 1))
    irradiance = vtk_to_numpy(lights.GetOutput().GetPointData().GetArray("Irradiance"))
    total = irradiance.astype(np.float64).sum(axis=0)
    error = np.abs(total - expected).max() / expected.max()
    print(f"{irradiance.shape[0]} lights: irradiance sum {total.round(4)}, map integral "
          f"{expected.round(4)}, relative difference {error:.2e}")
    return error < 1e-3


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output", nargs="?", help="PNG to render offscreen into")
    parser.add_argument("--environment", help="lat-long HDR file or procedural:sky|sun")
    parser.add_argument("--lights", type=int, default=64, help="median-cut lights (64)")
    args = parser.parse_args()

    # images -> filters -> textures
    source = vtkProceduralReliefSource()
    source.SetPatternToBricks()
    source.SetResolution(512, 512)
    relief = vtkReliefTextureFilter()
    relief.SetInputConnection(source.GetOutputPort(0))  # depth map
    relief.SetDepthScale(0.04)
    albedo = vtkTexture()
    albedo.SetInputConnection(source.GetOutputPort(1))  # matching colours
    albedo.InterpolateOn()
    albedo.MipmapOn()

    # textures -> mapper: a quad with texture coordinates is all the geometry there is
    wall = vtkPlaneSource()
    mapper = vtkReliefMapper()
    mapper.SetInputConnection(wall.GetOutputPort())
    mapper.SetReliefTextureConnection(relief.GetOutputPort())
    mapper.GetReliefProperty().SetDepthScale(0.04)
    # The default method: the exact first hit (maximum-mipmap traversal), self-shadowed.

    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetTexture(albedo)
    actor.GetProperty().SetAmbient(0.1)
    actor.GetProperty().SetSpecular(0.2)

    # -> lights
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    sun = vtkLight()
    sun.SetLightTypeToSceneLight()
    sun.SetPosition(-1.0, 1.0, 0.8)
    sun.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(sun)
    lights_ok = True
    if args.environment:
        environment = environment_source(args.environment)
        lights = vtkMedianCutLights()
        lights.SetInputConnection(environment.GetOutputPort())
        lights.SetNumberOfLights(args.lights)
        mapper.SetLightSetConnection(lights.GetOutputPort(1))  # each light shades and shadows
        mapper.GetReliefProperty().SetExposure(1.0)
        lights.Update()
        lights_ok = check_light_energy(environment, lights)
    renderer.GetActiveCamera().SetPosition(0.3, -1.2, 1.0)
    renderer.GetActiveCamera().SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera()

    window = vtkRenderWindow()
    window.SetSize(800, 800)
    window.AddRenderer(renderer)
    if args.output:
        window.SetOffScreenRendering(1)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        png = vtkPNGWriter()
        png.SetInputConnection(grab.GetOutputPort())
        png.SetFileName(args.output)
        png.Write()
        if png.GetErrorCode() != 0:
            return 1
        print(f"wrote {args.output}")
        return 0 if lights_ok else 1
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    window.Render()
    interactor.Start()
    return 0 if lights_ok else 1


if __name__ == "__main__":
    sys.exit(main())
