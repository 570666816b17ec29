#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Where the relief's error sits: the mean relative luminance error per relief pixel (mask >= 1,
# as bench vlf-relief counts) over all of them, per band of 16 image rows, and without a border of
# B pixels around the relief's pixel bounds, for images written by bench-vlf-relief.sh.
#
#   border-analysis.sh OUTDIR MAP IMAGE [B]    e.g. /tmp/rb-bench procedural-bricks field-multi-bounce 4
set -eu
out="$1"; map="$2"; image="$3"; border="${4:-4}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
for f in "$map-$image" "$map-reference"; do
  oiiotool "$out/$f.exr" --ch R,G,B --chsum:weight=0.2126,0.7152,0.0722 -o "$tmp/$f.exr"
  oiiotool --dumpdata "$tmp/$f.exr" > "$tmp/$f.txt"
done
oiiotool --dumpdata "$out/$map-mask.exr" > "$tmp/mask.txt"
python3 - "$tmp/$map-$image.txt" "$tmp/$map-reference.txt" "$tmp/mask.txt" "$border" <<'PY'
import re, sys
def load(path):
    values = {}
    for line in open(path):
        m = re.match(r'\s*Pixel \((\d+), (\d+)\): ([-\d.e+]+)', line)
        if m:
            values[(int(m[1]), int(m[2]))] = float(m[3])
    return values
image, ref, mask = (load(p) for p in sys.argv[1:4])
b = int(sys.argv[4])
px = [k for k, v in mask.items() if v >= 1]
err = {k: (image[k] - ref[k]) / ref[k] for k in px}
xs = [k[0] for k in px]; ys = [k[1] for k in px]
mean = lambda ks: sum(abs(err[k]) for k in ks) / len(ks)
signed = lambda ks: sum(err[k] for k in ks) / len(ks)
print("all %d pixels: mean %.4f, signed %+.4f" % (len(px), mean(px), signed(px)))
for y0 in range(min(ys), max(ys) + 1, 16):
    ks = [k for k in px if y0 <= k[1] < y0 + 16]
    if ks:
        print("  rows %3d-%3d (%5d px): mean %.4f, signed %+.4f" % (y0, y0 + 15, len(ks), mean(ks), signed(ks)))
inner = [k for k in px if min(ys) + b <= k[1] <= max(ys) - b and min(xs) + b <= k[0] <= max(xs) - b]
print("without a %d-pixel border (%d pixels): mean %.4f, signed %+.4f" % (b, len(inner), mean(inner), signed(inner)))
PY
