#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
# The relief's error against the path-traced reference per region of the relief: each pixel's
# centre ray (the published Cornell camera, 256 x 256, depth scale 0.05 on the back wall) is
# marched through the depth map (nearest texel, walled at the border) and its pixel counted as a
# brick top (depth < 0.1), a bevel, a slot bottom (depth > 0.97) or a side wall (the border below
# the surface). Per region and image: mean |relative error| of the luminance, signed mean, and
# the region's share of the image's total |error|. Pixels with mask coverage >= 0.999, as
# `bench vlf-relief` counts them.
#
#   relief-regions.py DEPTH.pgm REFERENCE.exr MASK.exr NAME=IMAGE.exr [...]
#
# DEPTH.pgm: scripts/bench-vlf-relief.sh's input/bricks-depth.pgm (binary PGM). Needs oiiotool.
import re, sys, os, subprocess, math, tempfile
tmp = tempfile.mkdtemp()
depthpgm, ref, mask = sys.argv[1], sys.argv[2], sys.argv[3]
imgs = [a.split("=", 1) for a in sys.argv[4:]]
def lum(path, tag):
    out = f"{tmp}/{tag}.txt"
    subprocess.run(["oiiotool", path, "--ch", "R,G,B", "--chsum:weight=0.2126,0.7152,0.0722", "-o", f"{tmp}/{tag}.exr"], check=True)
    with open(out, "w") as f:
        subprocess.run(["oiiotool", "--dumpdata", f"{tmp}/{tag}.exr"], stdout=f, check=True)
    v = {}
    for line in open(out):
        g = re.match(r'\s*Pixel \((\d+), (\d+)\): ([-\d.e+na]+)', line)
        if g: v[(int(g[1]), int(g[2]))] = float(g[3])
    return v
def readpgm(p):
    data = open(p, "rb").read()
    parts = data.split(maxsplit=4)
    w, h = int(parts[1]), int(parts[2])
    pix = parts[4]
    return w, h, [[pix[(h - 1 - j) * w + i] / 255.0 for i in range(w)] for j in range(h)]  # [j][i], j=0 bottom
W, H, D = readpgm(depthpgm)
def depth(u, v):  # nearest texel, clamped; walled outside
    if u < 0 or u > 1 or v < 0 or v > 1: return 0.0
    i = min(W - 1, int(u * W)); j = min(H - 1, int(v * H))
    return D[j][i]
refv = lum(ref, "ref"); maskv = lum(mask, "mask")
px = [k for k, m in maskv.items() if m >= 0.999]
cam = (278.0, 273.0, -800.0); tanf = math.tan(math.radians(39.3077) / 2); S = 256
zw, K = 559.2, 0.05 * 556.0
region = {}
for (x, y) in px:
    nx = ((x + 0.5) / (S / 2) - 1) * tanf; ny = (1 - (y + 0.5) / (S / 2)) * tanf
    d = (-nx, ny, 1.0)
    t0 = (zw - cam[2]); t1 = (zw + K - cam[2])
    N = 400; r = None
    for s in range(N + 1):
        t = t0 + (t1 - t0) * s / N
        wx, wy = cam[0] + d[0] * t, cam[1] + d[1] * t
        u, v = 1 - wx / 556.0, wy / 548.8
        rd = (t - t0) / K
        if rd >= depth(u, v) - 1e-9:
            if u < 0 or u > 1 or v < 0 or v > 1: r = "side wall"
            else:
                dd = depth(u, v)
                r = "top" if dd < 0.1 else ("bottom" if dd > 0.97 else "bevel")
            break
    region[(x, y)] = r or "bottom"
ys = sorted(set(k[1] for k in px))
names = ["top", "bevel", "bottom", "side wall"]
data = [(n, lum(p, f"img{i}")) for i, (n, p) in enumerate(imgs)]
print(f"{'region':10s} {'pixels':>6s} " + " ".join(f"{n[:18]:>26s}" for n, _ in data))
for rn in names + ["all"]:
    ks = [k for k in px if rn == "all" or region[k] == rn]
    if not ks: continue
    cols = []
    for n, img in data:
        e = [(img[k] - refv[k]) / refv[k] for k in ks]
        tot = sum(abs((img[k] - refv[k]) / refv[k]) for k in px)
        cols.append(f"{sum(map(abs, e)) / len(ks):7.4f} {sum(e) / len(ks):+7.4f} {sum(map(abs, e)) / tot:5.3f}")
    print(f"{rn:10s} {len(ks):6d} " + " ".join(f"{c:>26s}" for c in cols))
print("columns: mean |rel err|, signed mean, share of the image's total |err|")
