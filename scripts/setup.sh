#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs Mesolight's Debian packages (if missing), then configures and builds in ./build.
# Idempotent: a second run only rebuilds what changed.
#   MESOLIGHT_BUILD_DIR  build directory (default: <repo>/build)
#   MESOLIGHT_BUILD_TYPE CMake build type (default: Release)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_BUILD_DIR:-$here/build}"

bash "$here/scripts/install-deps.sh"

generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE="${MESOLIGHT_BUILD_TYPE:-Release}" \
    -DMESOLIGHT_WARNINGS_AS_ERRORS=ON
fi
cmake --build "$build" --parallel "$(nproc)"
