#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# An office lit by more lamps than the relief shader shades (8), for
# `scripts/bench-vlf-relief.sh` (SCENE=...): the props office (`bench vlf-accuracy --scenes props
# --write-obj`, nine game models from redeclipse-data) with its two 0.6 x 0.6 m ceiling lamps
# replaced by twelve of 0.245 x 0.245 m on a 4 x 3 grid (x 1.0, 2.3, 3.7, 5.0; z 1.0, 2.5, 4.0),
# the same material and about the same total area (0.720 m^2 against 0.72). Writes
# OUTDIR/props12.obj and .mtl and prints the benchmark's command. With `cubes` it also writes the
# movable object's shadow scenes of docs/measurements/vlf/object-shadows-twelve-lamps: cube.obj (a
# 0.5 m cube centred on the origin, for `vlf render --object`) and props12cube.obj /
# props12cube-low.obj (the office with that cube at (5.0, 2.15, 3.0) / (5.0, 1.0, 3.0), grey,
# for the path tracer). With `walls` it also writes props16.obj: the twelve ceiling lamps and four
# more of the same size on the side walls, 2.3 m up (above the furniture) at z 1.5 and 3.5, facing
# into the room (+x on the left wall, -x on the right), so that the lights the relief shades face
# three ways and light the back wall from its sides.
#
# Usage: scripts/make-twelve-lamp-office.sh MESOLIGHT_BINARY OUTDIR [cubes] [walls]
set -euo pipefail
bin="$(realpath "$1")"
out="$2"
mkdir -p "$out"
for file in props12.obj props12.mtl cube.obj props12cube.obj props12cube-low.obj props16.obj props16.mtl; do
  if [ -e "$out/$file" ]; then
    echo "$out/$file exists; not overwritten" >&2
    exit 1
  fi
done
props="$(mktemp -d)"
trap 'rm -rf "$props"' EXIT
"$bin" bench vlf-accuracy --scenes props --write-obj "$props" > /dev/null
python3 - "$props" "$out" "${@:3}" <<'PY'
import sys
props, out = sys.argv[1], sys.argv[2]
for extra in sys.argv[3:]:
    if extra not in ("cubes", "walls"):
        sys.exit("unknown scene '%s': cubes or walls" % extra)
cubes, walls = "cubes" in sys.argv[3:], "walls" in sys.argv[3:]
lines, material, dropped = [], None, 0
for line in open(props + "/props.obj").read().splitlines():
    if line.startswith("usemtl "):
        material = line.split()[1]
    if line.startswith("f ") and material == "lamp":
        dropped += 1  # the two lamps' triangles
        continue
    lines.append(line.replace("mtllib props.mtl", "mtllib props12.mtl"))
while lines and not lines[-1]:
    lines.pop()
offset = sum(1 for line in lines if line.startswith("v "))
side, height = 0.245, 2.799  # just below the 2.8 m ceiling, as the two lamps were
faces = []
for x in (1.0, 2.3, 3.7, 5.0):
    for z in (1.0, 2.5, 4.0):
        b = offset + 1
        lines += ["v %.4f %.4f %.4f" % (x + dx * side / 2, height, z + dz * side / 2)
                  for dx, dz in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        faces += ["f %d %d %d" % (b, b + 1, b + 2), "f %d %d %d" % (b, b + 2, b + 3)]  # facing down
        offset += 4
lines += ["g", "usemtl lamp"] + faces
open(out + "/props12.obj", "w").write("\n".join(lines) + "\n")
open(out + "/props12.mtl", "w").write(open(props + "/props.mtl").read())
print("wrote %s/props12.obj: the props office with twelve ceiling lamps (%d lamp triangles "
      "replaced by %d)" % (out, dropped, len(faces)))
if cubes:
    corners = [(a, b, c) for a, b, c in [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                                         (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 4, 7, 3), (1, 2, 6, 5), (0, 1, 5, 4), (3, 7, 6, 2)]

    def cube(centre, first):  # counter-clockwise seen from outside
        v = ["v %.4f %.4f %.4f" % tuple(centre[i] + 0.25 * p[i] for i in range(3)) for p in corners]
        f = []
        for q in quads:
            a, b, c, d = (first + i for i in q)
            f += ["f %d %d %d" % (a, b, c), "f %d %d %d" % (a, c, d)]
        return v, f

    v, f = cube((0.0, 0.0, 0.0), 1)
    open(out + "/cube.obj", "w").write("\n".join(v + f) + "\n")
    for name, centre in (("props12cube", (5.0, 2.15, 3.0)), ("props12cube-low", (5.0, 1.0, 3.0))):
        v, f = cube(centre, offset + 1)
        open(out + "/" + name + ".obj", "w").write("\n".join(lines + ["g cube", "usemtl grey"] + v + f) + "\n")
    print("wrote %s/cube.obj, props12cube.obj and props12cube-low.obj" % out)
if walls:
    wall_lines, first = [], offset + 1
    for x, corners in ((0.001, ((-1, -1), (1, -1), (1, 1), (-1, 1))),    # facing +x
                       (5.999, ((-1, -1), (-1, 1), (1, 1), (1, -1)))):   # facing -x
        for z in (1.5, 3.5):
            wall_lines += ["v %.4f %.4f %.4f" % (x, 2.3 + dy * side / 2, z + dz * side / 2)
                           for dy, dz in corners]
            faces += ["f %d %d %d" % (first, first + 1, first + 2),
                      "f %d %d %d" % (first, first + 2, first + 3)]
            first += 4
    lamps = len(lines) - 1 - lines[::-1].index("usemtl lamp")  # the twelve lamps' faces
    walled = lines[:lamps - 1] + wall_lines + ["g", "usemtl lamp"] + faces
    open(out + "/props16.obj", "w").write(
        "\n".join(line.replace("mtllib props12.mtl", "mtllib props16.mtl") for line in walled) + "\n")
    open(out + "/props16.mtl", "w").write(open(props + "/props.mtl").read())
    print("wrote %s/props16.obj: the twelve ceiling lamps and four on the side walls" % out)
PY
scene=props12.obj
for extra in "${@:3}"; do [ "$extra" != walls ] || scene=props16.obj; done
echo "measure: SCENE=$out/$scene SURFACE=back CAMERA=4.6,1.6,4.8,2.2,0.8,1.2 FOV=65" \
  "RAYS=72 scripts/bench-vlf-relief.sh $bin OUTDIR"
