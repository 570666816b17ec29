#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The ParaView GUI with the Mesolight plugin: the plugin auto-loaded (PV_PLUGIN_PATH) and
# ParaView's Python modules (the View > Python Shell, --script, macros) taken from the local
# python3-paraview copy that scripts/setup-paraview.sh unpacks (it cannot be apt-installed next
# to python3-vtk9, which the main build needs). Arguments go to `paraview` unchanged:
#   scripts/paraview.sh                         (the GUI)
#   scripts/paraview.sh --state=examples/relief-environment.pvsm
#   scripts/paraview.sh --script=my_pipeline.py
# Without a display it runs under Xvfb (scripts/xvfb.sh), e.g. for scripted checks, with its own
# settings directory where ParaView's welcome dialog is off (no one could close it, and a script
# that loads a state would wait behind it: scripts/paraview-script-settings.sh).
#   MESOLIGHT_PARAVIEW_BUILD_DIR  the plugin's build directory (default: <repo>/build-paraview)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_PARAVIEW_BUILD_DIR:-$here/build-paraview}"
plugin_dir="$build/lib/paraview-5.11/plugins/Mesolight"
python_dir="$build/paraview-python/usr/lib/python3/dist-packages"
if [ ! -f "$plugin_dir/Mesolight.so" ] || [ ! -d "$python_dir/paraview" ]; then
  echo "scripts/paraview.sh: no plugin build in $build; run scripts/setup-paraview.sh first" >&2
  exit 1
fi
export PYTHONPATH="$python_dir${PYTHONPATH:+:$PYTHONPATH}"
export PV_PLUGIN_PATH="$plugin_dir${PV_PLUGIN_PATH:+:$PV_PLUGIN_PATH}"
export MESOLIGHT_PLUGIN="$plugin_dir/Mesolight.so"
if [ -z "${DISPLAY:-}" ]; then
  config="$(mktemp -d "${TMPDIR:-/tmp}/mesolight-paraview-settings.XXXXXX")"
  trap 'rm -rf "$config"' EXIT
  bash "$here/scripts/paraview-script-settings.sh" "$config"
  status=0
  XDG_CONFIG_HOME="$config" XDG_RUNTIME_DIR="$config" bash "$here/scripts/xvfb.sh" paraview "$@" ||
    status=$?
  exit "$status"
fi
exec paraview "$@"
