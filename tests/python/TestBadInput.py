# SPDX-License-Identifier: BSD-3-Clause
"""Bad input from Python gives a VTK error that an observer catches, never a crash, and the
pipeline goes on: each case must raise at least one ErrorEvent naming the problem and leave an
empty output; a good input afterwards must work again. A case that raised no error (a silent
wrong result) fails the test.
"""
import os
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkCommonDataModel import vtkImageData

from mesolight import (vtkConeMapFilter, vtkCornellBoxSource, vtkLightFieldActor,
                       vtkLightFieldReliefActor, vtkMedianCutLights, vtkOIIOImageReader,
                       vtkProceduralEnvironmentSource, vtkProceduralReliefSource,
                       vtkReliefTextureFilter, vtkVirtualLightField)


class ErrorRecorder:
    """An ErrorEvent observer: VTK then reports to it instead of the output window."""

    # VTK passes the message as call data to an observer that says which type it wants.
    CallDataType = VTK_STRING

    def __init__(self, *objects):
        self.messages = []
        for obj in objects:
            obj.AddObserver(vtkCommand.ErrorEvent, self)

    def __call__(self, caller, event, message=None):
        self.messages.append(str(message) if message is not None else "")


def image(width, height, values):
    data = vtkImageData()
    data.SetDimensions(width, height, 1)
    data.GetPointData().SetScalars(numpy_to_vtk(values.reshape(-1, values.shape[-1]), deep=True))
    return data


def expect_error(name, algorithm, pattern, output_size):
    errors = ErrorRecorder(algorithm, algorithm.GetExecutive())
    algorithm.Update()
    size = output_size(algorithm)
    matched = [m for m in errors.messages if pattern.lower() in m.lower()]
    lines = [line.strip() for m in matched for line in m.splitlines()
             if pattern.lower() in line.lower()]
    print(f"{name}: {len(errors.messages)} error(s), output size {size}: "
          f"{lines[0] if lines else '(none)'}")
    if not matched:
        print(f"  FAIL: no error mentioning '{pattern}'")
        return False
    if size != 0:
        print("  FAIL: an output despite the error")
        return False
    return True


def expect_actor_error(name, actor, pattern):
    """The actor's own observers hear the error, once however often it is measured; it has no
    bounds and the walkthrough shows the flat surface (no hole)."""
    errors = ErrorRecorder(actor)
    bounds = [actor.GetBounds() for _ in range(3)]  # a render asks several times
    empty = all(b is None or b[1] < b[0] for b in bounds)
    matched = [m for m in errors.messages if pattern.lower() in m.lower()]
    shown = actor.GetLightFieldActor().GetNumberOfHiddenSurfaces() == 0
    print(f"{name}: {len(errors.messages)} error(s) to the actor, empty: {empty}, surface shown: "
          f"{shown}: {matched[0].strip().splitlines()[-1] if matched else '(none)'}")
    ok = True
    if not matched:
        print(f"  FAIL: no error mentioning '{pattern}' reached the actor's observer")
        ok = False
    if len(errors.messages) != 1:
        print("  FAIL: not one message")
        ok = False
    if not empty:
        print("  FAIL: bounds despite the error")
        ok = False
    if not shown:
        print("  FAIL: the walkthrough hides the surface of a relief that is not drawn")
        ok = False
    actor.RemoveObservers(vtkCommand.ErrorEvent)
    return ok


def main():
    ok = True
    points = lambda a: a.GetOutput().GetNumberOfPoints()  # noqa: E731

    # An all-black environment: no light to cut.
    lights = vtkMedianCutLights()
    lights.SetInputData(image(64, 32, np.zeros((32, 64, 3), np.float32)))
    ok &= expect_error("black environment", lights, "no light", points)

    # NaN pixels are named, not propagated into the lights.
    nan_map = np.ones((32, 64, 3), np.float32)
    nan_map[5, 7] = np.nan
    lights.SetInputData(image(64, 32, nan_map))
    ok &= expect_error("NaN environment", lights, "NaN", points)

    # A file that does not exist.
    reader = vtkOIIOImageReader()
    reader.SetFileName(os.path.join(tempfile.gettempdir(), "mesolight-no-such-file.exr"))
    ok &= expect_error("missing file", reader, "no-such-file", points)

    # A cone map filter without an input.
    cones = vtkConeMapFilter()
    ok &= expect_error("no input", cones, "input", points)

    # A relief actor on a light field: no texture, then a surface the scene does not have. The
    # actor is measured (GetBounds updates it, as a render does): an error, nothing to draw.
    box = vtkCornellBoxSource()
    field = vtkVirtualLightField()
    field.SetInputConnection(box.GetOutputPort())
    field.SetDirections(129)
    field.SetRaysPerSide(8)
    field.SetIterations(1)
    walkthrough = vtkLightFieldActor()
    walkthrough.SetLightFieldFilter(field)
    walkthrough.GetBounds()  # propagates
    relief = vtkLightFieldReliefActor()
    relief.SetLightFieldActor(walkthrough)
    relief.SetSurfaceName("back")
    ok &= expect_actor_error("relief actor without a texture", relief, "relief texture")
    bricks = vtkProceduralReliefSource()
    bake = vtkReliefTextureFilter()
    bake.SetInputConnection(bricks.GetOutputPort(0))
    bake.Update()
    relief.SetReliefTextureData(bake.GetOutput())
    relief.SetSurfaceName("wall")
    ok &= expect_actor_error("relief actor on an unknown surface", relief, "back, left")
    relief.SetSurfaceName("tall")
    ok &= expect_actor_error("relief actor on a surface that is not planar", relief, "planar")
    relief.SetSurfaceName("back")
    errors = ErrorRecorder(relief)
    bounds = relief.GetBounds()
    hidden = walkthrough.GetNumberOfHiddenSurfaces()
    relief.VisibilityOff()
    hidden_off = walkthrough.GetNumberOfHiddenSurfaces()
    relief.VisibilityOn()
    good = (bounds[1] > bounds[0] and not errors.messages and hidden == 1 and hidden_off == 0
            and walkthrough.GetNumberOfHiddenSurfaces() == 1)
    print(f"relief actor on 'back' afterwards: x from {bounds[0]:.3f} to {bounds[1]:.3f}, "
          f"{len(errors.messages)} errors; surfaces hidden {hidden}, {hidden_off} with the actor "
          f"invisible, {walkthrough.GetNumberOfHiddenSurfaces()} visible again")
    ok &= good
    del relief  # deleted, the walkthrough shows the back wall again
    print(f"relief actor deleted: surfaces hidden {walkthrough.GetNumberOfHiddenSurfaces()}")
    ok &= walkthrough.GetNumberOfHiddenSurfaces() == 0

    # The same filter goes on working with a good input.
    sky = vtkProceduralEnvironmentSource()
    sky.SetResolution(64, 32)
    lights.SetInputConnection(sky.GetOutputPort())
    lights.SetNumberOfLights(8)
    errors = ErrorRecorder(lights)
    lights.Update()
    good = points(lights) == 8 and not errors.messages
    print(f"good input afterwards: {points(lights)} lights, {len(errors.messages)} errors")
    ok &= good
    print("OK" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
