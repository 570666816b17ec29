# SPDX-License-Identifier: BSD-3-Clause
"""Shared pieces of the GUI tests: scripts run by the real `paraview` executable
(run-gui-test.sh: `paraview --script=F.py --exit` under Xvfb, private HOME).

The plugin is auto-loaded by the GUI itself (PV_PLUGIN_PATH), not by LoadPlugin. Proxies are
created with their XML defaults, which are the defaults the Properties panel shows. Apply is
`apply()`: ParaView 5.11's pqApplyBehavior::showData (Qt, not reachable from Python) step by step
with the same server-manager controller it uses: every output port shown by
ShowInPreferredView (which honours the proxy's <View> and <RepresentationType> hints), the
camera reset when the data is the only visible one, the interaction mode chosen as
pqRenderView::updateInteractionMode chooses it (2D for data with a flat bounding box), and the
inputs hidden as the <Visibility replace_input> hint says. TestGUIApplyButton.xml clicks the real
Apply button instead.
"""
import os
import sys
import traceback

import numpy as np
import paraview.simple as pvs
from paraview import servermanager as sm
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

RESULT = os.environ.get("MESOLIGHT_GUI_RESULT", "")


def output_dir():
    out = os.environ.get("MESOLIGHT_TEST_OUTPUT", ".")
    os.makedirs(out, exist_ok=True)
    return out


def run(main):
    """Runs main() (returning a list of failures) and writes the verdict for run-gui-test.sh."""
    try:
        failures = main()
    except Exception:  # any exception is a failure with its traceback
        failures = ["exception:\n" + traceback.format_exc()]
    verdict = "OK\n" if not failures else "FAILED\n" + "\n".join(failures) + "\n"
    print(verdict)
    sys.stdout.flush()
    if RESULT:
        with open(RESULT, "w") as f:
            f.write(verdict)


def gui_view():
    """The render view the GUI opened at start-up (the one a user sees)."""
    view = pvs.GetActiveView()
    if view is None or view.GetXMLName() != "RenderView":
        raise RuntimeError("the GUI has no active render view")
    return view


def visible_data_representations(view):
    reps = []
    for rep in view.Representations:
        if rep.GetProperty("Input") is not None and rep.GetPropertyValue("Visibility"):
            reps.append(rep)
    return reps


def _replace_input(proxy):
    hints = proxy.SMProxy.GetHints()
    if hints is None:
        return 1
    for i in range(hints.GetNumberOfNestedElements()):
        child = hints.GetNestedElement(i)
        if child.GetName() == "Visibility" and child.GetAttribute("replace_input") is not None:
            return int(child.GetAttribute("replace_input"))
    return 1


def _update_interaction_mode(view, source, port):
    bounds = source.GetDataInformation(port).GetBounds()
    extents = [bounds[2 * i + 1] - bounds[2 * i] for i in range(3)]
    flat = [i for i in range(3) if extents[i] == 0]
    if not flat:
        view.InteractionMode = "3D"
        return
    axis = flat[0]
    focal = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    position = list(focal)
    position[axis] = focal[axis] + 10000  # ParaView 5.11.0 (5.11.2: 3.35 x the widest extent)
    up = [0.0, 0.0, 0.0]
    up[(axis + 2) % 3] = 1.0
    view.CameraFocalPoint = focal
    view.CameraPosition = position
    view.CameraViewUp = up
    view.InteractionMode = "2D"


def apply(source, view=None):
    """The first Apply of a newly created source (pqApplyBehavior::showData, ParaView 5.11)."""
    view = view or gui_view()
    controller = sm.vtkSMParaViewPipelineControllerWithRendering()
    source.UpdatePipeline()
    for port in range(source.GetNumberOfOutputPorts()):
        preferred = controller.ShowInPreferredView(source.SMProxy, port, view.SMProxy)
        if preferred is None:
            continue
        if preferred.GetGlobalID() != view.SMProxy.GetGlobalID():
            raise RuntimeError("%s opened another view" % source.GetXMLLabel())
        if len(visible_data_representations(view)) == 1:
            view.ResetCamera(False)
            _update_interaction_mode(view, source, port)
        replace = _replace_input(source) if source.GetProperty("Input") is not None else 0
        if replace > 0:
            for name in ("Input", "ReliefTexture", "LightSet", "LightField"):
                prop = source.GetProperty(name)
                if prop is None:
                    continue
                for i in range(len(prop)):
                    inp = prop[i]
                    if inp is None:
                        continue
                    if replace == 2:
                        # pqApplyBehavior::hideInputIfRequired: only inputs shown as an opaque
                        # Surface.
                        shown = pvs.GetDisplayProperties(getattr(inp, "Proxy", inp), view)
                        if (shown.Representation not in ("Surface", "Surface With Edges")
                                or shown.Opacity < 1.0):
                            continue
                    controller.Hide(inp.SMProxy, inp.Port, view.SMProxy)
    pvs.SetActiveSource(source)
    pvs.Render(view)


def readme_pipeline(view, lights=False):
    """The README's GUI pipeline, each step created with its defaults and applied:
    Procedural Relief -> Relief Texture; Plane -> Attach Relief Texture (and, with lights,
    Procedural Environment -> Median Cut Lights as its Light Set)."""
    depth = pvs.MesolightProceduralRelief()
    apply(depth, view)
    relief = pvs.MesolightReliefTexture(Input=pvs.OutputPort(depth, 0))
    apply(relief, view)
    plane = pvs.Plane()
    apply(plane, view)
    light_set = None
    if lights:
        environment = pvs.MesolightProceduralEnvironment()
        apply(environment, view)
        cut = pvs.MesolightMedianCutLights(Input=environment)
        apply(cut, view)
        light_set = pvs.OutputPort(cut, 1)
    attached = pvs.MesolightAttachReliefTexture(Input=plane, ReliefTexture=relief)
    if light_set is not None:
        attached.LightSet = light_set
    apply(attached, view)
    return {"depth": depth, "relief": relief, "plane": plane, "attached": attached}


def grab(view, name):
    """The view's frame as the GUI shows it (its own size), saved and returned H x W x 3."""
    pvs.Render(view)
    path = os.path.join(output_dir(), name)
    pvs.SaveScreenshot(path, view, TransparentBackground=0)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[:, :, :3].astype(np.int32)


def covered(frame, background_frame, tolerance=8):
    """Pixels that differ from the same view drawn without the data."""
    return np.any(np.abs(frame - background_frame) > tolerance, axis=2)
