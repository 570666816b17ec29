#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The sanitizer stage of scripts/test.sh (docs/fuzzing.md): builds the plain C++ algorithm cores,
# their unit tests that need no VTK and the fuzz corpus replays with AddressSanitizer +
# UndefinedBehaviorSanitizer in ./build-sanitize-cores (-DMESOLIGHT_CORES_ONLY=ON: no VTK, a few
# minutes cold where the whole suite under the sanitizers, scripts/sanitize.sh, takes about 40) and
# runs them. Extra arguments go to ctest (e.g. -R LightField). Any sanitizer report fails its test.
#   MESOLIGHT_SANITIZE_CORES_BUILD_DIR   build directory (default: ./build-sanitize-cores)
#   MESOLIGHT_JOBS                       build jobs (default: nproc)
#   MESOLIGHT_SANITIZE_CORES_SLOW=1      also run the tests labelled slow (about 13 minutes more)
#   MESOLIGHT_SANITIZE_CANARY=1          also build and run sanitizer_canary, a program with a
#                                        deliberate heap overflow and signed overflow: the stage
#                                        must then fail (the check that findings do fail it)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_SANITIZE_CORES_BUILD_DIR:-$here/build-sanitize-cores}"

launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)
cmake -S "$here" -B "$build" "${generator[@]}" "${launcher[@]}" -DMESOLIGHT_CORES_ONLY=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMESOLIGHT_SANITIZE=address,undefined \
  -DMESOLIGHT_WARNINGS_AS_ERRORS=ON \
  -DMESOLIGHT_SANITIZER_CANARY="${MESOLIGHT_SANITIZE_CANARY:-0}" > /dev/null
cmake --build "$build" --parallel "${MESOLIGHT_JOBS:-$(nproc)}"

# Leaks are reported too: the cores own their memory through RAII and link no VTK or TBB
# singletons. halt_on_error/abort_on_error: the first report ends the test program, so it fails.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The tests labelled slow (tests/cores/CMakeLists.txt: over 10 s each here) only on request.
skip=(-LE slow)
[ "${MESOLIGHT_SANITIZE_CORES_SLOW:-0}" = 1 ] && skip=()
ctest --test-dir "$build" --output-on-failure --timeout 900 -j"${MESOLIGHT_JOBS:-$(nproc)}" \
  "${skip[@]}" "$@"
