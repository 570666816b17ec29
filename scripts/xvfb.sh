#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs a command under a private Xvfb display (Mesa llvmpipe renders into it). Every offscreen
# render here goes through this one wrapper.
#
# -noreset: by default an X server resets itself when its last client disconnects, and a client
# that connects during that reset has its connection closed after the connection set-up was sent
# (Xlib then returns no display and VTK 9.1 aborts with "bad X server connection"). Each test
# process, and each render window a process opens after closing its previous one, is such a
# client; the test OffscreenWindows.TwoHundredWindowsOneAfterAnother aborts without -noreset.
set -euo pipefail
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
