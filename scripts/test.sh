#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Sets up (packages, build) and runs the whole test suite. GL tests render with Mesa llvmpipe
# under Xvfb (scripts/xvfb.sh). Extra arguments go to ctest (e.g. -R Relief, -L GL). Then builds
# the ParaView plugin (scripts/setup-paraview.sh, ./build-paraview) and runs its pvbatch tests,
# serial and MPI; MESOLIGHT_SKIP_PARAVIEW=1 skips that part.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_BUILD_DIR:-$here/build}"
bash "$here/scripts/setup.sh"

status=0
bash "$here/scripts/xvfb.sh" \
  ctest --test-dir "$build" --output-on-failure --timeout 600 "$@" || status=$?

if [ "${MESOLIGHT_SKIP_PARAVIEW:-0}" != "1" ]; then
  bash "$here/scripts/setup-paraview.sh"
  bash "$here/scripts/xvfb.sh" \
    ctest --test-dir "${MESOLIGHT_PARAVIEW_BUILD_DIR:-$here/build-paraview}" --output-on-failure \
    --timeout 600 || status=$?
fi

# CI shows the end of this script's output: repeat there which tests failed, with the end of what
# each printed (ctest's logs keep all of it).
if [ "$status" -ne 0 ]; then
  for dir in "$build" "${MESOLIGHT_PARAVIEW_BUILD_DIR:-$here/build-paraview}"; do
    failed="$dir/Testing/Temporary/LastTestsFailed.log"
    [ -s "$failed" ] || continue
    echo "==== failed in $dir:"
    cat "$failed"
    while IFS=: read -r _ name; do
      echo "==== last lines of $name:"
      awk -v t="Test: $name" '!on && substr($0, length($0) - length(t) + 1) == t {on = 1}
        on {print} on && /^Test time =/ {exit}' \
        "$dir/Testing/Temporary/LastTest.log" | tail -n 40
    done < "$failed"
  done
fi
exit $status
