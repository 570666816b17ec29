#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates the GUI screenshots of docs/paraview.md: for each walk-through step the real
# `paraview` (scripts/paraview.sh's environment, a private HOME with the splash screen and welcome
# dialog off) builds the step's state with screenshot_steps.py and stays open; once the script
# is done and Qt has painted, the whole X screen is saved (grab_x11.py) and that paraview ends.
#   docs/paraview/screenshots.sh            (runs itself under Xvfb, 1280 x 1024)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
if [ -z "${DISPLAY:-}" ]; then
  exec bash "$repo/scripts/xvfb.sh" bash "$0" "$@"
fi
build="${MESOLIGHT_PARAVIEW_BUILD_DIR:-$repo/build-paraview}"
home="$(mktemp -d "${TMPDIR:-/tmp}/mesolight-shots.XXXXXX")"
trap 'rm -rf "$home"' EXIT
mkdir -p "$home/.config/ParaView"
printf '[General]\nGeneralSettings.ShowSplashScreen=false\nGeneralSettings.ShowWelcomeDialog=false\n' \
  > "$home/.config/ParaView/ParaView5.11.0.ini"
export PYTHONPATH="$repo/paraview_plugin/Testing/GUI:$build/paraview-python/usr/lib/python3/dist-packages"
export PV_PLUGIN_PATH="$build/lib/paraview-5.11/plugins/Mesolight"
names=(01-procedural-relief 02-relief-surface 03-relit)
for step in 1 2 3; do
  ready="$home/ready-$step"
  HOME="$home" XDG_CONFIG_HOME="$home/.config" XDG_RUNTIME_DIR="$home" \
    MESOLIGHT_SCREENSHOT_STEP=$step MESOLIGHT_SCREENSHOT_READY="$ready" \
    paraview --script="$here/screenshot_steps.py" > "$home/log-$step" 2>&1 &
  pid=$!
  for _ in $(seq 1 240); do
    [ -f "$ready" ] && break
    sleep 0.5
  done
  sleep 4 # let Qt paint the panels after the script returned
  python3 "$here/grab_x11.py" "$here/${names[$((step - 1))]}.png"
  kill "$pid"
  wait "$pid" || true
  [ -f "$ready" ] || { echo "step $step never got ready:"; cat "$home/log-$step"; exit 1; }
  echo "wrote $here/${names[$((step - 1))]}.png"
done
