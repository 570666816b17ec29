# SPDX-License-Identifier: BSD-3-Clause
"""GUI: the errors a GUI user meets name what to do in ParaView (the Output Messages window shows
them), not only C++ classes. Cases: a cone method without a cone map, a surface without
texture coordinates (a Sphere), and a map twice as wide as tall attached to Sources > Plane
(square: the relief drawn twice too tall), whose warning names Mesolight Relief Plane; the same
map on a Relief Plane gives no such warning. The messages are caught by a vtkStringOutputWindow
put in place of the GUI's output window for the duration of each render."""
import mesolight_guitest as g
import paraview.simple as pvs
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

CASES = [
    # (what, must contain, must not be the only advice)
    ("cone method without a cone map", "apply Mesolight Cone Map to the depth image",
     "vtkConeMapFilter"),
    ("surface without texture coordinates", "apply Texture Map to Plane", "vtkTextureMapToPlane"),
    ("map twice as wide as tall on Sources > Plane", "Filters > Mesolight > Mesolight Relief Plane",
     "vtkReliefPlaneFilter"),
]


def messages_of(render):
    previous = vtkOutputWindow.GetInstance()
    previous.Register(None)
    window = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(window)
    try:
        render()
    finally:
        vtkOutputWindow.SetInstance(previous)
        previous.UnRegister(None)
    return window.GetOutput()


def main():
    failures = []
    view = g.gui_view()
    p = g.readme_pipeline(view)
    display = pvs.GetDisplayProperties(p["attached"], view)

    def cone_method():
        display.ReliefMethod = "Relaxed cone + binary"
        pvs.Render(view)
        display.ReliefMethod = "Relief (linear + binary)"

    def no_tcoords():
        sphere = pvs.Sphere()
        attached = pvs.MesolightAttachReliefTexture(Input=sphere, ReliefTexture=p["relief"])
        g.apply(attached, view)
        pvs.Render(view)
        pvs.Hide(attached, view)  # its error would repeat in the cases after it

    wide = {}

    def wide_map_on_square_plane():
        depth = pvs.MesolightProceduralRelief(Resolution=[256, 128])
        g.apply(depth, view)
        wide["relief"] = pvs.MesolightReliefTexture(Input=pvs.OutputPort(depth, 0))
        g.apply(wide["relief"], view)
        plane = pvs.Plane()
        g.apply(plane, view)
        attached = pvs.MesolightAttachReliefTexture(Input=plane, ReliefTexture=wide["relief"])
        g.apply(attached, view)
        pvs.Render(view)

    for (what, advice, cxx), render in zip(
            CASES, (cone_method, no_tcoords, wide_map_on_square_plane)):
        text = messages_of(render)
        print("%s -> %r" % (what, text.strip()))
        if advice.lower() not in text.lower():
            failures.append("%s: the message should say %r: %r" % (what, advice, text))
        if cxx in text and text.lower().find(advice.lower()) > text.find(cxx):
            failures.append("%s: the C++ class comes before the GUI advice" % what)
        if what.startswith("map twice") and "2 times too tall" not in text:
            failures.append("%s: the warning should say how stretched: %r" % (what, text))

    def wide_map_on_relief_plane():
        plane = pvs.MesolightReliefPlane(Input=wide["relief"])
        g.apply(plane, view)
        attached = pvs.MesolightAttachReliefTexture(Input=plane, ReliefTexture=wide["relief"])
        g.apply(attached, view)
        pvs.Render(view)

    text = messages_of(wide_map_on_relief_plane)
    print("the same map on a Relief Plane -> %r" % text.strip())
    if "too tall" in text or "too wide" in text:
        failures.append("a map on its own Relief Plane is not stretched: %r" % text)
    return failures


g.run(main)
