#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A relief lit by the light field, measured against the truth: the Cornell box with a relief on
# its back wall, rendered
#   - by the light field (`vlf render FIELD --relief back=DEPTH --exr`, the method),
#   - by the path tracer on the dense displaced mesh of the same relief, same camera (`trace
#     --scene cornell --relief back=DEPTH --exr`, the reference; twice, with other random paths,
#     so the reference's own noise is printed beside the errors), with the relief's pixel mask,
#   - and the two negative cases: the relief lit by the flat wall's field value, and by
#     hand-placed VTK lights,
# then `mesolight bench vlf-relief` prints the mean relative error per relief pixel of each, the
# goal (<= 8% at 2049 directions, >= 2x better than both negatives) and the cost ratio of a
# relief pixel lit by the field vs one lit by a VTK light with shadows, and appends the rows to
# docs/measurements/vlf-relief/vlf-relief.csv with a plot per map.
#
#   scripts/bench-vlf-relief.sh MESOLIGHT_BINARY OUTDIR
#
# Depth maps: a procedural brick map (written here) and, when the Debian package redeclipse-data
# is installed, its brick height map (wicked/highqualitybrickz.jpg, inverted to depth); skipped
# when absent. Settings through the environment (defaults in brackets): DIRECTIONS [2049], RAYS
# [32] (the field), SIZE [256] (square images), SAMPLES [1024] (paths per pixel of the
# reference), DEPTH_SCALE [0.05], CAMERA [278,273,-800,278,273,0, the published Cornell camera],
# FOV [39.3077], CSV_DIR [docs/measurements/vlf-relief under the source tree].
#
# The light-field side's options are those of `mesolight vlf render --relief`: FIELD_MODE
# [unset: the command's default], FLAT_OPTION [--relief-lighting flat] for the first negative
# case and VTK_LIGHTS_OPTION [--relief-lighting vtk-light] for the second; a step whose command
# fails (e.g. an option that renderer does not have) is reported and left out of the comparison.
set -u
bin="$(realpath "$1")"
out="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source_dir="$(dirname "$here")"
directions="${DIRECTIONS:-2049}"
rays="${RAYS:-32}"
size="${SIZE:-256}"
samples="${SAMPLES:-1024}"
scale="${DEPTH_SCALE:-0.05}"
camera="${CAMERA:-278,273,-800,278,273,0}"
fov="${FOV:-39.3077}"
csv_dir="${CSV_DIR:-$source_dir/docs/measurements/vlf-relief}"
flat_option="${FLAT_OPTION:---relief-lighting flat}"
vtk_option="${VTK_LIGHTS_OPTION:---relief-lighting vtk-light}"
mode_option=()
if [ -n "${FIELD_MODE:-}" ]; then mode_option=(--mode "$FIELD_MODE"); fi
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
    echo "$end - $start" | bc -l
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

field="$out/cornell-$directions.vlf"
if [ ! -f "$field" ]; then
  t=$(timed propagate "$bin" vlf propagate --out "$field" --directions "$directions" --rays "$rays")
  echo "field: $directions directions, $rays rays per side, propagated in $t s"
fi

view=(--camera "$camera" --fov "$fov")
status=0
for entry in "${maps[@]}"; do
  name="${entry%%:*}"
  depth="${entry#*:}"
  relief=(--relief "back=$depth" --relief-depth-scale "$scale")
  echo "== $name"
  t_ref=$(timed "$name-reference" "$bin" trace --scene cornell "${relief[@]}" "${view[@]}" \
    --width "$size" --height "$size" --samples "$samples" --seed 1 --offscreen \
    --out "$name-reference.png" --exr "$name-reference.exr" --relief-mask "$name-mask.exr")
  t_ref2=$(timed "$name-reference-2" "$bin" trace --scene cornell "${relief[@]}" "${view[@]}" \
    --width "$size" --height "$size" --samples "$samples" --seed 2 --offscreen \
    --out "$name-reference-2.png" --exr "$name-reference-2.exr")
  echo "reference: $t_ref s, second reference: $t_ref2 s ($samples paths per pixel)"
  if [ "$t_ref" = FAILED ] || [ "$t_ref2" = FAILED ]; then status=1; continue; fi
  images=()
  times=()
  # The method and the negative cases; each kept only if its renderer ran.
  for variant in field flat vtk-light; do
    extra=()
    case $variant in
      flat) read -r -a extra <<< "$flat_option" ;;
      vtk-light) read -r -a extra <<< "$vtk_option" ;;
    esac
    t=$(timed "$name-$variant" "$bin" vlf render "$field" "${mode_option[@]}" "${relief[@]}" \
      "${extra[@]}" "${view[@]}" --size "${size}x${size}" --out "$name-$variant.png" \
      --exr "$name-$variant.exr" --force)
    if [ "$t" != FAILED ]; then
      images+=("$variant=$name-$variant.exr")
      times+=("$variant=$t")
    elif [ "$variant" = field ]; then
      status=1
    fi
  done
  if [ ${#images[@]} -eq 0 ]; then
    echo "no light-field rendering of $name: only the reference and the mask were made"
    continue
  fi
  joined_images=$(IFS=,; echo "${images[*]}")
  joined_times=$(IFS=,; echo "${times[*]}")
  log "$bin" bench vlf-relief ...
  "$bin" bench vlf-relief --reference "$name-reference.exr" --reference-2 "$name-reference-2.exr" \
    --mask "$name-mask.exr" --images "$joined_images" --times "$joined_times" \
    --cost-pair field,vtk-light --label "cornell-back-$name-$directions" \
    --csv "$csv_dir/vlf-relief.csv" --plot "$csv_dir/vlf-relief-$name.png" | tee "$name-bench.log"
  [ "${PIPESTATUS[0]}" -eq 0 ] || status=1
done
echo "commands in $out/commands.txt"
exit $status
