#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Writes ParaView settings for a session no one watches into the configuration directory DIR
# (use it as XDG_CONFIG_HOME): the splash screen and the welcome dialog off
# (GeneralSettings.ShowSplashScreen / ShowWelcomeDialog, read from DIR/ParaView/ParaView<version>.ini
# by ParaView 5.11's client). Under Xvfb no one can close the welcome dialog, and a script that
# loads a state waits behind it for ever. Used by scripts/paraview.sh without a display and by
# the GUI tests (paraview_plugin/Testing/GUI/run-gui-test.sh). The user's own settings are
# neither read nor changed.
#   paraview-script-settings.sh DIR
set -euo pipefail
dir="$1"
# The version without starting paraview (it aborts without a display): the Debian package's.
version="$(dpkg-query -W -f='${Version}' paraview 2>/dev/null | sed 's/[+~-].*//' || true)"
version="${version:-5.11.0}"
mkdir -p "$dir/ParaView"
cat > "$dir/ParaView/ParaView$version.ini" <<INI
[General]
GeneralSettings.ShowSplashScreen=false
GeneralSettings.ShowWelcomeDialog=false
INI
