#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# pvbatch with the Mesolight plugin: ParaView's Python modules from the local python3-paraview
# copy (scripts/setup-paraview.sh) and the plugin auto-loaded through PV_PLUGIN_PATH.
# Without a display it runs under Xvfb. Example:
#   scripts/pvbatch.sh my_pipeline.py [args...]  (LoadPlugin is not needed; calling it anyway is
#                                                 a no-op, not a "Plugin load failed" error)
#   mpiexec -n 2 scripts/pvbatch.sh my_pipeline.py
# Options (starting with -, before the script) go to pvbatch. Start-up:
# paraview_plugin/python/mesolight_pvlaunch.py.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_PARAVIEW_BUILD_DIR:-$here/build-paraview}"
export PYTHONPATH="$build/paraview-python/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
export PV_PLUGIN_PATH="$build/lib/paraview-5.11/plugins/Mesolight${PV_PLUGIN_PATH:+:$PV_PLUGIN_PATH}"
export MESOLIGHT_PLUGIN="$build/lib/paraview-5.11/plugins/Mesolight/Mesolight.so"
export MESOLIGHT_PARAVIEW_PYTHON="$build/paraview-python/usr/lib/python3/dist-packages"
options=()
while [ $# -gt 0 ] && [[ "$1" == -* ]]; do options+=("$1"); shift; done
command=(pvbatch "${options[@]}" "$here/paraview_plugin/python/mesolight_pvlaunch.py" "$@")
if [ -z "${DISPLAY:-}" ]; then
  exec bash "$here/scripts/xvfb.sh" "${command[@]}"
fi
exec "${command[@]}"
