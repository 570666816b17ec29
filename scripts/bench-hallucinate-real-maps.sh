#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench hallucinate` on real height maps: the eight game textures' height ("z") maps
# of scripts/bench-relief-real-maps.sh plus a fine perforated grate, from Debian's
# redeclipse-data (512^2, white = high, hence --height), each displaced as a dense mesh 32 texels
# deep and path-traced under an overcast sky and with a flash at the camera. Prints per map the
# default's correlation with the true depth, the automatic layer choice, the old default, the best
# fixed layer count and both naive baselines (1 - diffuse luminance; the diffuse/flash ratio).
# The package is large (about 860 MB): `MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh` installs
# it. Without it this script says so and exits 0.
#
# Usage: scripts/bench-hallucinate-real-maps.sh OUTPUT.txt [extra bench hallucinate options]
#   (the table goes to OUTPUT.txt, the rows to OUTPUT.csv, the summary to OUTPUT-summary.csv,
#   the chart to OUTPUT.png), e.g.
#   scripts/bench-hallucinate-real-maps.sh docs/measurements/hallucination/real-maps.txt
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
data=/usr/share/games/redeclipse/data
maps=(dziq/brick_wall01_b.jpg dziq/dq_stones01_b.jpg dziq/metal_rusty01a_b.jpg
  jojo/concrete05_z.png jojo/redrock01_z.png jojo/windowstile_z.png mikeplus64/decktiles_z.png
  luckystrike/paris_wall_z.jpg unnamed/grate01_z.png)
list=""
for m in "${maps[@]}"; do
  if [ ! -f "$data/$m" ]; then
    echo "[mesolight] skipped: $data/$m is absent (MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh installs redeclipse-data)"
    exit 0
  fi
  list="${list:+$list,}$data/$m:32"
done
out="${1:-}"
if [ -z "$out" ]; then
  echo "usage: $0 OUT.txt [bench hallucinate options], e.g. docs/measurements/hallucination/real-maps.txt" >&2
  exit 2
fi
shift
prefix="${out%.txt}"
mkdir -p "$(dirname "$prefix")"
"$here/scripts/xvfb.sh" "$here/build/bin/mesolight" bench hallucinate --maps "$list" --height \
  --sweep 1,2,3,4,5,6,7,8,9 --csv "$prefix.csv" --plot "$prefix.png" "$@" > "$prefix.txt"
echo "wrote $prefix.txt, $prefix.csv, $prefix-summary.csv and $prefix.png"
