#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
# Writes the two OBJ + MTL scenes of the path tracer's cross-check against Blender Cycles
# (scripts/cycles-crosscheck.sh), both unlike the Cornell box:
#   room.obj   a 4 x 2.6 x 5 m room lit only indirectly: the one emitter lies face up on top of a
#              wardrobe, out of the camera's sight, and lights the room through the ceiling;
#   boxes.obj  a 6 x 6 m floor with five boxes (two turned), under a 1 m square emitter facing
#              down, open to a black sky.
# Metres, y up; faces counter-clockwise seen from their front (the emitters' front emits, Ke is
# the emitted radiance); diffuse materials only (Kd). Usage: make_scenes.py OUTDIR
import math
import os
import sys


class Scene:
    def __init__(self):
        self.vertices = []
        self.faces = []  # (material, [vertex indices, 1-based])
        self.materials = {}

    def material(self, name, kd, ke=(0.0, 0.0, 0.0)):
        self.materials[name] = (kd, ke)

    def quad(self, material, corners):
        base = len(self.vertices)
        self.vertices.extend(corners)
        self.faces.append((material, [base + 1, base + 2, base + 3, base + 4]))

    def box(self, material, lower, upper, turn_degrees=0.0, inward=False):
        """An axis-aligned box turned about its vertical axis; faces outward (or inward: a room)."""
        cx, cz = 0.5 * (lower[0] + upper[0]), 0.5 * (lower[2] + upper[2])
        c, s = math.cos(math.radians(turn_degrees)), math.sin(math.radians(turn_degrees))

        def p(x, y, z):
            dx, dz = x - cx, z - cz
            return (cx + c * dx + s * dz, y, cz - s * dx + c * dz)

        x0, y0, z0 = lower
        x1, y1, z1 = upper
        faces = [  # outward, counter-clockwise seen from outside
            [p(x0, y0, z0), p(x1, y0, z0), p(x1, y0, z1), p(x0, y0, z1)],  # bottom (-y)
            [p(x0, y1, z0), p(x0, y1, z1), p(x1, y1, z1), p(x1, y1, z0)],  # top (+y)
            [p(x0, y0, z0), p(x0, y1, z0), p(x1, y1, z0), p(x1, y0, z0)],  # -z
            [p(x0, y0, z1), p(x1, y0, z1), p(x1, y1, z1), p(x0, y1, z1)],  # +z
            [p(x0, y0, z0), p(x0, y0, z1), p(x0, y1, z1), p(x0, y1, z0)],  # -x
            [p(x1, y0, z0), p(x1, y1, z0), p(x1, y1, z1), p(x1, y0, z1)],  # +x
        ]
        names = material if isinstance(material, list) else [material] * 6
        for name, corners in zip(names, faces):
            self.quad(name, list(reversed(corners)) if inward else corners)

    def write(self, obj_path, comment):
        mtl_path = os.path.splitext(obj_path)[0] + ".mtl"
        with open(mtl_path, "w") as mtl:
            mtl.write("# %s\n" % comment)
            for name, (kd, ke) in sorted(self.materials.items()):
                mtl.write("newmtl %s\nKd %g %g %g\n" % ((name,) + tuple(kd)))
                if max(ke) > 0.0:
                    mtl.write("Ke %g %g %g\n" % tuple(ke))
        with open(obj_path, "w") as obj:
            obj.write("# %s\nmtllib %s\n" % (comment, os.path.basename(mtl_path)))
            for v in self.vertices:
                obj.write("v %.6f %.6f %.6f\n" % v)
            current = None
            for name, indices in self.faces:
                if name != current:
                    obj.write("usemtl %s\n" % name)
                    current = name
                obj.write("f %s\n" % " ".join(str(i) for i in indices))


def room():
    s = Scene()
    s.material("white", (0.75, 0.75, 0.75))
    s.material("red", (0.62, 0.22, 0.18))
    s.material("teal", (0.18, 0.45, 0.5))
    s.material("floor", (0.55, 0.42, 0.3))
    s.material("wood", (0.45, 0.3, 0.18))
    s.material("panel", (0.7, 0.68, 0.6))
    s.material("lamp", (0.8, 0.8, 0.8), (40.0, 36.0, 30.0))
    # The room, faces inward: floor, ceiling, back (-z), front (+z), left (-x), right (+x).
    s.box(["floor", "white", "white", "white", "red", "teal"], (0, 0, 0), (4, 2.6, 5), inward=True)
    # The wardrobe in the back-left corner, its top 2.0 m up, and the uplight on it, face up.
    s.box("wood", (0.1, 0, 0.1), (1.1, 2.0, 0.7))
    s.quad("lamp", [(0.2, 2.001, 0.2), (0.2, 2.001, 0.6), (1.0, 2.001, 0.6), (1.0, 2.001, 0.2)])
    # A table, a tilted panel leaning on the right wall and a small cube on the floor.
    s.box("wood", (1.8, 0.7, 1.6), (3.0, 0.76, 2.4))
    for x, z in ((1.85, 1.65), (2.9, 1.65), (1.85, 2.3), (2.9, 2.3)):
        s.box("wood", (x, 0, z), (x + 0.05, 0.7, z + 0.05))
    s.quad("panel", [(3.5, 0.0, 3.6), (3.5, 0.0, 2.8), (3.98, 1.5, 2.8), (3.98, 1.5, 3.6)])
    s.box("red", (0.6, 0, 3.0), (1.0, 0.4, 3.4), turn_degrees=25.0)
    return s


def boxes():
    s = Scene()
    s.material("floor", (0.6, 0.6, 0.6))
    s.material("white", (0.8, 0.8, 0.8))
    s.material("orange", (0.7, 0.4, 0.15))
    s.material("blue", (0.2, 0.3, 0.65))
    s.material("lamp", (0.8, 0.8, 0.8), (15.0, 15.0, 15.0))
    s.quad("floor", [(-3, 0, -3), (-3, 0, 3), (3, 0, 3), (3, 0, -3)])
    s.box("white", (-1.5, 0, -1.0), (-0.5, 1.2, 0.0), turn_degrees=20.0)
    s.box("orange", (0.3, 0, -0.6), (1.1, 0.5, 0.2))
    s.box("blue", (-0.4, 0, 0.8), (0.2, 0.6, 1.4), turn_degrees=-35.0)
    s.box("white", (1.4, 0, 0.9), (1.7, 0.3, 1.2))
    s.box("orange", (-2.2, 0, 1.0), (-1.6, 0.25, 1.6))
    # The emitter, 3 m up, facing down.
    s.quad("lamp", [(-0.5, 3, -0.5), (0.5, 3, -0.5), (0.5, 3, 0.5), (-0.5, 3, 0.5)])
    return s


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    room().write(os.path.join(out, "room.obj"),
                 "A room lit indirectly by an uplight on a wardrobe (metres, y up)")
    boxes().write(os.path.join(out, "boxes.obj"),
                  "Five boxes on a floor under a square light (metres, y up)")
    print("wrote room.obj, boxes.obj and their .mtl in", out)
