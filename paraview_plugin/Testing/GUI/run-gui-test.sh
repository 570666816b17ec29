#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs a Python script inside the real ParaView GUI: `paraview --script=SCRIPT --exit`, as a
# user's session would (the plugin auto-loaded through PV_PLUGIN_PATH, ParaView's Python from
# PYTHONPATH), with a private HOME whose ParaView settings turn off the splash screen and the
# welcome dialog (scripts/paraview-script-settings.sh, as scripts/paraview.sh without a display). The script writes "OK"
# or its failures to $MESOLIGHT_GUI_RESULT: `paraview --script` runs it through
# vtkPythonInterpreter::RunSimpleString and exits 0 whatever happened, so a missing "OK" (an
# exception, a crash, a dialog that blocked) is the failure this wrapper reports.
# SCRIPT.xml is a QtTesting event file played by `paraview --test-script=SCRIPT.xml --exit` (it
# clicks the real Apply button; mesolight_xmltest.py's finish() writes the result): then a
# failed event or pqcheck (paraview's exit status) is a failure too.
#   run-gui-test.sh SCRIPT.py|SCRIPT.xml [paraview options...]   (needs DISPLAY: scripts/xvfb.sh)
set -euo pipefail
script="$1"
shift
home="$(mktemp -d "${TMPDIR:-/tmp}/mesolight-gui-home.XXXXXX")"
trap 'rm -rf "$home"' EXIT
bash "$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)/scripts/paraview-script-settings.sh" \
  "$home/.config"
result="$home/result.txt"
# The scripts' shared module beside them (paraview --script defines no __file__).
export PYTHONPATH="$(cd "$(dirname "$script")" && pwd)${PYTHONPATH:+:$PYTHONPATH}"
status=0
run=(--script="$script")
case "$script" in *.xml) run=(--test-script="$script") ;; esac
HOME="$home" XDG_CONFIG_HOME="$home/.config" XDG_RUNTIME_DIR="$home" \
  MESOLIGHT_GUI_RESULT="$result" timeout 600 paraview "${run[@]}" --exit "$@" || status=$?
if [[ "$script" == *.xml && $status -ne 0 ]]; then
  echo "GUI test failed: $(basename "$script") (a test event failed: paraview exit status $status)" >&2
  [ -f "$result" ] && cat "$result" >&2
  exit 1
fi
if [ -f "$result" ] && [ "$(head -1 "$result")" = "OK" ]; then
  echo "GUI test passed: $(basename "$script")"
  exit 0
fi
echo "GUI test failed: $(basename "$script") (paraview exit status $status)" >&2
if [ -f "$result" ]; then cat "$result" >&2; else echo "no result written" >&2; fi
exit 1
