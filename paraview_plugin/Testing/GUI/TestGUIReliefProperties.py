# SPDX-License-Identifier: BSD-3-Clause
"""GUI: every property of the Relief Surface representation (listed from MesolightRelief.xml, so
a new property without a case here fails) must change the image in the GUI's view. Scene: the
README pipeline with a light set, a sphere poking through the relief (for Write Depth), an
oblique camera (silhouettes, grazing rays). Each case sets its preconditions on both frames,
then one property to a non-default value; fewer than MIN_CHANGED_PIXELS pixels differing by
more than 2 levels fails: a property that changes nothing is a broken property."""
import os
import sys
import xml.etree.ElementTree as ET

# run-gui-test.sh puts this directory on PYTHONPATH (paraview --script defines no __file__).
import mesolight_guitest as g  # noqa: E402
import numpy as np  # noqa: E402
import paraview.simple as pvs  # noqa: E402

MIN_CHANGED_PIXELS = 50
RELIEF = "Relief (linear + binary)"

# property: (preconditions on the display or, with a "source." prefix, the depth source;
#            the change)
CASES = {
    "ReliefMethod": ({}, {"ReliefMethod": "Texture mapping"}),
    # The steps of the relief search (the default, maximum mipmap, has no refinement steps).
    "LinearSteps": ({"ReliefMethod": RELIEF, "RefinementSteps": 0}, {"LinearSteps": 3}),
    "RefinementSteps": ({"ReliefMethod": RELIEF, "LinearSteps": 4}, {"RefinementSteps": 0}),
    "AdaptiveSteps": ({"ReliefMethod": RELIEF, "RefinementSteps": 0, "LinearSteps": 32,
                       "MinimumSteps": 2}, {"AdaptiveSteps": 1}),
    "MinimumSteps": ({"ReliefMethod": RELIEF, "RefinementSteps": 0, "LinearSteps": 32,
                      "AdaptiveSteps": 1}, {"MinimumSteps": 1}),
    "OverrideDepthScale": ({"ReliefDepthScale": 0.15}, {"OverrideDepthScale": 1}),
    "ReliefDepthScale": ({"OverrideDepthScale": 1}, {"ReliefDepthScale": 0.15}),
    "SelfShadowing": ({}, {"SelfShadowing": 0}),
    "Silhouettes": ({}, {"Silhouettes": 0}),
    "WriteDepth": ({}, {"WriteDepth": 0}),
    # Rays that leave the texture at its edges: a pattern deep at the border (Stone), deep, and
    # no silhouettes, so that they go on into the wrapped texture rather than end at the edge.
    "RepeatTexture": ({"source.Pattern": "Stone", "OverrideDepthScale": 1,
                       "ReliefDepthScale": 0.3, "Silhouettes": 0}, {"RepeatTexture": 1}),
    # A 1024^2 stone texture over a few hundred pixels: minified, so mip levels matter (level
    # of detail is on by default).
    "LevelOfDetail": ({"source.Pattern": "Stone", "source.Resolution": [1024, 1024]},
                      {"LevelOfDetail": 0}),
    # The same minified stone: the filter of the footprint's normal, and the rays of a far pixel.
    "NormalFilter": ({"source.Pattern": "Stone", "source.Resolution": [1024, 1024]},
                     {"NormalFilter": "Mean normal"}),
    "FarViewRays": ({"source.Pattern": "Stone", "source.Resolution": [1024, 1024]},
                    {"FarViewRays": 1}),
    "Exposure": ({}, {"Exposure": 0.5}),
    "ToneMapping": ({}, {"ToneMapping": 0}),
    # Median cut gives lights of about equal energy: only a threshold near 1 skips some.
    "LightSetThreshold": ({}, {"LightSetThreshold": 0.99}),
    "ShadowedLights": ({}, {"ShadowedLights": 1}),
}

# Properties that need a light field in the scene, checked by the tests named instead.
CHECKED_ELSEWHERE = {
    "LightField": "TestGUIReliefInLightField.py (set from the panel, the relief matches the wall)",
    "ReliefLightFieldAutoExposure": "Python/TestReliefInLightField.py (off, the relief misses "
                                    "the wall it matches when on)",
    "ReliefLightFieldSceneDisplay": "Python/TestReliefInLightField.py (off, with the scene at "
                                    "exposure 2 the relief misses the wall it matches when on)",
    "ReliefLightFieldAlbedo": "Python/TestReliefInLightField.py (off, the white relief misses "
                              "the wall it matches when on)",
    "ReliefLightFieldOcclusion": "Python/TestReliefFieldOcclusion.py (off, the relief misses the "
                                 "CPU reference it matches when on)",
    # The README pipeline's surface is flat, where the checkbox rightly changes nothing.
    "SurfaceCurvature": "Python/TestReliefSurfaceCurvature.py (off, a relief on a sphere "
                        "changes; on a flat square nothing)",
}


def representation_properties():
    xml_dir = os.environ["MESOLIGHT_PLUGIN_XML_DIR"]
    root = ET.parse(os.path.join(xml_dir, "MesolightRelief.xml")).getroot()
    proxy = root.find(".//ReliefSurfaceRepresentationProxy"
                      "[@name='MesolightReliefSurfaceRepresentation']")
    # LightSetAttached (panel_visibility never) is set from the data, not by the user.
    return [e.get("name") for e in proxy if e.get("name") and e.tag.endswith("Property")
            and e.get("panel_visibility") != "never"]


def main():
    failures = []
    view = g.gui_view()
    p = g.readme_pipeline(view, lights=True)
    sphere = pvs.Sphere(Center=[0.1, 0.0, 0.0], Radius=0.12)
    g.apply(sphere, view)
    display = pvs.GetDisplayProperties(p["attached"], view)
    view.CameraPosition = [0.0, -1.2, 0.75]
    view.CameraFocalPoint = [0.0, 0.05, -0.05]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraParallelProjection = 0
    view.InteractionMode = "3D"

    names = representation_properties()
    print("Relief Surface properties (MesolightRelief.xml): %s" % ", ".join(names))
    for name in names:
        if name in CHECKED_ELSEWHERE:
            print("%-18s checked by %s" % (name, CHECKED_ELSEWHERE[name]))
            continue
        if name not in CASES:
            failures.append("%s: no case in this test (every property must be checked)" % name)
            continue
        pre, change = CASES[name]
        saved = {}
        for key, value in list(pre.items()) + list(change.items()):
            target, prop = (p["depth"], key[7:]) if key.startswith("source.") else (display, key)
            value = target.GetPropertyValue(prop)  # the live property: keep a copy
            value = value.GetData() if hasattr(value, "GetData") else value
            saved.setdefault((id(target), prop), (target, prop, value))
        for key, value in pre.items():
            target, prop = (p["depth"], key[7:]) if key.startswith("source.") else (display, key)
            setattr(target, prop, value)
        before = g.grab(view, "gui-property-%s-before.png" % name)
        for key, value in change.items():
            setattr(display, key, value)
        after = g.grab(view, "gui-property-%s-after.png" % name)
        changed = int(np.any(np.abs(after - before) > 2, axis=2).sum())
        mean = float(np.abs(after - before).mean())
        print("%-18s %s -> %s: %d pixels changed, mean difference %.3f levels"
              % (name, pre or "", change, changed, mean))
        if changed < MIN_CHANGED_PIXELS:
            failures.append("%s: changes %d pixels (at least %d expected)"
                            % (name, changed, MIN_CHANGED_PIXELS))
        for target, prop, value in saved.values():
            setattr(target, prop, value)
    return failures


g.run(main)
