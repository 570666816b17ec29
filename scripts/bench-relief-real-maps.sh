#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench relief` on eight real height maps: game textures' height ("z") maps from
# Debian's redeclipse-data (brick, stones, rusty metal, concrete, rock, window panels, deck
# tiles, a plaster wall; 512^2, white = high, hence --height). The package is large (about
# 860 MB), so it is not in the default install: `MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh`
# installs it. Without it this script says so and exits 0.
#
# Usage: scripts/bench-relief-real-maps.sh OUTPUT.txt [extra bench relief options]
#   (the table and summary go to OUTPUT.txt, the rows to OUTPUT.csv, the charts beside them as
#   OUTPUT-view<ANGLE>.png, so runs written to one folder keep their own charts)
#   e.g. scripts/bench-relief-real-maps.sh docs/measurements/relief-real-maps/relief-real-maps.txt \
#          --methods default,relief,relaxed-cone,max-mipmap --steps 8+8,10+8,16+8,32+8,64+8,128+8
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
data=/usr/share/games/redeclipse/data
maps=(dziq/brick_wall01_b.jpg dziq/dq_stones01_b.jpg dziq/metal_rusty01a_b.jpg
  jojo/concrete05_z.png jojo/redrock01_z.png jojo/windowstile_z.png mikeplus64/decktiles_z.png
  luckystrike/paris_wall_z.jpg)
list=""
for m in "${maps[@]}"; do
  if [ ! -f "$data/$m" ]; then
    echo "[mesolight] skipped: $data/$m is absent (MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh installs redeclipse-data)"
    exit 0
  fi
  list="${list:+$list,}$data/$m"
done
out="${1:-}"
if [ -z "$out" ]; then
  echo "usage: $0 OUT.txt [bench relief options], e.g. docs/measurements/relief-real-maps/relief-real-maps.txt" >&2
  exit 2
fi
shift
prefix="${out%.txt}"
mkdir -p "$(dirname "$prefix")"
charts="$(mktemp -d)"
trap 'rm -rf "$charts"' EXIT
"$here/scripts/xvfb.sh" "$here/build/bin/mesolight" bench relief --maps file --depth-file "$list" \
  --height --angles 45,70,85 --frames 3 --csv "$prefix.csv" --plots "$charts" "$@" \
  > "$prefix.txt"
for chart in "$charts"/relief-sweep-view*.png; do
  if [ -f "$chart" ]; then mv "$chart" "$prefix-${chart##*/relief-sweep-}"; fi
done
echo "wrote $prefix.txt, $prefix.csv and $prefix-view*.png"
