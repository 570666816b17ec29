#!/usr/bin/env bash
# Sets up (packages, build) and runs the whole test suite. GL tests render with Mesa llvmpipe
# under Xvfb. Extra arguments go to ctest (e.g. -R Relief, -L GL).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_BUILD_DIR:-$here/build}"
bash "$here/scripts/setup.sh"

xvfb-run -a -s "-screen 0 1280x1024x24" \
  ctest --test-dir "$build" --output-on-failure --timeout 600 "$@"
