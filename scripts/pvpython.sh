#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# pvpython with the Mesolight plugin, with or without a display: ParaView's Python modules from
# the local python3-paraview copy (scripts/setup-paraview.sh), the plugin auto-loaded through
# PV_PLUGIN_PATH (LoadPlugin is not needed; calling it anyway is a no-op), and, without DISPLAY,
# a private Xvfb (Debian's ParaView is built for X only: pvpython without a display dies with
# SIGSEGV in vtkXRenderWindowInteractor::Initialize at the first Render). Examples:
#   scripts/pvpython.sh my_pipeline.py [args...]
#   scripts/pvpython.sh                          (the interactive prompt)
#   scripts/pvpython.sh --force-offscreen-rendering my_pipeline.py
# Options (starting with -, before the script; --opt=value form) go to pvpython. Start-up:
# paraview_plugin/python/mesolight_pvlaunch.py (why pvpython alone cannot import paraview here).
#   MESOLIGHT_PARAVIEW_BUILD_DIR  the plugin's build directory (default: <repo>/build-paraview)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_PARAVIEW_BUILD_DIR:-$here/build-paraview}"
plugin_dir="$build/lib/paraview-5.11/plugins/Mesolight"
python_root="$build/paraview-python/usr"
python_dir="$python_root/lib/python3/dist-packages"
if [ ! -f "$plugin_dir/Mesolight.so" ] || [ ! -x "$python_root/bin/pvpython" ]; then
  echo "scripts/pvpython.sh: no plugin build in $build; run scripts/setup-paraview.sh first" >&2
  exit 1
fi
export PYTHONPATH="$python_dir${PYTHONPATH:+:$PYTHONPATH}"
export MESOLIGHT_PARAVIEW_PYTHON="$python_dir"
export PV_PLUGIN_PATH="$plugin_dir${PV_PLUGIN_PATH:+:$PV_PLUGIN_PATH}"
export MESOLIGHT_PLUGIN="$plugin_dir/Mesolight.so"
options=()
while [ $# -gt 0 ] && [[ "$1" == -* ]]; do options+=("$1"); shift; done
launch="$here/paraview_plugin/python/mesolight_pvlaunch.py"
if [ $# -eq 0 ]; then
  command=("$python_root/bin/pvpython" "${options[@]}" -i "$launch")
else
  command=("$python_root/bin/pvpython" "${options[@]}" "$launch" "$@")
fi
if [ -z "${DISPLAY:-}" ]; then
  exec bash "$here/scripts/xvfb.sh" "${command[@]}"
fi
exec "${command[@]}"
