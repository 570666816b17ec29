#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench hallucinate` on real height maps: the eight game textures' height ("z") maps
# of scripts/bench-relief-real-maps.sh plus a fine perforated grate, from Debian's
# redeclipse-data (512^2, white = high, hence --height), each displaced as a dense mesh 32 texels
# deep and path-traced under an overcast sky and with a flash at the camera. Prints per map the
# default's correlation with the true depth (the ratio model, its layers from the ratio image's
# feature size) and that autocorrelation length, the previous default (the ratio's scale average,
# --layers average), the one before (the shading's scale average, --model shading), the
# automatic layer choice, the old default, the best fixed layer count and both naive baselines
# (1 - diffuse luminance; the diffuse/flash ratio).
# The package is large (about 860 MB): `MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh` installs
# it. Without it this script says so and exits 0.
#
# Two sets: the nine maps the default was chosen on (OUTPUT.txt), and nine held out, chosen by a
# rule before they were measured (OUTPUT-heldout.txt): the 512^2 height maps of the package
# (*_z.*, *_b.*, torley's excluded), less the nine, in sorted order, every 8th from the 4th.
# MESOLIGHT_HALLUCINATION_PHOTOS=DIR keeps the rendered photographs there (--photos) and, when
# they are already there, reads them instead of rendering (--from-photos; about 25 min for the
# 18 maps otherwise).
#
# Usage: scripts/bench-hallucinate-real-maps.sh OUTPUT.txt [extra bench hallucinate options]
#   (the tables go to OUTPUT.txt and OUTPUT-heldout.txt, the rows to OUTPUT*.csv, the summaries
#   to OUTPUT*-summary.csv, the charts to OUTPUT*.png), e.g.
#   scripts/bench-hallucinate-real-maps.sh docs/measurements/hallucination/real-maps.txt
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
data=/usr/share/games/redeclipse/data
chosen=(dziq/brick_wall01_b.jpg dziq/dq_stones01_b.jpg dziq/metal_rusty01a_b.jpg
  jojo/concrete05_z.png jojo/redrock01_z.png jojo/windowstile_z.png mikeplus64/decktiles_z.png
  luckystrike/paris_wall_z.jpg unnamed/grate01_z.png)
heldout=(dziq/dryone_b.jpg jojo/concrete03_z.png jojo/concrete12_z.png jojo/redrock03_z.png
  luckystrike/paris_wall_b_z.jpg unnamed/darkness_tile01_z.png unnamed/stone01-c_z.png
  unnamed/tile09_grate_z.png unnamed/wall01-b_z.png)
out="${1:-}"
if [ -z "$out" ]; then
  echo "usage: $0 OUT.txt [bench hallucinate options], e.g. docs/measurements/hallucination/real-maps.txt" >&2
  exit 2
fi
shift
for m in "${chosen[@]}" "${heldout[@]}"; do
  if [ ! -f "$data/$m" ]; then
    echo "[mesolight] skipped: $data/$m is absent (MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh installs redeclipse-data)"
    exit 0
  fi
done
prefix="${out%.txt}"
mkdir -p "$(dirname "$prefix")"
photos="${MESOLIGHT_HALLUCINATION_PHOTOS:-}"
run() { # run OUTPUT-PREFIX MAP...
  local p="$1" list="" m photo_options=()
  shift
  for m in "$@"; do
    list="${list:+$list,}$data/$m:32"
  done
  if [ -n "$photos" ]; then
    mkdir -p "$photos"
    local stem
    stem="$(basename "${1%.*}")"
    if [ -f "$photos/$stem-diffuse.exr" ]; then
      photo_options=(--from-photos "$photos")
    else
      photo_options=(--photos "$photos")
    fi
  fi
  "$here/scripts/xvfb.sh" "$here/build/bin/mesolight" bench hallucinate --maps "$list" --height \
    --sweep 1,2,3,4,5,6,7,8,9 --csv "$p.csv" --plot "$p.png" "${photo_options[@]}" \
    ${BENCH_OPTIONS:-} > "$p.txt"
  echo "wrote $p.txt, $p.csv, $p-summary.csv and $p.png"
}
BENCH_OPTIONS="$*" run "$prefix" "${chosen[@]}"
BENCH_OPTIONS="$*" run "$prefix-heldout" "${heldout[@]}"
