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
exit $status
