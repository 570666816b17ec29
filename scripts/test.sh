#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Sets up (packages, build) and runs the whole test suite. GL tests render with Mesa llvmpipe
# under Xvfb (scripts/xvfb.sh). Extra arguments go to ctest (e.g. -R Relief, -L GL). Then builds
# the ParaView plugin (scripts/setup-paraview.sh, ./build-paraview) and runs its pvbatch tests,
# serial and MPI; MESOLIGHT_SKIP_PARAVIEW=1 skips that part. Then the sanitizer stage
# (docs/fuzzing.md): the algorithm cores' unit tests and the fuzz corpus replays built with
# AddressSanitizer + UndefinedBehaviorSanitizer without VTK (scripts/sanitize-cores.sh), and every
# libFuzzer target for MESOLIGHT_CI_FUZZ_SECONDS (default 10) each (scripts/fuzz.sh);
# MESOLIGHT_SKIP_SANITIZE=1 skips it.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_BUILD_DIR:-$here/build}"
# The relief tests on real height maps (redeclipse-data, about 860 MB;
# tests/support/RealHeightMaps.h) run here, not only where someone installed the maps: the package
# is installed with the others, and a test whose map is missing fails instead of skipping.
export MESOLIGHT_REAL_MAPS=1 MESOLIGHT_REQUIRE_REAL_MAPS=1
bash "$here/scripts/setup.sh"

status=0
# Each ctest's output is kept (tee) so that the end of this script can repeat why it failed: a
# ctest that stops before running tests (a test list that cannot be read) names no failed test.
main_log="$build/Testing/ctest-output.log"
paraview_build="${MESOLIGHT_PARAVIEW_BUILD_DIR:-$here/build-paraview}"
paraview_log="$paraview_build/Testing/ctest-output.log"
rm -f "$build/Testing/Temporary/LastTestsFailed.log"
mkdir -p "$build/Testing"
main_status=0
bash "$here/scripts/xvfb.sh" \
  ctest --test-dir "$build" --output-on-failure --timeout 600 "$@" 2>&1 | tee "$main_log" ||
  main_status=$?
[ "$main_status" -eq 0 ] || status=$main_status

paraview_status=skipped
if [ "${MESOLIGHT_SKIP_PARAVIEW:-0}" != "1" ]; then
  bash "$here/scripts/setup-paraview.sh"
  rm -f "$paraview_build/Testing/Temporary/LastTestsFailed.log"
  mkdir -p "$paraview_build/Testing"
  paraview_status=0
  bash "$here/scripts/xvfb.sh" \
    ctest --test-dir "$paraview_build" --output-on-failure --timeout 600 2>&1 |
    tee "$paraview_log" || paraview_status=$?
  [ "$paraview_status" -eq 0 ] || status=$paraview_status
fi

sanitize_status=skipped
fuzz_status=skipped
sanitize_build="${MESOLIGHT_SANITIZE_CORES_BUILD_DIR:-$here/build-sanitize-cores}"
sanitize_log="$sanitize_build/stage.log"
fuzz_log="${MESOLIGHT_FUZZ_BUILD_DIR:-$here/build-fuzz}/stage.log"
if [ "${MESOLIGHT_SKIP_SANITIZE:-0}" != "1" ]; then
  mkdir -p "$(dirname "$sanitize_log")" "$(dirname "$fuzz_log")"
  sanitize_status=0
  bash "$here/scripts/sanitize-cores.sh" 2>&1 |
    tee "$sanitize_log" || sanitize_status=$?
  [ "$sanitize_status" -eq 0 ] || status=$sanitize_status
  fuzz_status=0
  bash "$here/scripts/fuzz.sh" "${MESOLIGHT_CI_FUZZ_SECONDS:-10}" 2>&1 |
    tee "$fuzz_log" || fuzz_status=$?
  [ "$fuzz_status" -eq 0 ] || status=$fuzz_status
fi

# CI shows the end of this script's output: repeat there which tests failed, with the end of what
# each printed (ctest's logs keep all of it), or, when ctest named no failed test, its errors.
echo "[mesolight] main tests: exit $main_status; ParaView plugin tests: exit $paraview_status;" \
  "sanitizers (cores, replays): exit $sanitize_status; fuzzing: exit $fuzz_status"
report() { # report <build dir> <exit status of its ctest>
  local dir="$1" code="$2" failed="$1/Testing/Temporary/LastTestsFailed.log"
  [ "$code" != 0 ] && [ "$code" != skipped ] || return 0
  if [ ! -s "$failed" ]; then
    echo "==== ctest in $dir named no failed test; what it reported:"
    grep -n -A8 "CMake Error\|Errors while running\|No tests were found" \
      "$dir/Testing/ctest-output.log" | head -n 60 || tail -n 30 "$dir/Testing/ctest-output.log"
    return 0
  fi
  echo "==== failed in $dir:"
  cat "$failed"
  while IFS=: read -r _ name; do
    echo "==== last lines of $name:"
    awk -v t="Test: $name" '!on && substr($0, length($0) - length(t) + 1) == t {on = 1}
      on {print} on && /^Test time =/ {exit}' \
      "$dir/Testing/Temporary/LastTest.log" | tail -n 40
  done < "$failed"
}
report "$build" "$main_status"
report "$paraview_build" "$paraview_status"
if [ "$sanitize_status" != 0 ] && [ "$sanitize_status" != skipped ]; then
  echo "==== sanitizer stage (log: $sanitize_log):"
  grep -E "SUMMARY: |runtime error|The following tests FAILED|^\s+[0-9]+ - |error:" \
    "$sanitize_log" | head -n 40 || tail -n 30 "$sanitize_log"
fi
if [ "$fuzz_status" != 0 ] && [ "$fuzz_status" != skipped ]; then
  echo "==== fuzzing (log: $fuzz_log):"
  grep -E "^\[fuzz\]|input: |ERROR|error:" "$fuzz_log" | tail -n 40
fi
exit $status
