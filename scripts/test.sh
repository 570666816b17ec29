#!/usr/bin/env bash
# Sets up (packages, build) and runs the whole test suite. GL tests render with Mesa llvmpipe
# under Xvfb. Extra arguments go to ctest (e.g. -R Relief, -L GL).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_BUILD_DIR:-$here/build}"
bash "$here/scripts/setup.sh"

# --repeat until-pass:2: a test that fails is run once more. Under Xvfb + llvmpipe a GL test
# process occasionally aborts because XOpenDisplay fails ("bad X server connection", see
# docs/known-issues.md); a real failure fails twice, and its first output is still printed.
xvfb-run -a -s "-screen 0 1280x1024x24" \
  ctest --test-dir "$build" --output-on-failure --timeout 600 --repeat until-pass:2 "$@"
