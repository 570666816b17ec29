# SPDX-License-Identifier: BSD-3-Clause
"""GUI: a movable object in the light field, as a user builds it, each step applied as the GUI
applies it: Cornell Box -> Virtual Light Field; Sphere -> Transform (Translate) -> Light Field
Gather (Light Field = the field). Then the field display's Shadow Caster is set to the gather.

- Apply of the field shows it as Light Field without the Diffuse array or a legend;
- Apply of the gather shows it as Light Field (no colour array) and keeps the scene shown (its
  replace_input="2" hint hides only the Transform, shown as Surface);
- with the Shadow Caster the scene loses light under the object: more than MIN_SHADOW_PIXELS
  pixels darker by more than 3 levels, brighter ones fewer than 1% of them (the GUI smooths
  edges);
- must fail (the measure can fail): Shadow Mode None, and no Shadow Caster, darken nothing.
"""
# run-gui-test.sh puts this directory on PYTHONPATH (paraview --script defines no __file__).
import mesolight_guitest as g  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402

MIN_SHADOW_PIXELS = 300


def darkened(frame, reference):
    drop = (reference - frame).max(axis=2)
    return int((drop > 3).sum()), int(((frame - reference).max(axis=2) > 3).sum())


def main():
    failures = []
    view = g.gui_view()
    box = pvs.MesolightCornellBox()
    g.apply(box, view)
    field = pvs.MesolightVirtualLightField(Input=box)
    g.apply(field, view)
    # The scene's radiance, not its Diffuse array (the data's active scalars): no colour array,
    # no legend (before vtkSMLightFieldRepresentationProxy: Diffuse, "Diffuse Magnitude").
    shown_field = pvs.GetDisplayProperties(field, view)
    bars = [r for r in view.Representations
            if r.GetXMLName() == "ScalarBarWidgetRepresentation" and r.Visibility]
    print("Virtual Light Field shown as %r, colour array %r, %d legends"
          % (shown_field.Representation, shown_field.ColorArrayName[1], len(bars)))
    if shown_field.Representation != "Light Field" or shown_field.ColorArrayName[1] or bars:
        failures.append("Apply should show the field as Light Field without a colour array or "
                        "legend (%r, %r, %d legends)" % (shown_field.Representation,
                                                        shown_field.ColorArrayName[1], len(bars)))
    sphere = pvs.Sphere(Radius=55.0, ThetaResolution=32, PhiResolution=16)
    g.apply(sphere, view)
    moved = pvs.Transform(Input=sphere)
    moved.Transform.Translate = [170.0, 290.0, 160.0]
    g.apply(moved, view)
    gather = pvs.MesolightLightFieldGather(Input=moved, LightField=field)
    g.apply(gather, view)
    scene = pvs.GetDisplayProperties(field, view)
    obj = pvs.GetDisplayProperties(gather, view)
    shown = sorted(r.Input.GetXMLLabel() for r in g.visible_data_representations(view))
    print("after Apply: gather shown as %r (colour array %r); visible: %s"
          % (obj.Representation, obj.ColorArrayName[1], shown))
    if obj.Representation != "Light Field" or obj.ColorArrayName[1]:
        failures.append("Apply should show the gather as Light Field without a colour array")
    if "Mesolight Virtual Light Field" not in shown or "Transform" in shown:
        failures.append("Apply should keep the scene and hide the Transform: %s" % shown)
    view.CameraPosition = [278.0, 273.0, -800.0]
    view.CameraFocalPoint = [278.0, 273.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 39.3077
    without = g.grab(view, "gui-object-no-caster.png")
    scene.ShadowCaster = gather  # what picking it in the Shadow Caster selector does
    with_shadow = g.grab(view, "gui-object-shadow.png")
    darker, brighter = darkened(with_shadow, without)
    print("Shadow Caster = the gather (Shadow Mode %s): %d pixels darker, %d brighter"
          % (scene.LightFieldShadowMode, darker, brighter))
    if darker < MIN_SHADOW_PIXELS or brighter > 0.01 * darker:
        failures.append("the object's shadow should darken > %d pixels and brighten < 1%% of "
                        "them (%d, %d)"
                        % (MIN_SHADOW_PIXELS, darker, brighter))
    scene.LightFieldShadowMode = "None"
    off = g.grab(view, "gui-object-mode-none.png")
    scene.LightFieldShadowMode = "Field"
    scene.ShadowCaster = []
    removed = g.grab(view, "gui-object-caster-removed.png")
    for label, frame in (("Shadow Mode None", off), ("Shadow Caster removed", removed)):
        d, b = darkened(frame, without)
        print("negative: %s: %d pixels darker, %d brighter" % (label, d, b))
        if d > 0 or b > 0:
            failures.append("negative check: %s should leave the scene as without a caster"
                            % label)
    return failures


g.run(main)
