# SPDX-License-Identifier: BSD-3-Clause
"""GUI: vtkSMReliefSurfaceRepresentationProxy switches a 2D view to 3D when the relief replaces
its flat input, but never for a representation loaded from a state file: the README pipeline
(emulated Apply) ends in 3D; the user sets 2D and a camera, saves the state, deletes everything
and loads it: the loaded view, whose only visible data is the relief, keeps 2D and the camera
(without the state-file guard it would be switched to 3D and the camera reset)."""
import os

# run-gui-test.sh puts this directory on PYTHONPATH (paraview --script defines no __file__).
import mesolight_guitest as g  # noqa: E402
import paraview.simple as pvs  # noqa: E402


def main():
    failures = []
    view = g.gui_view()
    p = g.readme_pipeline(view)
    print("after the README pipeline: interaction mode %s" % view.InteractionMode)
    if view.InteractionMode != "3D":
        failures.append("after the README pipeline: %s, expected 3D" % view.InteractionMode)
    view.InteractionMode = "2D"
    camera = [0.3, 0.2, 5.0]
    view.CameraPosition = camera
    view.CameraFocalPoint = [0.3, 0.2, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    pvs.Render(view)
    path = os.path.join(g.output_dir(), "gui-state-2d.pvsm")
    pvs.SaveState(path)
    for name in ("attached", "plane", "relief", "depth"):
        pvs.Delete(p[name])
    pvs.Delete(view)
    pvs.LoadState(path)
    loaded = pvs.GetActiveViewOrCreate("RenderView")
    pvs.Render(loaded)
    pvs.Render(loaded)
    visible = [r.Input.GetXMLName() for r in g.visible_data_representations(loaded)]
    print("loaded state: visible %s, interaction mode %s, camera %s"
          % (visible, loaded.InteractionMode, list(loaded.CameraPosition)))
    if visible != ["MesolightAttachReliefTexture"]:
        failures.append("the loaded state should show only the relief, not %s" % visible)
    if loaded.InteractionMode != "2D":
        failures.append("the loaded state's 2D became %s" % loaded.InteractionMode)
    if max(abs(a - b) for a, b in zip(loaded.CameraPosition, camera)) > 1e-6:
        failures.append("the loaded camera moved to %s" % list(loaded.CameraPosition))
    return failures


g.run(main)
