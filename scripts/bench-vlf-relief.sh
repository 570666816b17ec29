#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A relief lit by the light field, measured against the truth: a scene (the Cornell box unless
# SCENE names an OBJ file) with a relief on one of its walls (SURFACE, the back wall unless
# told), from one camera,
#   - path traced on the dense displaced mesh of the relief (`trace --scene SCENE --relief
#     SURFACE=DEPTH --exr`, the reference), twice with other random paths so that the reference's
#     own noise is printed beside the errors, with the relief's pixel mask (--relief-mask);
#   - the flat wall path traced and drawn by the field without a relief, over the same pixels:
#     the field's own error there, which the relief inherits;
#   - `vlf render --relief SURFACE=DEPTH --exr` (the method as a user runs it), and the interactive
#     GPU path (`vlf render --mode progressive --relief ...`, the relief mapper as `vlf view`
#     draws it, with and without its precomputed occlusion), measured as a method of its own
#     against the same negative cases: drawn at one ray per pixel and with `--supersampling S`
#     (S x S pixels drawn per pixel and averaged, the pixel average the reference's paths cover
#     and the in-process CPU rows' 2 x 2 rays take), the supersampled image the method's row;
#   - `bench vlf-relief FIELD --relief ...`: the relief's pixels rendered in-process, on the same
#     rays, lit by the field (the method), by the flat wall's field value and by one light of the
#     lamp's power with shadows (the negative cases), each timed: the mean relative error per
#     relief pixel against the reference, the goal (<= 8% at 2049 directions, >= 2x better than
#     both negative cases) and the cost of a relief pixel lit by the field vs by one light.
# Rows are appended to docs/measurements/relief-against-path-tracer/relief-against-path-tracer.csv
# with a plot per map.
#
#   scripts/bench-vlf-relief.sh MESOLIGHT_BINARY OUTDIR
#
# Depth maps: a procedural brick map (written here) and, when the Debian package redeclipse-data
# is installed, its brick height map (wicked/highqualitybrickz.jpg, inverted to depth); skipped
# when absent. Settings through the environment (defaults in brackets): DIRECTIONS [2049], RAYS
# [32] (the field), SCENE [cornell, or an OBJ + MTL scene with named surfaces, e.g. the props
# office of `mesolight bench vlf-accuracy --scenes props --write-obj DIR`], SURFACE [back],
# SIZE [256] (square images), SAMPLES [1024] (paths per pixel of the
# references), SUPERSAMPLING [2] (the GPU's pixels drawn per image pixel side), DEPTH_SCALE [0.05], CAMERA [278,273,-800,278,273,0, the published Cornell camera],
# FOV [39.3077], CSV_DIR [docs/measurements/relief-against-path-tracer in the source tree],
# LABEL_SUFFIX [none: appended to every CSV row's label, e.g. to tell two binaries' runs on the
# same references apart].
# References already in OUTDIR are reused (they are the slow part).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/bench-arguments.sh"
bench_arguments /tmp/vlf-relief "$@"
directions="${DIRECTIONS:-2049}"
rays="${RAYS:-32}"
size="${SIZE:-256}"
samples="${SAMPLES:-1024}"
scale="${DEPTH_SCALE:-0.05}"
supersampling="${SUPERSAMPLING:-2}"
gpu_method="gpu-${supersampling}x${supersampling}"
camera="${CAMERA:-278,273,-800,278,273,0}"
fov="${FOV:-39.3077}"
csv_dir="${CSV_DIR:-$source_dir/docs/measurements/relief-against-path-tracer}"
suffix="${LABEL_SUFFIX:-}"
scene="${SCENE:-cornell}"
surface="${SURFACE:-back}"
scene_args=()
if [ "$scene" != cornell ]; then
  scene="$(realpath "$scene")"
  scene_args=("$scene")
fi
# The rows' labels begin with the scene's file name without .obj and the surface
# ("cornell-back-..." by default).
label="$(basename "$scene" .obj)-$surface"
mkdir -p "$out/input" "$csv_dir"
cd "$out"
log() { echo "+ $*" >> commands.txt; }
# Runs a command, logging it; prints its wall time in seconds on stdout.
timed() {
  local name="$1"; shift
  log "$@"
  local start end
  start=$(date +%s.%N)
  if "$@" > "$name.log" 2>&1; then
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f\n", b - a }'
  else
    echo "step '$name' failed (see $out/$name.log):" >&2
    tail -3 "$name.log" >&2
    echo "FAILED"
  fi
}

