#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs TestLauncherPipeline.py through scripts/pvpython.sh or scripts/pvbatch.sh WITHOUT a display
# (DISPLAY unset: the launcher must start its own Xvfb), as a user's headless first run. Fails
# unless the script printed OK and the output has no ParaView error (e.g. "Plugin load failed").
#   run-launcher-test.sh pvpython|pvbatch
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../../.." && pwd)"
launcher="$1"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
env -u DISPLAY MESOLIGHT_LAUNCHER="$launcher" timeout 300 \
  bash "$repo/scripts/$launcher.sh" "$here/TestLauncherPipeline.py" >"$log" 2>&1
status=$?
cat "$log"
if [ $status -ne 0 ]; then
  echo "FAILED: scripts/$launcher.sh exited with $status" >&2
  exit 1
fi
if grep -q "Plugin load failed\|ERROR\|Segmentation\|SIGSEGV" "$log"; then
  echo "FAILED: scripts/$launcher.sh printed an error" >&2
  exit 1
fi
if ! grep -qx "OK" "$log"; then
  echo "FAILED: no OK from the script" >&2
  exit 1
fi
echo "passed: scripts/$launcher.sh without a display"
