#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds Mesolight with AddressSanitizer + UndefinedBehaviorSanitizer in ./build-sanitize and runs
# the tests not labelled GL (the algorithm cores, the VTK filters, the walkthrough, the command
# line's bad input), where the sanitizers see Mesolight's own code rather than Mesa's. Extra
# arguments go to ctest (e.g. -R Snapshot). Not part of the README's test command: on two cores
# the build takes about 40 minutes and the tests several times the normal suite; run it on demand.
#   MESOLIGHT_SANITIZE   sanitizers (default: address,undefined)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
bash "$here/scripts/install-deps.sh"

generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DMESOLIGHT_SANITIZE="${MESOLIGHT_SANITIZE:-address,undefined}" \
    -DMESOLIGHT_BUILD_EXAMPLES=OFF
fi
cmake --build "$build" --parallel "${MESOLIGHT_JOBS:-$(nproc)}"

# Leaks: VTK's and TBB's process-lifetime singletons would be reported; leaks in Mesolight's
# own code are what the suite's RAII design rules out, and ASan still catches use-after-free,
# overflows and double frees.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The install consumer builds without the sanitizer runtime; the suites labelled GL spend their
# time in Mesa. Some unlabelled tests still open a window, hence Xvfb.
bash "$here/scripts/xvfb.sh" \
  ctest --test-dir "$build" --output-on-failure --timeout 1800 -LE GL -E "^install\." "$@"
