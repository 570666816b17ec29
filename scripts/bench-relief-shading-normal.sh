#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The relief mapper's brightness against the exact CPU renderer on real height maps with detail a
# texel or two wide: the shading normal's bias. Real game height maps from Debian's
# redeclipse-data (luckystrike/paris_wall_b.jpg at 512^2 and box-filtered to 256^2,
# dziq/brick_wall01_b.jpg), white = high, depth scale 0.05, on the back wall of the Cornell box lit
# by its light field, drawn by the walkthrough's relief mapper (`vlf render --mode progressive
# --relief back=...`, one ray per pixel and 4 x 4 per pixel) and by the CPU reference (`vlf render
# --relief`: exact first hits, the bilinear surface's own normal). Per map and rays per pixel: the
# GPU's mean linear radiance over the relief's pixels divided by the CPU's (1 = no bias). The
# relief's pixels: where the CPU relief differs from the flat wall, closed by 3 pixels and eroded
# by 7 (its border left out). A table on stdout, rows appended to
# docs/measurements/relief-shading-normal/relief-shading-normal.csv.
#
#   scripts/bench-relief-shading-normal.sh MESOLIGHT_BINARY OUTDIR
#
# Settings through the environment: DIRECTIONS [513], RAYS [16], ITERATIONS [3] (the field), SIZE
# [256] (square images), LABEL [the host name].
set -u
source "$(dirname "${BASH_SOURCE[0]}")/bench-arguments.sh"
bench_arguments /tmp/shading-normal "$@"
directions="${DIRECTIONS:-513}"
rays="${RAYS:-16}"
iterations="${ITERATIONS:-3}"
size="${SIZE:-256}"
label="${LABEL:-$(hostname)}"
maps_dir=/usr/share/games/redeclipse/data
csv_dir="$source_dir/docs/measurements/relief-shading-normal"
for map in luckystrike/paris_wall_b.jpg dziq/brick_wall01_b.jpg; do
  if [ ! -f "$maps_dir/$map" ]; then
    echo "$maps_dir/$map is absent: install redeclipse-data (MESOLIGHT_REAL_MAPS=1" \
      "scripts/setup.sh)" >&2
    exit 2
  fi
done
mkdir -p "$out" "$csv_dir" || exit 2
cd "$out" || exit 2

oiiotool "$maps_dir/luckystrike/paris_wall_b.jpg" --ch 0 -d uint8 -o paris512.png &&
  oiiotool "$maps_dir/luckystrike/paris_wall_b.jpg" --ch 0 --resize 256x256 -d uint8 \
    -o paris256.png &&
  oiiotool "$maps_dir/dziq/brick_wall01_b.jpg" --ch 0 -d uint8 -o brick.png || exit 1
"$bin" vlf propagate --directions "$directions" --rays "$rays" --iterations "$iterations" \
  --out cornell.vlf --force > propagate.log 2>&1 || { cat propagate.log; exit 1; }
view=(--size "${size}x${size}")
"$bin" vlf render cornell.vlf "${view[@]}" --exr flat.exr --out flat.png --force > flat.log 2>&1 ||
  { cat flat.log; exit 1; }

# The mean of each channel of IMAGE over MASK's pixels, averaged over the channels.
masked_mean() {
  local m
  m=$(oiiotool --stats "$2" | sed -n 's/.*Stats Avg: *\([0-9.e+-]*\).*/\1/p' | head -n 1)
  oiiotool "$1" --ch R,G,B "$2" --ch 0,0,0 --chnames R,G,B --mul --printstats |
    sed -n 's/.*Stats Avg: *//p' | head -n 1 | awk -v m="$m" '{ print ($1 + $2 + $3) / (3 * m) }'
}

csv="$csv_dir/relief-shading-normal.csv"
[ -f "$csv" ] || echo "label,map,size,rays_per_pixel,gpu_over_cpu" > "$csv"
printf '%-10s %-15s %s\n' map "rays per pixel" "GPU / CPU mean radiance"
status=0
for map in paris256 paris512 brick; do
  relief=(--relief back="$map.png" --relief-height --relief-depth-scale 0.05)
  if ! "$bin" vlf render cornell.vlf "${view[@]}" "${relief[@]}" --exr "$map-cpu.exr" \
    --out "$map-cpu.png" --force > "$map-cpu.log" 2>&1; then
    cat "$map-cpu.log"
    status=1
    continue
  fi
  oiiotool flat.exr "$map-cpu.exr" --absdiff --maxchan --mulc 1e6 --clamp:min=0:max=1 \
    --dilate 3x3 --erode 7x7 -o "$map-mask.exr" > /dev/null 2>&1 || { status=1; continue; }
  cpu=$(masked_mean "$map-cpu.exr" "$map-mask.exr")
  for s in 1 4; do
    if ! bash "$here/xvfb.sh" "$bin" vlf render cornell.vlf --mode progressive "${view[@]}" \
      "${relief[@]}" --supersampling "$s" --exr "$map-gpu-$s.exr" --out "$map-gpu-$s.png" \
      --force > "$map-gpu-$s.log" 2>&1; then
      cat "$map-gpu-$s.log"
      status=1
      continue
    fi
    ratio=$(awk -v g="$(masked_mean "$map-gpu-$s.exr" "$map-mask.exr")" -v c="$cpu" \
      'BEGIN { printf "%.4f", g / c }')
    printf '%-10s %-15s %s\n' "$map" "$((s * s))" "$ratio"
    echo "$label,$map,$size,$((s * s)),$ratio" >> "$csv"
  done
done
exit $status
