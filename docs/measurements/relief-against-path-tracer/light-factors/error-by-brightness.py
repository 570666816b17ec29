#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
# The relief's error against the path-traced reference by the reference's luminance (quantile bins of
# the relief pixels, mask coverage >= 0.999): where the GPU's error exceeds the CPU path's. Needs
# oiiotool and numpy (/usr/bin/python3).
#   error-by-brightness.py RUN_DIR MAP NAME=IMAGE.exr [...]   (RUN_DIR: scripts/bench-vlf-relief.sh's
#   output, MAP e.g. procedural-bricks)
import os, re, subprocess, sys, tempfile
import numpy as np
tmp = tempfile.mkdtemp()
def lum(path):
    out = os.path.join(tmp, "luminance.exr")
    subprocess.run(["oiiotool", path, "--ch", "R,G,B", "--chsum:weight=0.2126,0.7152,0.0722", "-o", out], check=True)
    txt = subprocess.run(["oiiotool", "--dumpdata", out], capture_output=True, text=True, check=True).stdout
    a = np.zeros((256,256))
    for g in re.finditer(r'Pixel \((\d+), (\d+)\): ([-\d.e+na]+)', txt):
        a[int(g[2]), int(g[1])] = float(g[3])
    return a
d = sys.argv[1]; m = sys.argv[2]
ref = lum(f"{d}/{m}-reference.exr"); mask = lum(f"{d}/{m}-mask.exr")
imgs = {k: lum(v) for k, v in (a.split("=",1) for a in sys.argv[3:])}
sel = mask >= 0.999
r = ref[sel]
q = np.quantile(r, [0, 0.1, 0.25, 0.5, 0.75, 1.0])
print("ref-luminance bin      pixels " + " ".join(f"{k:>22s}" for k in imgs))
for lo, hi, name in zip(q[:-1], q[1:], ["darkest 10%", "10-25%", "25-50%", "50-75%", "brightest 25%"]):
    b = (r >= lo) & (r <= hi)
    cols = []
    for k, im in imgs.items():
        e = (im[sel][b] - r[b]) / r[b]
        cols.append(f"{np.abs(e).mean():8.4f} {e.mean():+8.4f}")
    print(f"{name:20s} {b.sum():8d} " + " ".join(f"{c:>22s}" for c in cols))
cols = []
for k, im in imgs.items():
    e = (im[sel] - r) / r
    cols.append(f"{np.abs(e).mean():8.4f} {e.mean():+8.4f}")
print(f"{'all':20s} {sel.sum():8d} " + " ".join(f"{c:>22s}" for c in cols))
print("columns: mean |rel err|, signed mean")
