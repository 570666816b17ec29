#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
# The object's shadow on the floor of the twelve-lamp office: `vlf render --mode progressive
# --object cube.obj --shadows MODE` (after: new-MODE.exr; before: old-MODE.exr) against the path
# tracer with the cube in the scene (ref-cube.exr), over the pixels the cube darkens by more than
# 5% in the path tracer (ref-cube / ref-nocube < 0.95), the object's own pixels left out (where
# the render with the object and no shadows differs from one without the object).
# Usage: compare-shadows.py PREFIX [NO_OBJECT.exr [NAME,NAME,...]]   (reads the EXRs with
# oiiotool --dumpdata; NAMEs: the renders PREFIX+NAME.exr to compare, the first one with
# --shadows none when NO_OBJECT.exr is given; default the modes before and after)
import re
import subprocess
import sys

import numpy as np


def load(path):
    out = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True, text=True).stdout
    w, h = map(int, re.search(r"(\d+) x\s+(\d+)", out.split("\n")[0]).groups())
    values = [[float(x) for x in line.split(":")[1].split()[:3]]
              for line in out.split("\n")[1:] if "Pixel" in line]
    return np.array(values).reshape(h, w, 3).mean(axis=2)


p = sys.argv[1]
names = ["new-soft", "old-soft", "new-field", "old-field", "new-pcf", "old-pcf", "new-none"]
names_given = len(sys.argv) > 3
if names_given:
    names = sys.argv[3].split(",")
ref, nocube = load(p + "ref-cube.exr"), load(p + "ref-nocube.exr")
obj = np.zeros(ref.shape, bool)
if len(sys.argv) > 2 and sys.argv[2]:
    obj = np.abs(load(p + (names[0] if names_given else "new-none") + ".exr")
                 - load(sys.argv[2])) > 1e-6
ratio = ref / np.maximum(nocube, 1e-9)
mask = (ratio < 0.95) & ~obj
print(f"{p or 'high '}: object pixels {obj.sum()}, shadow pixels (reference with cube < 0.95 x "
      f"without, object left out) {mask.sum()}, reference ratio there {ratio[mask].mean():.3f}")
for name in names:
    img = load(p + name + ".exr")
    rel = np.abs(img - ref) / np.maximum(ref, 1e-9)
    print(f"  {name:10s} shadow pixels: mean rel. error {rel[mask].mean()*100:5.1f}%, mean ratio "
          f"{(img[mask]/ref[mask]).mean():.3f}; frame without the object {rel[~obj].mean()*100:5.1f}%")