# A procedural brick depth map: bricks at depth 0.05 with bevelled edges, mortar at depth 1.
python3 - "$out/input/bricks-depth.pgm" <<'EOF'
import sys
w = h = 256
rows, cols = 8, 4
mortar, bevel = 3.0, 6.0
data = bytearray()
for j in range(h - 1, -1, -1):  # PGM stores the top row first
    for i in range(w):
        r = j * rows / h
        row = int(r)
        x = (i + (0.5 if row % 2 else 0.0) * w / cols) % w
        c = x * cols / w
        # distance to the nearest mortar line, in pixels
        dy = min(r - row, row + 1 - r) * h / rows
        dx = min(c - int(c), int(c) + 1 - c) * w / cols
        d = min(dx, dy)
        if d < mortar:
            depth = 1.0
        elif d < mortar + bevel:
            depth = 0.05 + 0.95 * (1.0 - (d - mortar) / bevel)
        else:
            depth = 0.05
        data.append(int(round(depth * 255)))
with open(sys.argv[1], "wb") as f:
    f.write(b"P5\n%d %d\n255\n" % (w, h))
    f.write(bytes(data))
EOF
maps=("procedural-bricks:$out/input/bricks-depth.pgm")
real=/usr/share/games/redeclipse/data/wicked/highqualitybrickz.jpg
if [ -f "$real" ]; then
  # A height map (white = high): inverted to depth, the one convention both renderers read.
  oiiotool "$real" --ch R --invert -d uint8 -o input/redeclipse-bricks-depth.png
  maps+=("redeclipse-bricks:$out/input/redeclipse-bricks-depth.png")
else
  echo "note: redeclipse-data not installed; only the procedural map is measured"
fi

field="$out/$(basename "$scene" .obj)-$directions-$rays.vlf"
if [ ! -f "$field" ]; then
  t=$(timed propagate "$bin" vlf propagate "${scene_args[@]}" --out "$field" \
    --directions "$directions" --rays "$rays")
  echo "field: $directions directions, $rays rays per side, propagated in $t s"
fi

