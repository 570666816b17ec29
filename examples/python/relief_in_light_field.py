# SPDX-License-Identifier: BSD-3-Clause
"""A relief on a wall of a virtual light field walkthrough, lit by the field, from Python: one
vtkLightFieldReliefActor beside the vtkLightFieldActor (what `mesolight vlf view FIELD --relief
SURFACE=DEPTH_IMAGE` draws). The actor hides the flat wall from the walkthrough, gathers the
field's indirect light over the wall as SH9 probes, lights the relief by the field's emitters
with its self-shadowing and the scene's shadows, colours it with the wall's Kd and takes the
walkthrough's exposure and tone map, so the relief and the room around it show the same radiance
as the same pixel value.

    scripts/python.sh examples/python/relief_in_light_field.py                  (a window)
    scripts/python.sh examples/python/relief_in_light_field.py out.png          (offscreen)
    scripts/python.sh examples/python/relief_in_light_field.py out.png --field box.vlf \\
        --depth grooves.png --surface back --depth-scale 0.1 --size 96

Without --field the built-in Cornell box is propagated (513 directions, 32 rays, 4 iterations);
without --depth the back wall gets procedural bricks. --field loads a snapshot written by
`mesolight vlf propagate` (any OBJ scene; name its surface with --surface).
"""
import argparse
import sys

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkRenderWindow, vtkRenderWindowInteractor,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle  # noqa: F401 (the interactor's default style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

from mesolight import (vtkCornellBoxSource, vtkLightFieldActor, vtkLightFieldReliefActor,
                       vtkOIIOImageReader, vtkProceduralReliefSource, vtkReliefTextureFilter,
                       vtkVirtualLightField)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", help="PNG to write offscreen (else a window)")
    parser.add_argument("--field", help="a light field snapshot (`mesolight vlf propagate`)")
    parser.add_argument("--depth", help="depth image (0 = top, 1 = deepest); default bricks")
    parser.add_argument("--surface", default="back", help="the surface's name in the scene")
    parser.add_argument("--depth-scale", type=float, default=0.02,
                        help="relief depth over the texture's width (default 0.02)")
    parser.add_argument("--size", type=int, default=400, help="window size in pixels")
    parser.add_argument("--no-occlusion", action="store_true",
                        help="without the relief's occlusion and the scene's shadows")
    args = parser.parse_args(argv[1:])

    errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        # VTK's message, last line (the first names the source file and line).
        errors.append(message)
        print("relief_in_light_field.py: " + message.strip().splitlines()[-1], file=sys.stderr)

    def watch(obj):
        obj.AddObserver(vtkCommand.ErrorEvent, on_error)
        if hasattr(obj, "GetExecutive"):  # its "returned failure" follow-up says nothing new
            obj.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda caller, event: None)
        return obj

    # The walkthrough: a snapshot, or the Cornell box propagated when first drawn.
    scene = vtkLightFieldActor()
    scene.SetRenderModeToProgressive()
    if args.field:
        if not scene.LoadLightField(args.field):
            return 1  # the actor reported why
    else:
        box = vtkCornellBoxSource()
        field = vtkVirtualLightField()
        field.SetInputConnection(box.GetOutputPort())
        field.SetDirections(513)
        field.SetRaysPerSide(32)
        field.SetIterations(4)
        scene.SetLightFieldFilter(field)

    # The relief texture: a depth image (any OpenImageIO format), or procedural bricks.
    if args.depth:
        depth = watch(vtkOIIOImageReader())
        depth.SetFileName(args.depth)
        depth_port = depth.GetOutputPort()
    else:
        bricks = vtkProceduralReliefSource()
        bricks.SetPatternToBricks()
        bricks.SetResolution(256, 256)
        depth_port = bricks.GetOutputPort(0)
    bake = watch(vtkReliefTextureFilter())
    bake.SetInputConnection(depth_port)
    bake.SetDepthScale(args.depth_scale)
    bake.Update()
    if errors:
        return 1

    # The relief: the named surface, drawn by the relief mapper and lit by the field.
    relief = watch(vtkLightFieldReliefActor())
    relief.SetLightFieldActor(scene)
    relief.SetSurfaceName(args.surface)
    relief.SetReliefTextureData(bake.GetOutput())  # drawn at the bake's depth scale
    relief.SetOcclusion(not args.no_occlusion)

    renderer = vtkRenderer()
    renderer.AutomaticLightCreationOff()  # the relief is lit by the field's emitters only
    renderer.AddActor(scene)
    renderer.AddActor(relief)
    camera = renderer.GetActiveCamera()  # the published Cornell box camera
    camera.SetPosition(278.0, 273.0, -800.0)
    camera.SetFocalPoint(278.0, 273.0, 0.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetViewAngle(39.3077)
    renderer.ResetCameraClippingRange()  # updates the relief: its probes and lights
    if errors:
        return 1

    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(args.size, args.size)
    if args.out:
        window.SetOffScreenRendering(1)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        writer = vtkPNGWriter()
        writer.SetInputConnection(grab.GetOutputPort())
        writer.SetFileName(args.out)
        writer.Write()
        if writer.GetErrorCode() != 0 or errors:
            print(f"relief_in_light_field.py: could not write {args.out}", file=sys.stderr)
            return 1
        print(f"wrote {args.out}")
        return 0
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    window.Render()
    interactor.Start()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
