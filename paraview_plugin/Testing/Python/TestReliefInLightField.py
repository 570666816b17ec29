# SPDX-License-Identifier: BSD-3-Clause
"""A Relief Surface lit by a Virtual Light Field (the representation's Light Field input) on the
Cornell box's back wall, beside the scene drawn as Light Field.

Reference (independent of the probes and the emitter lights): the field's own radiance leaving
the back wall, as the Light Field representation draws it (the propagated texture, exposed,
tone-mapped, sRGB). A flat relief (depth scale 0) on a patch in front of that wall, lit by the
field, is shaded from other data entirely: SH9 probes of the field's incident light gathered
over the patch plus the emitters as lights, Kd x E / pi, through the same display transform, with
Solid Color left white: the relief takes the wall's Kd (Light Field Albedo, on by default).
Where the patch covers the wall the two images must agree (the wall and the relief look
continuous). Must fail: the same relief lit by the view's lights (Light Field unset), and lit
by the field without its automatic exposure, and with Light Field Albedo off (Solid Color white). A relief with depth lit by the field must differ
from the flat one (it is drawn as a relief) and stay near it on average (same light); though
its depth lies behind the wall the patch stands 1.2 mm in front of, the wall hides none of it
(it shows as it does with the scene hidden) while the boxes in front still hide it.

Also: the probes are gathered once per field or surface (renders and camera moves gather none,
a new propagation gathers again); bad input (a Light Field that is not a field) is an error
through VTK, the relief is then drawn the ordinary way, no crash. Runs on one or two MPI ranks.

The relief with depth's visible-share map (Light Field Occlusion, on by default): on one rank
--write-map FILE.npz writes it; on two --compare-map FILE.npz checks that its rows were split
over the ranks and that the combined map equals the one-rank map, and that the map with the
second rank's rows left 0 does not (mesolight_pvtest.check_share_map).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow  # noqa: E402

SIZE = 300
BACK_Z = 559.2     # the published box's back wall (millimetres, facing -z)
PATCH_Z = 558.0    # the patch 1.2 mm in front of it (within the wall's plane tolerance)
MAX_MEAN_ERROR = 6.0  # 8-bit levels, relief vs the wall's own radiance over the patch

args, failures, check, ranks = t.start_share_map_test()
out = t.output_dir()

box = pvs.MesolightCornellBox()
# The final gather on (the default): a gathered wall is smooth, so a relief the wall hides shows
# nothing of its depth against the flat one (the measure below fails then).
field = pvs.MesolightVirtualLightField(Input=box, Directions=513, RaysPerSide=32, Iterations=4)

view = t.make_cornell_view(SIZE)


def capture(name):
    return t.cornell_capture(view, os.path.join(out, name))


scene = pvs.Show(field, view)
check(scene.Representation == "Light Field", "the scene is shown as Light Field")
wall = capture("pv-relief-field-wall.png")

# The back wall's Kd, from the box's cell data: the albedo a relief mounted on it takes by
# default (Light Field Albedo), and the Solid Color that gives the same image with that off.
data = servermanager.Fetch(box)
points = vtk_to_numpy(data.GetPoints().GetData())
diffuse = vtk_to_numpy(data.GetCellData().GetArray("Diffuse"))
kd = None
for c in range(data.GetNumberOfCells()):
    ids = data.GetCell(c).GetPointIds()
    if all(points[ids.GetId(k)][2] > BACK_Z - 1.0 for k in range(ids.GetNumberOfIds())):
        kd = [float(v) for v in diffuse[c]]
        break
print("back wall Kd: %s" % kd)

# The patch: normal -z (towards the camera), texture coordinates from the Plane source.
patch = pvs.Plane(Origin=[90.0, 90.0, PATCH_Z], Point1=[90.0, 470.0, PATCH_Z],
                  Point2=[470.0, 90.0, PATCH_Z], XResolution=4, YResolution=4)
attached, relief = t.show_relief(patch, t.relief_texture(128), view, OverrideDepthScale=1,
                                 ReliefDepthScale=0.0)
# Solid Color stays ParaView's default (white): a user who adds a relief to a wall sets nothing.
relief.Ambient, relief.Diffuse = 0.0, 1.0

# The patch's footprint, shrunk by 3 pixels (edges are not compared).
scene.Visibility = 0
relief.SetRepresentationType("Surface")
relief.AmbientColor = relief.DiffuseColor = [1.0, 1.0, 1.0]
relief.Ambient, relief.Diffuse = 1.0, 0.0
footprint = t.eroded(capture("pv-relief-field-footprint.png").max(axis=2) > 128, 3)
print("patch footprint: %d pixels" % int(footprint.sum()))
check(footprint.sum() > SIZE * SIZE // 8, "the patch covers much of the view")
scene.Visibility = 1
relief.SetRepresentationType("Relief Surface")
relief.AmbientColor = relief.DiffuseColor = [1.0, 1.0, 1.0]
relief.Ambient, relief.Diffuse = 0.0, 1.0


def error(image, label):
    e = float(np.abs(image[footprint].astype(float) - wall[footprint]).mean())
    print("%s: mean |relief - wall| %.2f levels over the patch (wall mean %.1f, relief mean %.1f)"
          % (label, e, float(wall[footprint].mean()), float(image[footprint].mean())))
    return e


def gatherings():
    relief.UpdatePropertyInformation()
    return relief.GetPropertyValue("LightFieldProbeGatherings")


# --- negative: the view's lights (Light Field unset) ------------------------------------------
kit = capture("pv-relief-field-view-lights.png")
check(error(kit, "negative: view's lights") > MAX_MEAN_ERROR,
      "negative: the relief lit by the view's lights does not match the wall")
check(gatherings() == 0, "no probes gathered without a Light Field")

# --- the relief lit by the field -------------------------------------------------------------
relief.LightField = field
flat = capture("pv-relief-field-flat.png")
check(error(flat, "flat relief lit by the field") <= MAX_MEAN_ERROR,
      "a flat relief lit by the field matches the wall's own radiance (<= %g levels)"
      % MAX_MEAN_ERROR)
first = gatherings()
check(first == 1, "the probes were gathered once (%d)" % first)

# The albedo came from the wall (Light Field Albedo, on by default), not from Solid Color (white):
# off, the white relief must fail; off with Solid Color set to the wall's Kd by hand, it matches.
relief.ReliefLightFieldAlbedo = 0
white = capture("pv-relief-field-white.png")
check(error(white, "negative: Light Field Albedo off, Solid Color white") > MAX_MEAN_ERROR,
      "negative: the relief with the default Solid Color (white) does not match the wall")
relief.DiffuseColor = kd
by_hand = capture("pv-relief-field-solid-color-kd.png")
check(error(by_hand, "Light Field Albedo off, Solid Color = the wall's Kd") <= MAX_MEAN_ERROR,
      "Solid Color set to the wall's Kd by hand matches as the default does")
relief.DiffuseColor = [1.0, 1.0, 1.0]
relief.ReliefLightFieldAlbedo = 1
check(float(np.abs(capture("pv-relief-field-flat-again.png")[footprint].astype(float) -
                   flat[footprint]).mean()) < 0.5,
      "Light Field Albedo on again: the wall's Kd again")
check(gatherings() == first, "the albedo gathers no probes (%d)" % gatherings())

# The scene's display changed (exposure 2, clamp), nothing else: the relief follows it (Light
# Field Display From Scene, on by default) and still matches the wall drawn at that display; off,
# the relief keeps its own and must not match. A first-time user saw a 26.8-level seam here.
scene.LightFieldExposure, scene.LightFieldToneMapping = 2.0, 0
relief.Visibility = 0
wall_bright = capture("pv-relief-field-wall-exposure2.png")
relief.Visibility = 1
followed = capture("pv-relief-field-exposure2.png")


def error_against(image, reference, label):
    e = float(np.abs(image[footprint].astype(float) - reference[footprint]).mean())
    print("%s: mean |relief - wall| %.2f levels over the patch" % (label, e))
    return e


check(error_against(followed, wall_bright, "scene exposure 2, clamp") <= MAX_MEAN_ERROR,
      "the relief follows the scene display's exposure and tone mapping")
check(relief.Exposure == 2.0 and relief.ToneMapping == 0,
      "the relief's Exposure and Tone Mapping show the scene's")
relief.ReliefLightFieldSceneDisplay = 0
relief.Exposure, relief.ToneMapping = 1.0, 1
own = capture("pv-relief-field-exposure2-own.png")
check(error_against(own, wall_bright, "negative: the relief's own display") > MAX_MEAN_ERROR,
      "negative: the relief's own display misses the scene at exposure 2")
relief.ReliefLightFieldSceneDisplay = 1
scene.LightFieldExposure, scene.LightFieldToneMapping = 1.0, 1
again = capture("pv-relief-field-display-back.png")
check(float(np.abs(again[footprint].astype(float) - flat[footprint]).mean()) < 0.5,
      "the scene's display back: the relief back to its first image")

# Renders, camera moves and display settings gather nothing.
view.CameraPosition = [300.0, 250.0, -700.0]
pvs.Render(view)
relief.LinearSteps = 12
capture("pv-relief-field-again.png")
check(gatherings() == first, "renders and settings gather no probes (%d)" % gatherings())

# --- negative: without the field's automatic exposure ---------------------------------------
# (the relief's own setting: not the scene display's)
relief.ReliefLightFieldSceneDisplay = 0
relief.ReliefLightFieldAutoExposure = 0
dim = capture("pv-relief-field-no-auto-exposure.png")
check(error(dim, "negative: no automatic exposure") > MAX_MEAN_ERROR,
      "negative: the relief without the field's automatic exposure does not match")
relief.ReliefLightFieldAutoExposure = 1
relief.ReliefLightFieldSceneDisplay = 1

# --- a relief with depth: drawn as a relief, lit alike on average ----------------------------
# Its depth (0.1 x 380 mm = 38 mm) lies far behind the back wall, 1.2 mm behind the patch: the
# relief mounted on the wall must replace the wall (its written depth goes no deeper than halfway
# to the wall), not be hidden by it. Before that rule the relief with depth drew exactly the
# wall: 0% of the patch's pixels changed by > 8 levels on this gathered field (6.4% on an
# ungathered one, whose wall is blotchier than the flat relief: the wall's own noise).
relief.ReliefDepthScale = 0.1
deep = capture("pv-relief-field-deep.png")
t.check_share_map(check, relief, ranks, args.write_map, args.compare_map)
changed = float((np.abs(deep[footprint] - flat[footprint]).max(axis=1) > 8).mean())
mean_shift = abs(float(deep[footprint].mean()) - float(flat[footprint].mean()))
print("relief with depth: %.1f%% of the patch's pixels differ from the flat one by > 8 levels; "
      "mean level shift %.1f" % (100.0 * changed, mean_shift))
check(changed > 0.10 and mean_shift < 20.0,
      "a relief with depth shows its relief, lit like the flat one on average")
check(gatherings() == first, "a relief setting gathers no probes")

# The wall hides no part of it, the boxes in front still do. Reference: the same reliefs with
# the scene hidden (nothing to hide them). Where the flat relief shows as it does alone, the
# patch is in front of everything but the wall: there the relief with depth must show as it does
# alone; where the flat one does not (the boxes in front), the relief with depth must not either.
scene.Visibility = 0
deep_alone = capture("pv-relief-field-deep-alone.png")
relief.ReliefDepthScale = 0.0
flat_alone = capture("pv-relief-field-flat-alone.png")
relief.ReliefDepthScale = 0.1
scene.Visibility = 1
open_patch = footprint & (np.abs(flat.astype(float) - flat_alone).max(axis=2) <= 2)
boxed = footprint & (np.abs(flat.astype(float) - flat_alone).max(axis=2) > 30)
hidden = float((np.abs(deep[open_patch].astype(float) - deep_alone[open_patch]).max(axis=1) >
                8).mean())
through = float((np.abs(deep[boxed].astype(float) - flat[boxed]).max(axis=1) > 8).mean())
print("relief with depth in front of the wall: %.2f%% of %d open patch pixels differ from the "
      "relief alone by > 8 levels; %.2f%% of %d pixels behind the boxes differ from the boxes"
      % (100.0 * hidden, int(open_patch.sum()), 100.0 * through, int(boxed.sum())))
check(open_patch.sum() > SIZE * SIZE // 16 and boxed.sum() > SIZE * SIZE // 32,
      "the patch is partly open, partly behind the boxes")
check(hidden < 0.005, "the wall the relief is mounted on hides none of it")
check(through < 0.005, "the boxes in front of the relief still hide it")

# --- a new propagation gathers again ---------------------------------------------------------
field.Iterations = 5
capture("pv-relief-field-five-iterations.png")
check(gatherings() == first + 1, "a new field gathers the probes again (%d)" % gatherings())

# --- unset: the view's lights again ------------------------------------------------------------
relief.LightField = None
relief.ReliefDepthScale = 0.0
back = capture("pv-relief-field-unset.png")
check(float(np.abs(back[footprint] - kit[footprint]).mean()) < 1.0,
      "unsetting the Light Field gives the view's lighting back")

# --- bad input: a Light Field that is no field ------------------------------------------------
messages = []


window = vtkOutputWindow.GetInstance()
tag = window.AddObserver(vtkCommand.ErrorEvent,
                         lambda caller, event: messages.append("error"))
relief.LightField = box
bad = capture("pv-relief-field-bad-input.png")
first_bad = len(messages)
# Another wrong choice (the patch itself) is said again: each choice is the user's, and the
# first message may have scrolled away (before, neither this one nor the one after unsetting a
# field was said: only a change of the field's producer counted).
relief.LightField = patch
capture("pv-relief-field-bad-input-again.png")
window.RemoveObserver(tag)
print("bad input: %d error(s) reported for the box, %d more for the patch"
      % (first_bad, len(messages) - first_bad))
check(first_bad > 0, "a Light Field that is no field is an error")
check(len(messages) > first_bad, "a second wrong Light Field is an error again")
check(float(np.abs(bad[footprint] - kit[footprint]).mean()) < 1.0,
      "a Light Field that is no field: the relief is drawn the ordinary way")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
