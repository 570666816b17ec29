# SPDX-License-Identifier: BSD-3-Clause
"""GUI: a relief on the Cornell box's back wall lit by the light field, as a user builds it,
each step applied as the GUI applies it: Cornell Box -> Virtual Light Field; Procedural Relief
-> Relief Texture; Plane (in front of the back wall, facing the camera) -> Attach Relief
Texture, shown as Relief Surface (Solid Color left white: mounted on the back wall, the relief
takes the wall's Kd, Light Field Albedo); then the relief display's Light Field is set to the
field (what picking it in the panel's Light Field selector does).

- with the Light Field the relief looks like the wall it covers (the scene drawn as Light Field
  with the relief hidden): mean difference over the patch within MAX_MEAN_ERROR levels;
- must fail (the measure can fail): the relief lit by the view's lights (no Light Field);
- the panel shows Exposure, Tone Mapping and the Light Field's settings once the Light Field is
  set (LightFieldAttached 0, then 1), and not the light set's (LightSetAttached stays 0: no
  light set is attached; before, the field set it to 1 and showed Light Set Threshold and
  Shadowed Lights, which do nothing without a light set).
- a movable object (Sphere -> Transform -> Light Field Gather, applied as the GUI does) set as
  the scene display's Shadow Caster shadows the relief too: more than MIN_SHADOW_PIXELS of the
  patch darker by more than 3 levels and under 1% of that brighter (the relief still drawn),
  and the relief display's Shadow Caster is the gather;
  must fail: the caster removed darkens nothing.
"""
# run-gui-test.sh puts this directory on PYTHONPATH (paraview --script defines no __file__).
import mesolight_guitest as g  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402

MAX_MEAN_ERROR = 8.0
MIN_SHADOW_PIXELS = 300
PATCH_Z = 539.0  # the relief (depth 0.05 x 380 mm = 19 mm) mounted in front of the wall


def main():
    failures = []
    view = g.gui_view()
    box = pvs.MesolightCornellBox()
    g.apply(box, view)
    field = pvs.MesolightVirtualLightField(Input=box, Directions=513, RaysPerSide=32,
                                           Iterations=3)
    g.apply(field, view)
    depth = pvs.MesolightProceduralRelief()
    g.apply(depth, view)
    relief = pvs.MesolightReliefTexture(Input=pvs.OutputPort(depth, 0))
    g.apply(relief, view)
    plane = pvs.Plane(Origin=[90.0, 90.0, PATCH_Z], Point1=[90.0, 470.0, PATCH_Z],
                      Point2=[470.0, 90.0, PATCH_Z])
    g.apply(plane, view)
    attached = pvs.MesolightAttachReliefTexture(Input=plane, ReliefTexture=relief)
    g.apply(attached, view)
    shown = pvs.GetDisplayProperties(attached, view)
    shown.SetRepresentationType("Relief Surface")
    shown.ColorArrayName = ["POINTS", ""]
    for source in (depth, relief, plane):
        pvs.Hide(source, view)
    pvs.Show(field, view)
    view.CameraPosition = [278.0, 273.0, -800.0]
    view.CameraFocalPoint = [278.0, 273.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 39.3077

    # The patch's footprint: the relief hidden against the relief drawn plain white.
    shown.Visibility = 0
    wall = g.grab(view, "gui-relief-field-wall.png")
    shown.Visibility = 1
    shown.SetRepresentationType("Surface")
    shown.AmbientColor = shown.DiffuseColor = [1.0, 1.0, 1.0]
    shown.Ambient, shown.Diffuse = 1.0, 0.0
    white = g.grab(view, "gui-relief-field-footprint.png")
    footprint = (white.min(axis=2) > 250) & (wall.min(axis=2) < 250)
    for _ in range(3):
        footprint = (footprint & np.roll(footprint, 1, 0) & np.roll(footprint, -1, 0) &
                     np.roll(footprint, 1, 1) & np.roll(footprint, -1, 1))
    shown.SetRepresentationType("Relief Surface")
    shown.Ambient, shown.Diffuse = 0.0, 1.0  # Solid Color stays white
    print("patch footprint: %d pixels" % int(footprint.sum()))
    if footprint.sum() < 1000:
        failures.append("the patch should cover much of the view (%d px)" % footprint.sum())
        return failures

    def error(frame):
        return float(np.abs(frame[footprint] - wall[footprint]).mean())

    kit = g.grab(view, "gui-relief-field-view-lights.png")
    lit = (shown.LightFieldAttached, shown.LightSetAttached)
    shown.LightField = field  # what picking the field in the panel's Light Field selector does
    with_field = g.grab(view, "gui-relief-field-lit.png")
    e_kit, e_field = error(kit), error(with_field)
    print("relief vs the wall it covers: view's lights %.2f levels, Light Field %.2f levels"
          % (e_kit, e_field))
    if e_field > MAX_MEAN_ERROR:
        failures.append("with the Light Field the relief should look like the wall (%.2f > %g)"
                        % (e_field, MAX_MEAN_ERROR))
    if e_kit <= MAX_MEAN_ERROR:
        failures.append("negative check: the view's lights should not match the wall (%.2f)"
                        % e_kit)
    now = (shown.LightFieldAttached, shown.LightSetAttached)
    print("panel: LightFieldAttached %d without, %d with the Light Field; LightSetAttached %d, %d"
          % (lit[0], now[0], lit[1], now[1]))
    if lit != (0, 0) or now != (1, 0):
        failures.append("the panel should show the Light Field's settings (not the light set's) "
                        "with a Light Field")

    # The movable object between the lamp and the patch's left part (clear of the patch).
    sphere = pvs.Sphere(Radius=40.0, ThetaResolution=32, PhiResolution=16)
    g.apply(sphere, view)
    moved = pvs.Transform(Input=sphere)
    moved.Transform.Translate = [150.0, 380.0, 480.0]
    g.apply(moved, view)
    gather = pvs.MesolightLightFieldGather(Input=moved, LightField=field)
    g.apply(gather, view)
    scene = pvs.GetDisplayProperties(field, view)
    no_caster = g.grab(view, "gui-relief-field-no-caster.png")
    scene.ShadowCaster = gather  # what picking it in the scene's Shadow Caster selector does
    shadowed = g.grab(view, "gui-relief-field-caster.png")
    darker = int((((no_caster - shadowed).max(axis=2) > 3) & footprint).sum())
    # Brighter pixels: the relief replaced by the flat wall (drawn nothing for a frame) would
    # brighten its grooves.
    brighter = int((((shadowed - no_caster).max(axis=2) > 3) & footprint).sum())
    followed = shown.GetProperty("ReliefShadowCaster").GetData()
    print("Shadow Caster set on the scene's display: %d pixels of the patch darker, %d brighter; "
          "the relief's Shadow Caster %s" % (darker, brighter, followed))
    if darker < MIN_SHADOW_PIXELS or brighter > 0.01 * darker:
        failures.append("the object's shadow should darken the relief (%d <= %d pixels) and "
                        "brighten none of it (%d)" % (darker, MIN_SHADOW_PIXELS, brighter))
    if followed is None or followed.SMProxy is not gather.SMProxy:
        failures.append("the relief should follow the scene display's Shadow Caster")
    scene.ShadowCaster = []
    removed = g.grab(view, "gui-relief-field-caster-removed.png")
    left = int((((no_caster - removed).max(axis=2) > 3) & footprint).sum())
    print("negative: the caster removed: %d pixels of the patch darker" % left)
    if left > 0:
        failures.append("negative check: without the caster the relief should not darken (%d)"
                        % left)
    return failures


g.run(main)
