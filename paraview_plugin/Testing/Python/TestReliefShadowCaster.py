# SPDX-License-Identifier: BSD-3-Clause
"""The movable object's shadow on a Relief Surface lit by a Virtual Light Field (Wither 2005
ch. 4): a sphere (Sphere -> Transform -> Light Field Gather) in front of the Cornell box's back
wall, a relief patch mounted on that wall, the gather output set as the Shadow Caster of the
field's own display only (what a user does to shadow the scene).

- The relief follows the scene display's Shadow Caster (Light Field Display From Scene, on by
  default): its ReliefShadowCaster becomes the gather output.
- The shadow on the flat relief against an independent renderer of the same field, object and
  view: `mesolight vlf render --object sphere.obj --shadows field` (the VTK light field actor,
  its own shadow maps, on the flat wall the patch covers), against its `--shadows none` image.
  Over the shadow region on the patch (pixels the reference's shadow darkens by more than 3
  levels, where the unshadowed relief and the reference's wall agree), the ratio of linear
  radiance with / without the shadow must match the reference's within MAX_RATIO_ERROR and
  darken by at least 20%.
- A relief with depth is shadowed alike (ratio within MAX_DEPTH_RATIO_ERROR of the flat one's),
  and what the shadowed frame shows on the patch is the relief (as drawn with the scene hidden),
  not the wall: a flat relief and its wall look alike, so the ratios alone could not tell.
- Negative: the relief's own empty Shadow Caster (scene display not followed) leaves the region
  unshadowed; the Black mode (followed from the scene display) misses the field-derived ratio;
  without a Light Field the caster changes nothing (the view's lights are not the field's).
- A display transform (Position) of the field-lit relief is warned about, once.
- A caster gathered from another field (another scene) shadows neither the scene nor the relief,
  and is warned about; the field's own caster shadows again after it.
- The panel's Light Field selector offers only fields, the Shadow Caster selectors only gathers.
- A saved state, loaded in a new session, shadows the relief again.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkOutputWindow  # noqa: E402

SIZE = 300
EXPOSURE = 4.0
PATCH_Z = 558.0  # 1.2 mm in front of the back wall (z = 559.2, facing -z)
# Below the lamp and in front of the back wall's left part: its shadow falls on the wall, clear
# of the tall block; the sphere is clear of every surface (the actor warns otherwise).
CENTRE, RADIUS = [150.0, 380.0, 500.0], 40.0
MAX_RATIO_ERROR = 0.05
MAX_DEPTH_RATIO_ERROR = 0.10

t.load_plugin()
failures = []
check = t.checker(failures)

out = t.output_dir()
snapshot = os.path.join(out, "pv-relief-shadow.vlf")
field, moved, gather = t.cornell_field_with_object(snapshot, CENTRE, RADIUS)

view = t.make_cornell_view(SIZE)
scene = pvs.Show(field, view)
obj = pvs.Show(gather, view)
for display in (scene, obj):
    display.LightFieldAutoExposure = 0
    display.LightFieldToneMapping = "Clamp"
    display.LightFieldExposure = EXPOSURE

# The patch on the back wall's left part (normal -z, towards the camera), above the short block
# and left of the tall one.
patch = pvs.Plane(Origin=[30.0, 230.0, PATCH_Z], Point1=[30.0, 500.0, PATCH_Z],
                  Point2=[260.0, 230.0, PATCH_Z], XResolution=2, YResolution=2)
attached, relief = t.show_relief(patch, t.relief_texture(128), view, OverrideDepthScale=1,
                                 ReliefDepthScale=0.0)
relief.Ambient, relief.Diffuse = 0.0, 1.0


def capture(name):
    return t.cornell_capture(view, os.path.join(out, name)).astype(np.float64)


# The patch's footprint, shrunk by 3 pixels (edges are not compared).
scene.Visibility = obj.Visibility = 0
relief.SetRepresentationType("Surface")
relief.AmbientColor = relief.DiffuseColor = [1.0, 1.0, 1.0]
relief.Ambient, relief.Diffuse = 1.0, 0.0
footprint = t.eroded(capture("pv-relief-shadow-footprint.png").max(axis=2) > 128, 3)
scene.Visibility = obj.Visibility = 1
relief.SetRepresentationType("Relief Surface")
relief.Ambient, relief.Diffuse = 0.0, 1.0
print("patch footprint: %d pixels" % int(footprint.sum()))
check(footprint.sum() > 2000, "the patch covers part of the view")

# --- without a Light Field the caster changes nothing ------------------------------------------
view_lit = capture("pv-relief-shadow-view-lights.png")
scene.ShadowCaster = gather
relief.ReliefShadowCaster = gather  # even set on the relief itself
view_lit_caster = capture("pv-relief-shadow-view-lights-caster.png")
moved_levels = float(np.abs(view_lit_caster[footprint] - view_lit[footprint]).mean())
print("negative: the relief lit by the view's lights, a Shadow Caster set: mean change %.3f "
      "levels" % moved_levels)
check(moved_levels < 0.5, "without a Light Field the Shadow Caster does not darken the relief")
scene.ShadowCaster = []
relief.ReliefShadowCaster = []

# --- the reference: the VTK light field actor on the flat wall ----------------------------------
relief.LightField = field
obj_file = t.write_obj(moved, os.path.join(out, "pv-relief-shadow-sphere.obj"))


def reference(shadows):
    path = os.path.join(out, "pv-relief-shadow-reference-%s.png" % shadows)
    return t.object_shadow_reference(snapshot, obj_file, shadows, path, SIZE, EXPOSURE)



unshadowed = capture("pv-relief-shadow-none.png")  # the field exists once this has rendered
ref_none, ref_field = reference("none"), reference("field")

# --- the Shadow Caster set on the scene display only ---------------------------------------------
scene.ShadowCaster = gather
shadowed = capture("pv-relief-shadow-field.png")
followed = relief.GetProperty("ReliefShadowCaster").GetData()
print("the relief's Shadow Caster after setting the scene display's: %s" % followed)
check(followed is not None and followed.SMProxy is gather.SMProxy,
      "the relief follows the scene display's Shadow Caster")

drop = (ref_none - ref_field) @ t.REC709
agree = np.abs(unshadowed - ref_none).max(axis=2) <= 10
region = footprint & (drop > 3.0) & (ref_none.max(axis=2) < 255) & agree
print("shadow region on the patch: %d pixels (%d darkened by the reference on the patch)"
      % (int(region.sum()), int((footprint & (drop > 3.0)).sum())))
check(region.sum() > 300, "the reference's shadow covers more than 300 pixels of the patch")


def ratio(with_shadow, without):
    return t.radiance_left(with_shadow, without, region, EXPOSURE)


r_ref = ratio(ref_field, ref_none)
r_relief = ratio(shadowed, unshadowed)
print("radiance left in the shadow (with / without): VTK actor's wall %.4f, Relief Surface "
      "%.4f (difference %.4f); mean pixel difference %.2f levels"
      % (r_ref, r_relief, r_relief - r_ref,
         float(np.abs(shadowed[region] - ref_field[region]).mean())))
check(abs(r_relief - r_ref) <= MAX_RATIO_ERROR, "the relief's field-derived shadow matches the "
      "VTK actor's on the wall within %.2f (%.4f vs %.4f)" % (MAX_RATIO_ERROR, r_relief, r_ref))
check(r_relief < 0.8, "the shadow darkens the relief by at least 20%% (%.4f left)" % r_relief)

# --- a relief with depth is shadowed alike --------------------------------------------------------
relief.ReliefDepthScale = 0.1
scene.ShadowCaster = []
deep_none = capture("pv-relief-shadow-deep-none.png")
scene.ShadowCaster = gather
deep_field = capture("pv-relief-shadow-deep-field.png")
r_deep = ratio(deep_field, deep_none)
changed = float((np.abs(deep_none[footprint] - unshadowed[footprint]).max(axis=1) > 8).mean())
print("relief with depth: %.1f%% of the patch differs from the flat one by > 8 levels; %.4f "
      "left in the shadow (flat %.4f)" % (100.0 * changed, r_deep, r_relief))
check(changed > 0.05, "the relief with depth shows its relief")
check(abs(r_deep - r_relief) <= MAX_DEPTH_RATIO_ERROR,
      "the relief with depth is shadowed like the flat one (%.4f vs %.4f)" % (r_deep, r_relief))
# What the shadowed frame shows on the patch is the relief, not the wall behind it: the same
# pixels as the relief drawn with the scene hidden (before the relief's data was delivered again
# after following the caster, it was drawn nothing and this was 29 levels).
scene.Visibility = 0
deep_alone = capture("pv-relief-shadow-deep-field-alone.png")
scene.Visibility = 1
shown_alone = float(np.abs(deep_field[footprint] - deep_alone[footprint]).mean())
print("the shadowed relief with depth against the same relief with the scene hidden: %.2f levels"
      % shown_alone)
check(shown_alone < 1.0, "the shadowed frame shows the relief over the patch (%.2f levels)"
      % shown_alone)
relief.ReliefDepthScale = 0.0

# --- negative tests ----------------------------------------------------------------------------
relief.ReliefLightFieldSceneDisplay = 0
relief.ReliefShadowCaster = []
own = capture("pv-relief-shadow-own-empty.png")
r_own = ratio(own, unshadowed)
print("negative: the relief's own empty Shadow Caster: %.4f left" % r_own)
check(abs(r_own - 1.0) <= 0.02, "the relief's own empty Shadow Caster: no darkening (%.4f)"
      % r_own)
check(abs(r_own - r_ref) > MAX_RATIO_ERROR, "negative: an unshadowed relief misses the reference")
relief.ReliefLightFieldSceneDisplay = 1
scene.LightFieldShadowMode = "Black"
black = capture("pv-relief-shadow-black.png")
r_black = ratio(black, unshadowed)
print("negative: Black mode (followed from the scene display): %.4f left (reference %.4f)"
      % (r_black, r_ref))
check(relief.ReliefShadowMode == "Black", "the relief follows the scene display's Shadow Mode")
check(abs(r_black - r_ref) > MAX_RATIO_ERROR,
      "negative: Black mode misses the field-derived reference (%.4f vs %.4f)" % (r_black, r_ref))
scene.LightFieldShadowMode = "None"
off = capture("pv-relief-shadow-mode-none.png")
r_off = ratio(off, unshadowed)
check(abs(r_off - 1.0) <= 0.005, "Shadow Mode None: no darkening of the relief (%.4f)" % r_off)

# --- a display transform moves the relief away from the light it is lit with: said once --------
warnings = []
window = vtkOutputWindow.GetInstance()


@calldata_type(VTK_STRING)
def on_warning(caller, event, text):
    warnings.append(text)


tag = window.AddObserver(vtkCommand.WarningEvent, on_warning)
relief.Position = [0.0, 0.0, -5.0]
capture("pv-relief-shadow-translated.png")
capture("pv-relief-shadow-translated-again.png")
relief.Position = [0.0, 0.0, 0.0]
capture("pv-relief-shadow-translated-back.png")
window.RemoveObserver(tag)
said = [w for w in warnings if "Transform filter" in w]
print("display transform on a field-lit relief: %d warning(s) over two renders" % len(said))
check(len(said) == 1, "a display transform of a field-lit relief is warned about once (%d)"
      % len(said))

# --- a caster gathered from another field casts no shadow, on the scene or the relief: said ---
# The same sphere gathered from the field of another scene (the box moved 100 mm to the right:
# another unit sphere, its lamp elsewhere) would put that field's shadow here.
scene.LightFieldShadowMode = "Field"
moved_box = pvs.Transform(Input=pvs.MesolightCornellBox())
moved_box.Transform.Translate = [100.0, 0.0, 0.0]
other_field = pvs.MesolightVirtualLightField(Input=moved_box, Directions=33, RaysPerSide=8,
                                             Iterations=1)
other_gather = pvs.MesolightLightFieldGather(Input=moved, LightField=other_field)
warnings.clear()
tag = window.AddObserver(vtkCommand.WarningEvent, on_warning)
scene.ShadowCaster = other_gather
mismatched = capture("pv-relief-shadow-other-field.png")
capture("pv-relief-shadow-other-field-again.png")
window.RemoveObserver(tag)
said = [w for w in warnings if "gathered from another light field" in w]
changed_px = int((np.abs(mismatched - unshadowed).max(axis=2) > 3).sum())
print("a caster gathered from another field: %d pixels of the frame differ from the unshadowed "
      "one by > 3 levels; %d warning(s) over two renders" % (changed_px, len(said)))
for w in said[:1]:
    print("  " + w.strip().splitlines()[-1])
check(changed_px == 0, "a caster of another field shadows neither the scene nor the relief "
      "(%d pixels changed)" % changed_px)
check(1 <= len(said) <= 2, "a caster of another field is said once per display that draws it "
      "(%d)" % len(said))
scene.ShadowCaster = gather  # its own field's caster shadows again (the check is not sticky)
r_again = ratio(capture("pv-relief-shadow-field-again.png"), unshadowed)
print("the field's own caster again: %.4f left (before %.4f)" % (r_again, r_relief))
check(abs(r_again - r_relief) <= 0.005, "the field's own caster shadows the relief again")

# --- the panel's selectors offer what each input takes -------------------------------------------
# Every output above has executed, so the panel knows its arrays. The relief's Light Field lists
# the two fields and nothing else (not the box, the sphere, the gathers, the patch); the scene's
# Shadow Caster lists the two gathers (a field, the sphere, the patch would each give an error).
fields = t.selector_choices(relief, "LightField")
casters = t.selector_choices(scene, "ShadowCaster")
print("Light Field selector: %d choices; Shadow Caster selector: %d choices" % (len(fields),
                                                                                len(casters)))
check(fields == {t.choice(field), t.choice(other_field)},
      "the relief's Light Field selector lists the two fields only")
check(casters == {t.choice(gather), t.choice(other_gather)},
      "the scene's Shadow Caster selector lists the two gathers only")
check(t.selector_choices(relief, "ReliefShadowCaster") == casters,
      "the relief's own Shadow Caster takes the same outputs")

# --- a state file brings the relief's shadow back ----------------------------------------------
state = os.path.join(out, "pv-relief-shadow.pvsm")
pvs.SaveState(state)
pvs.ResetSession()  # the plugin stays loaded in this process
pvs.LoadState(state)
view = pvs.GetActiveViewOrCreate("RenderView")
view.ViewSize = [SIZE, SIZE]
restored = capture("pv-relief-shadow-state.png")
r_state = ratio(restored, unshadowed)
print("state reloaded: %.4f left in the shadow on the relief (before %.4f)" % (r_state, r_relief))
check(abs(r_state - r_relief) <= 0.01,
      "the saved state brings the relief's shadow back (%.4f)" % r_state)

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
