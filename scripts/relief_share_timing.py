# SPDX-License-Identifier: BSD-3-Clause
"""The Relief Surface lit by a Virtual Light Field whose visible-share map the pvbatch benchmarks
time (bench-relief-share-mpi.py, bench-paraview-threads.py): one scene, one way to time it."""


def relief_on_back_wall(pvs, field, side=256, silhouettes=True):
    """A view of `field` (the Cornell box's) with a Relief Surface of side x side procedural
    bricks (depth scale 0.05) on a 380 mm patch in front of the box's back wall, lit by the
    field; rendered once (the field, the probes and the first map). Without silhouettes the
    relief is walled at its border (side walls down to the depth there, whose shares the map
    holds too). Returns (view, relief)."""
    view = pvs.CreateRenderView()
    view.ViewSize = [200, 200]
    pvs.Show(field, view)
    patch = pvs.Plane(Origin=[90.0, 90.0, 558.0], Point1=[90.0, 470.0, 558.0],
                      Point2=[470.0, 90.0, 558.0], XResolution=4, YResolution=4)
    depth = pvs.MesolightProceduralRelief(Pattern=0, Resolution=[side, side])
    texture = pvs.MesolightReliefTexture(Input=pvs.OutputPort(depth, 0), DepthScale=0.05)
    attached = pvs.MesolightAttachReliefTexture(Input=patch, ReliefTexture=texture)
    relief = pvs.Show(attached, view)
    relief.SetRepresentationType("Relief Surface")
    relief.Silhouettes = 1 if silhouettes else 0
    relief.OverrideDepthScale = 1
    relief.ReliefDepthScale = 0.05
    relief.LightField = field
    pvs.Render(view)
    return view, relief


def visible_share_maps(pvs, view, relief, repeats):
    """`repeats` visible-share maps, each after a depth scale change (which recomputes the map and
    keeps the probes), as the representation times them: a list of (seconds, processor seconds of
    the first rank's process, ranks the map was split over)."""
    maps = []
    for run in range(repeats):
        relief.ReliefDepthScale = 0.1 if run % 2 == 0 else 0.07
        pvs.Render(view)  # the map alone
        relief.UpdatePropertyInformation()
        maps.append(tuple(relief.GetPropertyValue(name) for name in (
            "LightFieldVisibleShareSeconds", "LightFieldVisibleShareCpuSeconds",
            "LightFieldVisibleShareRanks")))
    return maps
