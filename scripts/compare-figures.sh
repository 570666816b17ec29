#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Compares two directories written by scripts/deterministic-figures.sh; exit 0 if identical.
#   scripts/compare-figures.sh DIR_A DIR_B
set -u
a="$1"; b="$2"; ok=1
for f in "$a"/*.exr; do
  n=$(basename "$f"); r=$(idiff -fail 0 -warn 0 -a "$f" "$b/$n" 2>&1 | tail -1)
  echo "$n: $r"; [ "$r" = PASS ] || ok=0
done
for f in "$a"/lights-*.csv; do
  n=$(basename "$f")
  if cmp -s "$f" "$b/$n"; then echo "$n: identical"; else echo "$n: DIFFERENT"; ok=0; fi
done
# Every column but the two timings (ms_per_frame, first_frame_ms).
strip() { cut -d, -f1-9,12- "$1"; }
rows=$(($(wc -l < "$a/relief-sweep.csv") - 1))
if diff <(strip "$a/relief-sweep.csv") <(strip "$b/relief-sweep.csv") > /dev/null; then
  echo "relief-sweep.csv: $rows configurations identical but for the ms columns"
else echo "relief-sweep.csv: DIFFERENT"; ok=0; fi
energies() { grep -o 'iteration [0-9]*: [0-9.]* s, .*' "$1" | sed 's/: [0-9.]* s,/:/'; }
if diff <(energies "$a/vlf-propagate.log") <(energies "$b/vlf-propagate.log") > /dev/null; then
  echo "light-field energies: identical"; energies "$a/vlf-propagate.log"
else echo "light-field energies: DIFFERENT"; ok=0; fi
# A snapshot differs run to run only in its header (time, checksum) and per-iteration timings.
header=48
nd=$(cmp -l "$a/field.vlf" "$b/field.vlf" | awk -v h=$header '$1 > h' | wc -l)
echo "field.vlf: $nd bytes differ after the header (3 iterations x 7 bytes of timing records are expected)"
if cmp -s "$a/field.png" "$b/field.png"; then echo "field.png: identical"; else echo "field.png: DIFFERENT"; ok=0; fi
[ $ok = 1 ] && echo "ALL IDENTICAL" || echo "SOME DIFFER"
[ $ok = 1 ]
