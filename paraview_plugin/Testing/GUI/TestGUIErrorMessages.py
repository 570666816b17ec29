# SPDX-License-Identifier: BSD-3-Clause
"""GUI: the errors a GUI user meets name what to do in ParaView (the Output Messages window shows
them), not only C++ classes. Cases: a cone method without a cone map, and a surface without
texture coordinates (a Sphere). The messages are caught by a vtkStringOutputWindow put in place
of the GUI's output window for the duration of each render."""
import mesolight_guitest as g
import paraview.simple as pvs
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

CASES = [
    # (what, must contain, must not be the only advice)
    ("cone method without a cone map", "apply Mesolight Cone Map to the depth image",
     "vtkConeMapFilter"),
    ("surface without texture coordinates", "apply Texture Map to Plane", "vtkTextureMapToPlane"),
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

    for (what, advice, cxx), render in zip(CASES, (cone_method, no_tcoords)):
        text = messages_of(render)
        print("%s -> %r" % (what, text.strip()))
        if advice.lower() not in text.lower():
            failures.append("%s: the message should say %r: %r" % (what, advice, text))
        if cxx in text and text.lower().find(advice.lower()) > text.find(cxx):
            failures.append("%s: the C++ class comes before the GUI advice" % what)
    return failures


g.run(main)
