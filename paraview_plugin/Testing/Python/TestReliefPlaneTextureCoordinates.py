# SPDX-License-Identifier: BSD-3-Clause
"""A planar surface without texture coordinates drawn as Relief Surface gets those of its plane
(the command line's rule, SurfacePlaneOf: the depth image once over the surface's bounding
rectangle in its plane, upright), so no Texture Map to Plane is needed.

The unit square without its texture coordinates (removed by a Programmable Filter) against the
independent reference of the ReliefVsDenseMesh test: the same height field as a dense displaced
mesh drawn by ParaView's Surface representation. Must fail: the same square with texture
coordinates of another frame (Texture Map to Plane with u and v swapped). Bad input: a sphere
(not planar) without texture coordinates is an error naming the problem, no crash. On two ranks
the square is split between them: each piece must get the whole surface's frame (a piece's own
bounding rectangle would stretch the relief over each half).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_STRING  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow  # noqa: E402

t.load_plugin()
out = t.output_dir()
failures = []
check = t.checker(failures)
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
relief = t.relief_texture()

STRIP = """
data = self.GetInputDataObject(0, 0)
out = self.GetOutputDataObject(0)
out.ShallowCopy(data)
out.GetPointData().SetTCoords(None)
for name in ("TextureCoordinates", "TCoords"):
    out.GetPointData().RemoveArray(name)
"""


def without_tcoords(source):
    strip = pvs.ProgrammableFilter(Input=source)
    strip.Script = STRIP
    strip.CopyArrays = 0
    return strip


unit_plane = t.unit_square(16)
if ranks > 1:
    unit_plane = pvs.RedistributeDataSet(Input=unit_plane)  # each rank a part of the square
without = without_tcoords(unit_plane)
without.UpdatePipeline()
info = without.GetPointDataInformation()
names = [info.GetArray(k).GetName() for k in range(info.GetNumberOfArrays())]
check("TextureCoordinates" not in names and "TCoords" not in names,
      "the surface has no texture coordinates (%d ranks; point arrays %s)" % (ranks, names))
swapped = pvs.TextureMaptoPlane(Input=without, Origin=[0, 0, 0], Point1=[0, 1, 0],
                                Point2=[1, 0, 0])


def render_alone(name, make):
    view = t.make_view()
    make(view)
    return t.capture(view, os.path.join(out, "pv-plane-tcoords-%s.png" % name))


reference = render_alone("dense", lambda v: t.show_dense_reference(relief, v))
footprint = t.covered(render_alone("footprint", lambda v: pvs.Show(unit_plane, v)))
cases = {
    # name: (representation, must pass?)
    "plane-frame": (lambda v: t.show_relief(without, relief, v, SelfShadowing=0), True),
    "own-tcoords": (lambda v: t.show_relief(unit_plane, relief, v, SelfShadowing=0), True),
    "swapped-frame": (lambda v: t.show_relief(swapped, relief, v, SelfShadowing=0), False),
}
for name, (make, must_pass) in cases.items():
    d = t.compare(render_alone(name, make), reference, footprint)
    ok = t.within_tolerance(d)
    print("[%s] mean colour error %.2f levels, silhouette mismatch %.2f%%, covered %d px -> %s"
          % (name, d["mean_color_error"], d["silhouette_mismatch"], d["covered_both"],
             "within" if ok else "outside"))
    check(d["covered_both"] >= t.SIZE[0] * t.SIZE[1] // 8,
          "%s: the surface fills much of the view" % name)
    check(ok == must_pass, "%s %s the dense mesh" % (name, "matches" if must_pass else
                                                     "does not match"))

# --- bad input: not planar, no texture coordinates -------------------------------------------
messages = []
window = vtkOutputWindow.GetInstance()


tag = window.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: messages.append("error"))
sphere = without_tcoords(pvs.Sphere(ThetaResolution=16, PhiResolution=16))
view = t.make_view()
_, display = t.show_relief(sphere, relief, view)
pvs.Render(view)
window.RemoveObserver(tag)
print("non-planar surface: %d error(s) reported" % len(messages))
check(len(messages) > 0, "a non-planar surface without texture coordinates is an error")

# A plain Sphere shown as Relief Surface with no relief texture attached at all: the errors say
# what is missing (texture coordinates, a relief texture), not that the sphere is not planar (the
# plane rule is for a relief texture's surface; without one it was the first, misleading word).
texts = []


@calldata_type(VTK_STRING)
def on_error(caller, event, text):
    texts.append(text)


tag = window.AddObserver(vtkCommand.ErrorEvent, on_error)
bare_sphere = without_tcoords(pvs.Sphere(ThetaResolution=16, PhiResolution=16))
view = t.make_view()
bare_display = pvs.Show(bare_sphere, view)
bare_display.SetRepresentationType("Relief Surface")
pvs.Render(view)
after_one_render = len(texts)
pvs.Render(view)
pvs.Render(view)
window.RemoveObserver(tag)
said = " | ".join(texts)
print("sphere without a relief texture: %d error(s) after one render, %d after three: %s"
      % (after_one_render, len(texts), said.replace("\n", " ")[:300]))
check(len(texts) > 0, "a sphere without a relief texture or texture coordinates is an error")
check("not planar" not in said, "no plane-rule complaint on a surface with no relief texture")
# The first word is the first thing a relief surface needs, and it is said once, not at every
# render of the view.
check(len(texts) > 0 and "No relief texture" in texts[0],
      "the first error names the missing relief texture")
check(len(texts) == after_one_render, "renders of an unchanged surface repeat no error")

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
