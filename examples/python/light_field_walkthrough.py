# SPDX-License-Identifier: BSD-3-Clause
"""A walk through a virtual light field from Python (Wither 2005):
examples/cxx/LightFieldWalkthrough.cxx line for line. The built-in Cornell box is propagated by
vtkVirtualLightField, drawn by vtkLightFieldActor, and an ordinary sphere actor placed in it (the
movable object: move it with SetPosition and render again) is shaded by the light it gathers from
the field.

    scripts/python.sh examples/python/light_field_walkthrough.py            (a window)
    scripts/python.sh examples/python/light_field_walkthrough.py out.png    (one frame, offscreen)
"""
import sys

from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderWindow, vtkRenderWindowInteractor,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle  # noqa: F401 (the interactor's default style)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

from mesolight import (vtkCornellBoxSource, vtkLightFieldActor, vtkLightFieldObjectMapper,
                       vtkVirtualLightField)


def main(argv):
    # The scene: the published Cornell box in millimetres (any OBJ/MTL scene works as well, read
    # by vtkOBJSceneReader).
    box = vtkCornellBoxSource()

    # The light field: 513 directions, 32 x 32 rays a side, 4 shooting iterations (a few seconds
    # on two cores; 2049 directions and more iterations for final images).
    field = vtkVirtualLightField()
    field.SetInputConnection(box.GetOutputPort())
    field.SetDirections(513)
    field.SetRaysPerSide(32)
    field.SetIterations(4)

    scene = vtkLightFieldActor()
    scene.SetLightFieldFilter(field)  # updated when first drawn
    scene.SetRenderModeToProgressive()
    scene.SetExposure(0.6)

    # An ordinary actor in the box, shaded by the irradiance it gathers from the field.
    sphere = vtkSphereSource()
    sphere.SetRadius(60.0)
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(16)
    object_mapper = vtkLightFieldObjectMapper()
    object_mapper.SetInputConnection(sphere.GetOutputPort())
    object_mapper.SetLightFieldActor(scene)
    movable = vtkActor()
    movable.SetMapper(object_mapper)
    movable.SetPosition(400.0, 70.0, 150.0)  # on the floor, before the tall block
    movable.GetProperty().SetDiffuseColor(0.8, 0.8, 0.8)
    scene.SetMovableObject(movable)

    renderer = vtkRenderer()
    renderer.AddActor(scene)
    renderer.AddActor(movable)
    camera = renderer.GetActiveCamera()  # the published camera
    camera.SetPosition(278.0, 273.0, -800.0)
    camera.SetFocalPoint(278.0, 273.0, 0.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetViewAngle(39.3)
    renderer.ResetCameraClippingRange()

    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(400, 400)
    if len(argv) > 1:
        window.SetOffScreenRendering(1)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        writer = vtkPNGWriter()
        writer.SetInputConnection(grab.GetOutputPort())
        writer.SetFileName(argv[1])
        writer.Write()
        if writer.GetErrorCode() != 0:
            print(f"light_field_walkthrough.py: could not write {argv[1]}", file=sys.stderr)
            return 1
        print(f"wrote {argv[1]}")
        return 0
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    window.Render()
    interactor.Start()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
