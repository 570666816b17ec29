# SPDX-License-Identifier: BSD-3-Clause
"""The Light Field representation: Mesolight Cornell Box -> Mesolight Virtual Light Field, shown
the way Apply shows it (no representation chosen by the script), against an independent
reference of the same field and camera: `mesolight vlf render` (the main build's CPU renderer:
one Embree ray per pixel, the field's total diffuse texture at the hit, exposure, clamp, sRGB).

- Apply gives the "Light Field" representation (the filter's RepresentationType hint);
- the default (automatic exposure k = 0.18 / log-average luminance of the atlas texels,
  computed here in numpy from the output's field data; Reinhard) matches `vlf render --exposure
  k` decoded and Reinhard tone-mapped in numpy (where that saturates, `--exposure k/64` decoded
  and scaled by 64), and is neither a dark box nor saturated;
- Clamp tone mapping at exposure 4, automatic exposure off, matches `vlf render --exposure 4`;
- must fail: the old way (Surface coloured by cell Radiance, Map Scalars off: linear values, no
  tone mapping, one colour per triangle), colouring by a wrong array (cell Diffuse), the Light
  Field representation at twice the exposure, and Reinhard without the automatic exposure
  (exposure 1: the dark box, mean level 54).

Pixels compared: covered in both images and away from edges (the reference's 3 x 3
neighbourhood spans at most 16 levels), since a rasteriser and a ray caster disagree on which
surface an edge pixel shows.
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

SIZE = 300
MAX_MEAN_ERROR = 2.0  # 8-bit levels over the compared pixels

t.load_plugin()
failures = []
check = t.checker(failures)

out = t.output_dir()
snapshot = os.path.join(out, "pv-light-field.vlf")
if os.path.exists(snapshot):
    os.remove(snapshot)  # ours from an earlier run: start over
box = pvs.MesolightCornellBox()
field = pvs.MesolightVirtualLightField(Input=box, Directions=513, RaysPerSide=32, Iterations=4,
                                       SnapshotFileName=snapshot)

view = t.make_cornell_view(SIZE)  # black: the reference's misses are black

display = pvs.Show(field, view)  # what Apply does
print("representation on Apply: %s" % display.Representation)
check(display.Representation == "Light Field", "Apply shows the Light Field representation")
print("colour array on Apply: %s" % display.ColorArrayName)
check(not display.ColorArrayName[1], "Apply colours by no array (no colour map, no legend)")


def capture(name):
    return t.cornell_capture(view, os.path.join(out, name))


def reference(exposure):
    tool = os.environ.get("MESOLIGHT_TOOL", "")
    path = os.path.join(out, "pv-light-field-reference-%g.png" % exposure)
    command = [tool, "vlf", "render", snapshot, "--out", path, "--force",
               "--size", "%dx%d" % (SIZE, SIZE), "--view-angle", str(t.CORNELL_VIEW_ANGLE),
               "--camera", ",".join(str(v) for v in t.CORNELL_EYE + t.CORNELL_FOCAL),
               "--exposure", str(exposure)]
    print(" ".join(command))
    subprocess.run(command, check=True)
    return t.capture_file(path)


def compared_pixels(ref, extra=None):
    padded = np.pad(ref, ((1, 1), (1, 1), (0, 0)), mode="edge")
    shifts = [padded[1 + dy:1 + dy + SIZE, 1 + dx:1 + dx + SIZE]
              for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
    spread = (np.max(shifts, axis=0) - np.min(shifts, axis=0)).max(axis=2)
    mask = (spread <= 16) & (ref.max(axis=2) > 0)
    return mask if extra is None else mask & extra


def mean_error(image, ref, mask):
    covered = mask & (image.max(axis=2) > 0)
    missing = 100.0 * float((mask & ~covered).sum()) / max(1, int(mask.sum()))
    error = float(np.abs(image[mask].astype(float) - ref[mask]).mean())
    return error, missing


def matches(label, image, ref, mask):
    error, missing = mean_error(image, ref, mask)
    print("%s: mean error %.2f levels over %d pixels (%.1f%% of them background here)"
          % (label, error, int(mask.sum()), missing))
    return error <= MAX_MEAN_ERROR and missing < 1.0


# --- default display: automatic exposure, Reinhard --------------------------------------------
data = servermanager.Fetch(field)
atlas = vtk_to_numpy(data.GetFieldData().GetArray("LightFieldAtlas")).astype(np.float64)
luminance = atlas[:, :3] @ np.array([0.2126, 0.7152, 0.0722])
key = 0.18 / np.exp(np.log(luminance[luminance > 0]).mean())
print("atlas %s x %s texels; automatic exposure 0.18 / log-average luminance = %.4f"
      % tuple(vtk_to_numpy(data.GetFieldData().GetArray("LightFieldAtlasSize")).tolist() + [key]))
default = capture("pv-light-field-default.png")
ref_k, ref_dim = reference(key), reference(key / 64.0)
linear = np.where(ref_k < 255, t.srgb_decode(ref_k.astype(float)),
                  64.0 * t.srgb_decode(ref_dim.astype(float)))
reinhard = np.rint(t.srgb_encode(linear / (1.0 + linear)))
mask = compared_pixels(reinhard, ref_dim.max(axis=2) < 255)
check(matches("default (automatic exposure, Reinhard) vs reference", default, reinhard, mask),
      "the default display matches the CPU reference, Reinhard tone-mapped (<= %g levels)"
      % MAX_MEAN_ERROR)


def dark_or_saturated(image, label):
    covered = image.max(axis=2) > 0
    level = float(image[covered].mean())
    saturated = 100.0 * float((image[covered] >= 254).any(axis=1).mean())
    print("%s: mean level %.1f, %.2f%% of covered pixels have a saturated channel"
          % (label, level, saturated))
    return not (80 <= level <= 200 and saturated < 5.0)


check(not dark_or_saturated(default, "default"),
      "the default display is neither a dark box nor saturated")
state = os.path.join(out, "pv-light-field.pvsm")
pvs.SaveState(state)

# --- clamp at exposure 4 against vlf render --exposure 4 -------------------------------------
display.LightFieldAutoExposure = 0
display.LightFieldToneMapping = "Clamp"
display.LightFieldExposure = 4.0
clamp4 = capture("pv-light-field-clamp4.png")
ref4 = reference(4.0)
mask4 = compared_pixels(ref4)
check(matches("clamp, exposure 4 vs reference", clamp4, ref4, mask4),
      "clamp at exposure 4 matches `mesolight vlf render --exposure 4`")

# --- negative tests ----------------------------------------------------------------------------
display.LightFieldExposure = 8.0
doubled = capture("pv-light-field-clamp8.png")
check(not matches("negative: exposure 8 vs the exposure-4 reference", doubled, ref4, mask4),
      "negative: twice the exposure fails")

display.LightFieldToneMapping = "Reinhard"
display.LightFieldExposure = 1.0
fixed = capture("pv-light-field-exposure1.png")
check(not matches("negative: Reinhard at exposure 1 without automatic exposure", fixed, reinhard,
                  mask) and dark_or_saturated(fixed, "exposure 1 without automatic exposure"),
      "negative: Reinhard without the automatic exposure fails (a dark box)")
display.SetRepresentationType("Surface")
pvs.ColorBy(display, ("CELLS", "Radiance"))
display.MapScalars = 0
display.Ambient, display.Diffuse = 1.0, 0.0
old = capture("pv-light-field-old-way.png")
check(not matches("negative: Surface coloured by cell Radiance (Map Scalars off)",
                  old, reinhard, mask),
      "negative: the old way (linear Radiance as colours) fails")
pvs.ColorBy(display, ("CELLS", "Diffuse"))
display.MapScalars = 0
wrong = capture("pv-light-field-wrong-array.png")
check(not matches("negative: Surface coloured by cell Diffuse", wrong, reinhard, mask),
      "negative: colouring by a wrong array fails")

# --- a state file brings the display back (the atlas travels with the data) -----------------
pvs.ResetSession()  # the plugin stays loaded in this process (loading it again is an error)
pvs.LoadState(state)
view = pvs.GetActiveViewOrCreate("RenderView")
view.ViewSize = [SIZE, SIZE]
types = sorted(r.GetProperty("Representation").GetData() for r in view.Representations
               if r.GetProperty("Visibility") and r.Visibility)
print("after loading the state: visible representations %s" % types)
restored = capture("pv-light-field-state.png")
same = matches("state file vs reference", restored, reinhard, mask)
check(types == ["Light Field"] and same,
      "the saved state shows the Light Field display again")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