view=(--camera "$camera" --fov "$fov")
status=0
for entry in "${maps[@]}"; do
  name="${entry%%:*}"
  depth="${entry#*:}"
  relief=(--relief "$surface=$depth" --relief-depth-scale "$scale")
  echo "== $name"
  # References already in OUTDIR (same settings) are reused: they are the slow part.
  if [ -f "$name-reference.exr" ] && [ -f "$name-reference-2.exr" ] && [ -f "$name-mask.exr" ]; then
    echo "reusing $out/$name-reference*.exr and $name-mask.exr"
  else
    t_ref=$(timed "$name-reference" "$bin" trace --scene "$scene" "${relief[@]}" "${view[@]}" \
      --width "$size" --height "$size" --samples "$samples" --seed 1 --offscreen \
      --out "$name-reference.png" --exr "$name-reference.exr" --relief-mask "$name-mask.exr")
    t_ref2=$(timed "$name-reference-2" "$bin" trace --scene "$scene" "${relief[@]}" "${view[@]}" \
      --width "$size" --height "$size" --samples "$samples" --seed 2 --offscreen \
      --out "$name-reference-2.png" --exr "$name-reference-2.exr")
    echo "reference: $t_ref s, second reference: $t_ref2 s ($samples paths per pixel)"
    if [ "$t_ref" = FAILED ] || [ "$t_ref2" = FAILED ]; then status=1; continue; fi
  fi
  # The method as a user runs it: its frame time is the renderer's own figure.
  t=$(timed "$name-field" "$bin" vlf render "$field" "${relief[@]}" "${view[@]}" \
    --size "${size}x${size}" --out "$name-field.png" --exr "$name-field.exr" --force)
  if [ "$t" = FAILED ]; then status=1; continue; fi
  frame=$(sed -n 's/.*x[0-9]*, \([0-9.]*\) s, light field.*/\1/p' "$name-field.log")
  echo "vlf render --relief: ${frame:-?} s per ${size}x${size} frame"
  # The interactive GPU path (vtkReliefMapper, SH9 probes, the precomputed visible share, the
  # emitter lights with the scene's shadows), as `vlf view --relief` draws it, as linear EXR;
  # and without the occlusion (shown).
  gpu_images=""
  for variant in gpu "$gpu_method" gpu-unoccluded; do
    extra=()
    [ "$variant" = gpu-unoccluded ] && extra=(--relief-no-occlusion)
    [ "$variant" = "$gpu_method" ] && extra=(--supersampling "$supersampling")
    t=$(timed "$name-$variant" bash "$here/xvfb.sh" "$bin" vlf render "$field" --mode progressive \
      "${relief[@]}" "${extra[@]}" "${view[@]}" --size "${size}x${size}" --out "$name-$variant.png" \
      --exr "$name-$variant.exr" --force)
    [ "$t" = FAILED ] && status=1 || gpu_images="$gpu_images,$variant=$name-$variant.exr"
  done
  bench=(bench vlf-relief "$field" "${relief[@]}" "${view[@]}"
    --reference "$name-reference.exr" --reference-2 "$name-reference-2.exr"
    --mask "$name-mask.exr" --images "vlf-render=$name-field.exr$gpu_images"
    --times "vlf-render=${frame:-0}"
    --label "$label-$name-$directions-$samples$suffix" --write-images "$name"
    --csv "$csv_dir/relief-against-path-tracer.csv"
    --plot "$csv_dir/relief-against-path-tracer-$name.png")
  log "$bin" "${bench[@]}"
  # Under scripts/xvfb.sh: the plot is drawn by VTK's charts, which need a display.
  bash "$here/xvfb.sh" "$bin" "${bench[@]}" | tee "$name-bench.log"
  [ "${PIPESTATUS[0]}" -eq 0 ] || status=1
  # The GPU path as the method, against the same negative cases (written by the run above): its
  # image averaged over the pixel as the reference's is, and at one ray per pixel.
  for method in "$gpu_method" gpu; do
    [ -f "$name-$method.exr" ] || continue
    if [ "$method" = gpu ]; then
      echo "the GPU as the method at one ray per pixel"
    else
      echo "the GPU as the method: $method = --supersampling $supersampling (the mean of" \
        "$supersampling x $supersampling drawn pixels per pixel, as the reference averages its" \
        "paths over the pixel)"
    fi
    bench=(bench vlf-relief --reference "$name-reference.exr" --reference-2 "$name-reference-2.exr"
      --mask "$name-mask.exr"
      --images "$method=$name-$method.exr,flat-wall=$name-flat-wall.exr,one-light=$name-one-light.exr"
      --label "$label-$name-$method-$directions-$samples$suffix"
      --csv "$csv_dir/relief-against-path-tracer.csv")
    log "$bin" "${bench[@]}"
    "$bin" "${bench[@]}" | tee "$name-$method-bench.log"
  done
done
# The field's own error on the flat wall (no relief) over the first map's relief pixels.
first="${maps[0]%%:*}"
if [ -f "$first-mask.exr" ]; then
  if [ ! -f flat-reference.exr ]; then
    timed flat-reference "$bin" trace --scene "$scene" "${view[@]}" --width "$size" \
      --height "$size" --samples "$samples" --seed 1 --offscreen --out flat-reference.png \
      --exr flat-reference.exr > /dev/null
  fi
  timed flat-field "$bin" vlf render "$field" "${view[@]}" --size "${size}x${size}" \
    --out flat-field.png --exr flat-field.exr --force > /dev/null
  if [ -f flat-reference.exr ] && [ -f flat-field.exr ]; then
    echo "== the flat wall (no relief), over the $first relief's pixels"
    bench=(bench vlf-relief --reference flat-reference.exr --mask "$first-mask.exr"
      --images "flat-wall-field=flat-field.exr" --label "$label-flat-$directions-$samples$suffix"
      --csv "$csv_dir/relief-against-path-tracer.csv")
    log "$bin" "${bench[@]}"
    "$bin" "${bench[@]}" | tee flat-bench.log
  fi
fi
echo "commands in $out/commands.txt"
exit $status
