#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The main job: set up (packages, build), then render the default relief scene to
# mesolight-render.png. With a display it also opens an interactive window; without one it
# renders offscreen under Xvfb (Mesa llvmpipe). Extra arguments go to `mesolight render`.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_BUILD_DIR:-$here/build}"
bash "$here/scripts/setup.sh"

if [ -n "${DISPLAY:-}" ]; then
  exec "$build/bin/mesolight" render "$@"
fi
exec bash "$here/scripts/xvfb.sh" "$build/bin/mesolight" render --offscreen "$@"
