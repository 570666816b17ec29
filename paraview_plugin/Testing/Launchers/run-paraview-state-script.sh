#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The GUI launcher as a script runs it without a display: scripts/paraview.sh
# --script=load.py --exit, where load.py loads the shipped state (examples/relief-environment.pvsm)
# and renders. Under Xvfb no one can close ParaView's welcome dialog, and LoadState waited behind
# it until the timeout; scripts/paraview.sh now runs its Xvfb session with the dialog off. Fails
# unless the script ends (within the timeout) with its "OK" written, in a fresh HOME (a first-time
# user's settings: the dialog on).
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../../.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat > "$work/load.py" <<PY
from paraview.simple import LoadState, Render
LoadState("$repo/examples/relief-environment.pvsm")
Render()
with open("$work/result.txt", "w") as result:
    result.write("OK\n")
PY
status=0
start=$SECONDS
env -u DISPLAY HOME="$work/home" timeout 240 bash "$repo/scripts/paraview.sh" \
  --script="$work/load.py" --exit > "$work/log.txt" 2>&1 || status=$?
if [ "$(head -1 "$work/result.txt" 2>/dev/null)" != "OK" ]; then
  cat "$work/log.txt"
  echo "FAILED: scripts/paraview.sh --script (LoadState) did not finish in" \
    "$((SECONDS - start)) s (exit status $status; 124: the timeout, e.g. a dialog waiting)" >&2
  exit 1
fi
echo "scripts/paraview.sh --script loaded the state and rendered in $((SECONDS - start)) s" \
  "(exit status $status)"
