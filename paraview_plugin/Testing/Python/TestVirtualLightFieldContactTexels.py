# SPDX-License-Identifier: BSD-3-Clause
"""ContactTexelHalvings of Mesolight Virtual Light Field (vtkVirtualLightField, docs/vlf.md
"Finer texels where surfaces meet") through the plugin's proxy, on the Cornell box (513
directions, 32 x 32 rays, no iterations and no gather: only the texels matter here):

- the property exists, advanced, default -1 (automatic, the command line's `auto`);
- each halving refines the floor the two blocks stand on (four times its texels): the radiance
  atlas the output carries (LightFieldAtlasSize, texels plus gutters and packing) grows by more
  than a fifth per halving (measured: 4662, 6120, 10600 pixels at 0, 1, 2);
- -1 with given rays and no gather is no halving (the automatic rule): the atlas of 0;
- negative: 4 (outside 0-3) is refused with an error, the output is empty;
- AdaptiveTexels (texels refined from the light, AdaptiveTexels.h) exists, advanced, default off;
  with given rays it leaves the texels alone (the atlas of 0 with AdaptiveTexels on and off).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402

t.load_plugin()
failures = []
check = t.checker(failures)

box = pvs.MesolightCornellBox()
field = pvs.MesolightVirtualLightField(Input=box, Directions=513, RaysPerSide=32, Iterations=0,
                                       FinalGather=0)
prop = field.SMProxy.GetProperty("ContactTexelHalvings")
check(prop is not None, "the filter has a ContactTexelHalvings property")
check(field.ContactTexelHalvings == -1, "ContactTexelHalvings defaults to -1 (automatic), got %s"
      % field.ContactTexelHalvings)
check(prop.GetPanelVisibility() == "advanced", "ContactTexelHalvings is an advanced property")


def atlas_pixels(halvings):
    """Cells of the output and pixels of its radiance atlas with ContactTexelHalvings."""
    field.ContactTexelHalvings = halvings
    field.UpdatePipeline()
    data = servermanager.Fetch(field)
    size = data.GetFieldData().GetArray("LightFieldAtlasSize")
    pixels = int(size.GetValue(0)) * int(size.GetValue(1)) if size else 0
    print("ContactTexelHalvings %2d: %d cells, atlas %s pixels"
          % (halvings, data.GetNumberOfCells(),
             "%d x %d = %d" % (size.GetValue(0), size.GetValue(1), pixels) if size else "no"))
    return data.GetNumberOfCells(), pixels


cells0, uniform = atlas_pixels(0)
_, once = atlas_pixels(1)
_, twice = atlas_pixels(2)
check(cells0 > 0 and uniform > 0, "the uniform field has an output and an atlas")
check(once > 1.2 * uniform, "one halving: atlas %d > 1.2 x %d" % (once, uniform))
check(twice > 1.2 * once, "two halvings: atlas %d > 1.2 x %d" % (twice, once))
_, automatic = atlas_pixels(-1)
check(automatic == uniform,
      "-1 with given rays and no gather: no halving (atlas %d, uniform %d)" % (automatic, uniform))
cells_bad, _ = atlas_pixels(4)
check(cells_bad == 0, "negative: ContactTexelHalvings 4 gives an empty output (and an error)")

adaptive = field.SMProxy.GetProperty("AdaptiveTexels")
check(adaptive is not None, "the filter has an AdaptiveTexels property")
check(field.AdaptiveTexels == 0, "AdaptiveTexels defaults to off, got %s" % field.AdaptiveTexels)
check(adaptive.GetPanelVisibility() == "advanced", "AdaptiveTexels is an advanced property")
field.AdaptiveTexels = 1
_, on = atlas_pixels(0)
check(on == uniform, "AdaptiveTexels on with given rays: atlas %d, uniform %d" % (on, uniform))

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
