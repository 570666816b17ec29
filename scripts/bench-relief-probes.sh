#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# What the relief's SH9 probe count costs and buys on a large surface: a flat relief (depth 0) on
# the ground of examples/data/town.obj (10-12 m buildings on a 200 m ground, a 40 m sky panel),
# drawn by the walkthrough's relief mapper (`vlf render --mode progressive --relief
# ground=... --relief-probes N`) against the CPU reference of the same view (`vlf render
# --relief`: a shadow ray per emitter sample per pixel). Per probe count (8, 16, 32, the automatic
# choice, 64): the set-up seconds the tool prints (probes and the emitter lights' scene factors,
# once per field and surface, not per frame; the median of REPEATS runs) and the mean |GPU - CPU|
# over the image in thousandths of the reference's mean (the scene's shadows on the ground: 8
# probes a side, 25 m apart, average them away). A table on stdout, rows appended to
# docs/measurements/relief-probes/relief-probes.csv.
#
#   scripts/bench-relief-probes.sh MESOLIGHT_BINARY OUTDIR
#
# Settings through the environment: DIRECTIONS [513], RAYS [32], ITERATIONS [2] (the field),
# SIZE [96] (square images), REPEATS [3], LABEL [the host name].
set -u
source "$(dirname "${BASH_SOURCE[0]}")/bench-arguments.sh"
bench_arguments /tmp/probes "$@"
directions="${DIRECTIONS:-513}"
rays="${RAYS:-32}"
iterations="${ITERATIONS:-2}"
size="${SIZE:-96}"
repeats="${REPEATS:-3}"
label="${LABEL:-$(hostname)}"
csv_dir="$source_dir/docs/measurements/relief-probes"
mkdir -p "$out" "$csv_dir" || exit 2
cd "$out" || exit 2

printf 'P2\n2 2\n255\n0 0\n0 0\n' > zero.pgm
"$bin" vlf propagate "$source_dir/examples/data/town.obj" --directions "$directions" \
  --rays "$rays" --iterations "$iterations" --out town.vlf --force > propagate.log 2>&1 ||
  { cat propagate.log; exit 1; }
view=(--size "${size}x${size}" --camera 70,-90,45,0,0,5,0,0,1 --relief ground=zero.pgm)
"$bin" vlf render town.vlf "${view[@]}" --exr cpu.exr --out cpu.png --force > cpu.log 2>&1 ||
  { cat cpu.log; exit 1; }
mean() { oiiotool --stats "$1" | sed -n 's/.*Stats Avg: *\([0-9.e+-]*\).*/\1/p' | head -n 1; }
reference=$(mean cpu.exr)

csv="$csv_dir/relief-probes.csv"
[ -f "$csv" ] || echo "label,directions,rays,size,probes_requested,probes_used,setup_s,error_per_mille" > "$csv"
printf '%-10s %-8s %-14s %s\n' requested used "set-up s" "mean |GPU - CPU| / CPU mean"
status=0
for probes in 8 16 32 0 64; do
  times=()
  used=?
  for ((r = 0; r < repeats; ++r)); do
    if ! bash "$here/xvfb.sh" "$bin" vlf render town.vlf --mode progressive "${view[@]}" \
      --relief-probes "$probes" --exr "gpu-$probes.exr" --out "gpu-$probes.png" --force \
      > "gpu-$probes.log" 2>&1; then
      cat "gpu-$probes.log"
      status=1
      continue 2
    fi
    line=$(grep "relief on 'ground'" "gpu-$probes.log")
    used=$(echo "$line" | sed -n 's/.*: \([0-9]*\) x .*/\1/p')
    times+=("$(echo "$line" | sed -n 's/.*set up in \([0-9.e+-]*\) s.*/\1/p')")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -g | sed -n "$(((${#times[@]} + 1) / 2))p")
  oiiotool "gpu-$probes.exr" cpu.exr --absdiff -o "diff-$probes.exr"
  error=$(awk -v d="$(mean "diff-$probes.exr")" -v r="$reference" 'BEGIN { printf "%.1f", 1000 * d / r }')
  requested=$probes
  [ "$probes" = 0 ] && requested=automatic
  printf '%-10s %-8s %-14s %s/1000\n' "$requested" "$used" "$median" "$error"
  echo "$label,$directions,$rays,$size,$requested,$used,$median,$error" >> "$csv"
done
echo "rows appended to $csv"
exit $status
