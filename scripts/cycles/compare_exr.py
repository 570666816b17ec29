# SPDX-License-Identifier: BSD-3-Clause
# Per-pixel comparison of Mesolight's path tracer with Blender Cycles on one view, run in
# Blender's Python (it has numpy and reads EXR):
#   blender -b --factory-startup --python compare_exr.py -- NAME CYCLES1.exr CYCLES2.exr \
#       CYCLES_SECONDS OURS1.exr OURS2.exr OURS_SECONDS CSV
# Each renderer rendered the view twice with independent seeds (the seconds are for both).
# Reports, over the pixels Cycles sees lit (luminance above 1e-3 of the image's mean):
# - the per-pixel relative error of luminance |ours - cycles| / cycles, each the mean of its two
#   renders: mean and 95th percentile;
# - each renderer's relative noise: the RMS over pixels of (X1 - X2) / 2 / m, the standard
#   deviation of the two-render mean (independent seeds), m the mean of all four renders (not
#   one renderer's own mean, which is small exactly where its own samples came out small), and the error expected from noise
#   alone, sqrt(2 / pi) * sqrt(s_ours^2 + s_cycles^2) (mean |difference| of two Gaussians);
# - the same relative error over 4 x 4 pixel blocks (their mean luminance; blocks all lit), where
#   noise is 4 times smaller and a bias (a wrong emitter unit, camera or material) stays;
# - the time each would take to reach 1% relative noise, noise ~ 1 / sqrt(time).
# Appends one row to CSV (a header first when the file is new).
import os
import sys

import bpy
import numpy as np

argv = sys.argv[sys.argv.index("--") + 1:]
name = argv[0]
cycles_paths, cycles_seconds = argv[1:3], float(argv[3])
ours_paths, ours_seconds = argv[4:6], float(argv[6])
csv_path = argv[7]


def luminance(path):
    image = bpy.data.images.load(path)
    image.colorspace_settings.name = "Non-Color"
    width, height = image.size
    pixels = np.array(image.pixels[:], dtype=np.float64).reshape(height, width, image.channels)
    return 0.2126 * pixels[..., 0] + 0.7152 * pixels[..., 1] + 0.0722 * pixels[..., 2]


c1, c2 = (luminance(p) for p in cycles_paths)
o1, o2 = (luminance(p) for p in ours_paths)
if c1.shape != o1.shape:
    sys.exit("image sizes differ: Cycles %s, ours %s" % (c1.shape, o1.shape))
cycles = 0.5 * (c1 + c2)
ours = 0.5 * (o1 + o2)
lit = cycles > 1e-3 * cycles.mean()
relative = np.abs(ours[lit] - cycles[lit]) / cycles[lit]
both = 0.5 * (cycles + ours)
noise_cycles = np.sqrt(np.mean((0.5 * (c1[lit] - c2[lit]) / both[lit]) ** 2))
noise_ours = np.sqrt(np.mean((0.5 * (o1[lit] - o2[lit]) / both[lit]) ** 2))
expected = np.sqrt(2.0 / np.pi) * np.sqrt(noise_cycles ** 2 + noise_ours ** 2)
bias = ours[lit].sum() / cycles[lit].sum() - 1.0
def blocks(image, size=4):
    h, w = (image.shape[0] // size) * size, (image.shape[1] // size) * size
    return image[:h, :w].reshape(h // size, size, w // size, size).mean(axis=(1, 3))


block_lit = blocks(lit.astype(np.float64)) == 1.0
cycles_blocks, ours_blocks = blocks(cycles)[block_lit], blocks(ours)[block_lit]
block_relative = np.abs(ours_blocks - cycles_blocks) / cycles_blocks
target = 0.01
t_cycles = cycles_seconds * (noise_cycles / target) ** 2
t_ours = ours_seconds * (noise_ours / target) ** 2
row = {
    "scene": name,
    "pixels": "%dx%d" % (c1.shape[1], c1.shape[0]),
    "lit_pixels": int(lit.sum()),
    "mean_rel_error": "%.4f" % relative.mean(),
    "p95_rel_error": "%.4f" % np.percentile(relative, 95),
    "expected_from_noise": "%.4f" % expected,
    "block4_mean_rel_error": "%.4f" % block_relative.mean(),
    "block4_p95_rel_error": "%.4f" % np.percentile(block_relative, 95),
    "overall_bias": "%.4f" % bias,
    "cycles_seconds": "%.1f" % cycles_seconds,
    "cycles_noise": "%.4f" % noise_cycles,
    "ours_seconds": "%.1f" % ours_seconds,
    "ours_noise": "%.4f" % noise_ours,
    "cycles_s_to_1pct": "%.1f" % t_cycles,
    "ours_s_to_1pct": "%.1f" % t_ours,
    "speedup": "%.2f" % (t_cycles / t_ours),
}
new = not os.path.exists(csv_path)
with open(csv_path, "a") as csv:
    if new:
        csv.write(",".join(row) + "\n")
    csv.write(",".join(str(v) for v in row.values()) + "\n")
print("crosscheck " + " ".join("%s=%s" % item for item in row.items()))
