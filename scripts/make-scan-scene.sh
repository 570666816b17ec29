#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A scanned model in a light-field scene, for `mesolight bench vlf-accuracy --scenes FILE.obj`:
# the props office (`bench vlf-accuracy --scenes props --write-obj`, nine game models from
# redeclipse-data) with the Chinese dragon of CGAL's data set (a 3D scan, 10000 points and 19994
# triangles; libcgal-demo's data.tar.gz) standing 0.3 m tall on the desk, of a jade diffuse
# material. The .deb is downloaded with `apt-get download` and unpacked into build/scans with
# `dpkg-deb -x`: nothing is installed. Writes OUTDIR/props-scan.obj and .mtl and prints the
# benchmark's command.
#
# Usage: scripts/make-scan-scene.sh MESOLIGHT_BINARY OUTDIR
set -euo pipefail
bin="$(realpath "$1")"
out="$2"
here="$(cd "$(dirname "$0")/.." && pwd)"
scans="$here/build/scans"
off="$scans/data/meshes/ChineseDragon-10kv.off"
if [ ! -f "$off" ]; then
  mkdir -p "$scans/debs"
  (cd "$scans/debs" && apt-get download libcgal-demo) >&2
  dpkg-deb -x "$scans"/debs/libcgal-demo_*.deb "$scans/deb"
  tar -xzf "$scans/deb/usr/share/doc/libcgal-dev/data.tar.gz" -C "$scans" \
    data/meshes/ChineseDragon-10kv.off
  rm -rf "$scans/deb" "$scans/debs" # 48 MB for the one 0.8 MB file kept
fi
mkdir -p "$out"
if [ -e "$out/props-scan.obj" ] || [ -e "$out/props-scan.mtl" ]; then
  echo "$out/props-scan.obj or .mtl exists; not overwritten" >&2
  exit 1
fi
props="$(mktemp -d)"
trap 'rm -rf "$props"' EXIT
"$bin" bench vlf-accuracy --scenes props --write-obj "$props" > /dev/null
python3 - "$off" "$props" "$out" <<'PY'
import sys
off, props, out = sys.argv[1], sys.argv[2], sys.argv[3]
tokens = open(off).read().split()
assert tokens[0] == "OFF"
nv, nf = int(tokens[1]), int(tokens[2])
points = [tuple(float(x) for x in tokens[4 + 3 * i:7 + 3 * i]) for i in range(nv)]
faces, at = [], 4 + 3 * nv
for _ in range(nf):
    n = int(tokens[at])
    faces.append([int(x) for x in tokens[at + 1:at + 1 + n]])
    at += 1 + n
# Counter-clockwise seen from outside (the light field's surfaces are one-sided): the signed
# volume is positive.
volume = 0.0
for f in faces:
    for k in range(1, len(f) - 1):
        a, b, c = points[f[0]], points[f[k]], points[f[k + 1]]
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                   + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
if volume < 0.0:
    faces = [list(reversed(f)) for f in faces]
lower = [min(p[i] for p in points) for i in range(3)]
upper = [max(p[i] for p in points) for i in range(3)]
scale = 0.3 / (upper[1] - lower[1])  # 0.3 m tall, y up
foot = ((lower[0] + upper[0]) / 2, lower[1], (lower[2] + upper[2]) / 2)
desk = (3.6, 0.72, 3.2)  # on the props office's desk
scene = open(props + "/props.obj").read().replace("mtllib props.mtl", "mtllib props-scan.mtl")
offset = sum(1 for line in scene.splitlines() if line.startswith("v "))
lines = [scene.rstrip("\n"), "g dragon", "usemtl jade"]
lines += ["v %.7g %.7g %.7g" % tuple(desk[i] + scale * (p[i] - foot[i]) for i in range(3))
          for p in points]
lines += ["f " + " ".join(str(offset + 1 + i) for i in f) for f in faces]
open(out + "/props-scan.obj", "w").write("\n".join(lines) + "\n")
open(out + "/props-scan.mtl", "w").write(
    open(props + "/props.mtl").read() + "\nnewmtl jade\nKd 0.3 0.6 0.4\n")
print("wrote %s/props-scan.obj: the props office and the dragon (%d points, %d triangles)"
      % (out, nv, nf))
PY
echo "measure: $bin bench vlf-accuracy --scenes $out/props-scan.obj" \
  "--camera 4.5,1.35,4.5,3.6,0.85,3.2 --fov 40"
