# SPDX-License-Identifier: BSD-3-Clause
"""A movable object in ParaView (Wither 2005 ch. 3-4): Sphere -> Transform -> Light Field Gather
inside the Cornell box's field, the gather output as the field display's Shadow Caster.

- Apply of Light Field Gather shows the Light Field representation, coloured by no array: the
  gathered radiance exposed (the scene's automatic exposure) and tone-mapped like the scene;
  the object's mean display level matches the vertices' Radiance tone-mapped in numpy.
- The shadow on the scene against an independent renderer of the same field, object and view:
  `mesolight vlf render --object sphere.obj --shadows field` (the VTK light field actor, its
  own shadow maps and pipeline), against its `--shadows none` image. Over the shadow region
  (pixels the reference's shadow darkens by more than 3 levels), the ratio of linear radiance
  with / without the shadow must match the reference's within MAX_RATIO_ERROR, and the shadow
  must darken by at least 20%.
- Negative: without a caster the same region keeps its radiance (ratio 1 within 0.02); the
  Black and Blend modes (fixed darkening) must miss the field-derived reference.
- A saved state brings the Shadow Caster back with its shadow.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

SIZE = 300
EXPOSURE = 4.0
# Above the short block: clear of every surface (the actor warns otherwise); its shadow falls on
# the block and the floor.
CENTRE, RADIUS = [170.0, 290.0, 160.0], 55.0
MAX_RATIO_ERROR = 0.05

t.load_plugin()
failures = []
check = t.checker(failures)

out = t.output_dir()
snapshot = os.path.join(out, "pv-shadow-field.vlf")
field, moved, gather = t.cornell_field_with_object(snapshot, CENTRE, RADIUS)

view = t.make_cornell_view(SIZE)

scene = pvs.Show(field, view)
obj = pvs.Show(gather, view)  # what Apply does
print("gather output on Apply: representation %s, colour array %s"
      % (obj.Representation, obj.ColorArrayName))
check(obj.Representation == "Light Field", "Apply shows Light Field Gather as Light Field")
check(not obj.ColorArrayName[1], "Apply colours the gathered surface by no array (no colour map)")


def capture(name):
    return t.cornell_capture(view, os.path.join(out, name)).astype(np.float64)


# --- the object as Apply shows it: the scene's automatic exposure, Reinhard -------------------
default = capture("pv-shadow-default.png")
scene.Visibility = 0
alone = capture("pv-shadow-object-alone.png")
scene.Visibility = 1
covered = alone.max(axis=2) > 0
data = servermanager.Fetch(field)
atlas = vtk_to_numpy(data.GetFieldData().GetArray("LightFieldAtlas")).astype(np.float64)
luminance = atlas[:, :3] @ np.array([0.2126, 0.7152, 0.0722])
key = 0.18 / np.exp(np.log(luminance[luminance > 0]).mean())
gathered = servermanager.Fetch(gather)
radiance = vtk_to_numpy(gathered.GetPointData().GetArray("Radiance")).astype(np.float64)
normals = vtk_to_numpy(gathered.GetPointData().GetNormals()).astype(np.float64)
points = vtk_to_numpy(gathered.GetPoints().GetData()).astype(np.float64)
facing = np.einsum("ij,ij->i", normals, np.array(t.CORNELL_EYE) - points) > 0
v = key * radiance[facing]
expected = t.srgb_encode(v / (1.0 + v)).mean()
level = alone[covered].mean()
print("object: %d pixels, mean display level %.1f; its camera-facing vertices' Radiance x %.3f "
      "(the scene's automatic exposure), Reinhard, sRGB: mean %.1f" % (int(covered.sum()), level,
                                                                   key, expected))
check(covered.sum() > 500, "the object is drawn")
check(abs(level - expected) < 12.0, "the object shows its gathered radiance exposed like the "
      "scene (mean level %.1f vs %.1f)" % (level, expected))

# --- the shadow against the VTK light field actor ----------------------------------------------
for display in (scene, obj):
    display.LightFieldAutoExposure = 0
    display.LightFieldToneMapping = "Clamp"
    display.LightFieldExposure = EXPOSURE

obj_file = t.write_obj(moved, os.path.join(out, "pv-shadow-sphere.obj"))


def reference(shadows):
    path = os.path.join(out, "pv-shadow-reference-%s.png" % shadows)
    return t.object_shadow_reference(snapshot, obj_file, shadows, path, SIZE, EXPOSURE)



ref_none, ref_field = reference("none"), reference("field")
scene.ShadowCaster = gather
shadowed = capture("pv-shadow-field.png")
scene.ShadowCaster = []
unshadowed = capture("pv-shadow-none.png")

# The shadow region: darkened by the reference's shadow, not saturated, and where the two
# renderers agree without the shadow (edges of the object and of walls excluded).
drop = (ref_none - ref_field) @ t.REC709
agree = np.abs(unshadowed - ref_none).max(axis=2) <= 6
region = (drop > 3.0) & (ref_none.max(axis=2) < 255) & agree
print("shadow region: %d pixels (%d darkened by the reference, %d of them where the unshadowed "
      "images agree)" % (int(region.sum()), int((drop > 3.0).sum()), int(region.sum())))
check(region.sum() > 300, "the reference shows a shadow region of more than 300 pixels")


def ratio(with_shadow, without):
    return t.radiance_left(with_shadow, without, region, EXPOSURE)


r_ref = ratio(ref_field, ref_none)
r_pv = ratio(shadowed, unshadowed)
error = float(np.abs(shadowed[region] - ref_field[region]).mean())
print("radiance left in the shadow (with / without): VTK actor %.4f, Light Field "
      "representation %.4f (difference %.4f); mean pixel difference %.2f levels"
      % (r_ref, r_pv, r_pv - r_ref, error))
check(abs(r_pv - r_ref) <= MAX_RATIO_ERROR, "the representation's field-derived shadow matches "
      "the VTK actor's within %.2f (%.4f vs %.4f)" % (MAX_RATIO_ERROR, r_pv, r_ref))
check(r_pv < 0.8, "the shadow darkens the region by at least 20%% (%.4f left)" % r_pv)

# --- negative tests ----------------------------------------------------------------------------
r_none = ratio(unshadowed, ref_none)
print("no caster: the region keeps %.4f of the reference's unshadowed radiance" % r_none)
check(abs(r_none - 1.0) <= 0.02, "no Shadow Caster: no darkening (%.4f)" % r_none)
scene.ShadowCaster = gather
for mode in ("Black", "Blend"):
    scene.LightFieldShadowMode = mode
    image = capture("pv-shadow-%s.png" % mode.lower())
    r_mode = ratio(image, unshadowed)
    print("%s mode: %.4f left (field-derived reference %.4f)" % (mode, r_mode, r_ref))
    check(abs(r_mode - r_ref) > MAX_RATIO_ERROR, "negative: %s mode misses the field-derived "
          "reference (%.4f vs %.4f)" % (mode, r_mode, r_ref))
scene.LightFieldShadowMode = "None"
image = capture("pv-shadow-mode-none.png")
r_off = ratio(image, unshadowed)
check(abs(r_off - 1.0) <= 0.005, "Shadow Mode None with a caster: no darkening (%.4f)" % r_off)

# --- a state file keeps the caster ---------------------------------------------------------------
scene.LightFieldShadowMode = "Field"
state = os.path.join(out, "pv-shadow.pvsm")
pvs.SaveState(state)
pvs.ResetSession()  # the plugin stays loaded in this process
pvs.LoadState(state)
view = pvs.GetActiveViewOrCreate("RenderView")
view.ViewSize = [SIZE, SIZE]
casters = [r.GetProperty("ShadowCaster") for r in view.Representations
           if r.GetProperty("ShadowCaster") is not None and r.GetProperty("ShadowCaster").GetData()]
restored = capture("pv-shadow-state.png")
r_state = ratio(restored, unshadowed)
print("state reloaded: %d display(s) with a Shadow Caster, %.4f left in the shadow"
      % (len(casters), r_state))
check(len(casters) == 1 and abs(r_state - r_pv) <= 0.005,
      "the saved state brings the Shadow Caster and its shadow back (%.4f)" % r_state)

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
