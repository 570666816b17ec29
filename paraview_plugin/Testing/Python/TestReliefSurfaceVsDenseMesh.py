# SPDX-License-Identifier: BSD-3-Clause
"""The Relief Surface representation against a dense displaced mesh drawn by ParaView's own
Surface representation (independent reference), with negative checks: plain texture mapping
(method 0: normal mapping, no march) and the flat plane as a plain Surface must both fail."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import paraview.simple as pvs  # noqa: E402

t.load_plugin()
out = t.output_dir()
relief = t.relief_texture()
plane = t.unit_square()
failures = []


def render_alone(name, make):
    view = t.make_view()
    make(view)
    return t.capture(view, os.path.join(out, "pv-%s.png" % name))


reference = render_alone("dense", lambda v: t.show_dense_reference(relief, v))
footprint = t.covered(render_alone("footprint", lambda v: pvs.Show(plane, v)))
cases = {
    # name: (representation settings, must pass?)
    "relief": (lambda v: t.show_relief(plane, relief, v, SelfShadowing=0), True),
    "texture-mapping": (lambda v: t.show_relief(plane, relief, v, SelfShadowing=0, ReliefMethod=0), False),
    "flat-surface": (lambda v: pvs.Show(plane, v), False),
}
for name, (make, must_pass) in cases.items():
    d = t.compare(render_alone(name, make), reference, footprint)
    ok = t.within_tolerance(d)
    print("[%s] mean colour error %.2f levels, silhouette mismatch %.2f%%, covered %d px -> %s"
          % (name, d["mean_color_error"], d["silhouette_mismatch"], d["covered_both"],
             "within" if ok else "outside"))
    if d["covered_both"] < t.SIZE[0] * t.SIZE[1] // 8:
        failures.append("%s: the surface should fill much of the view" % name)
    if ok != must_pass:
        failures.append("%s should %s the comparison" % (name, "pass" if must_pass else "fail"))

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
