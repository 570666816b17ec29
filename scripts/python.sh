#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# python3 with the build's `mesolight` package (Mesolight's VTK classes for VTK's Python) on its
# path: the interpreter the build wrapped for (the one that imports python3-vtk9's vtkmodules,
# not a pyenv/virtualenv python3 first in PATH). Without a display it runs under Xvfb, so
# offscreen render windows work too (Debian's VTK 9.1 renders through X only). Examples:
#   scripts/python.sh examples/python/relief_wall.py relief-wall.png
#   scripts/python.sh -c "from mesolight import vtkReliefMapper; print(vtkReliefMapper())"
#   MESOLIGHT_BUILD_DIR=other-build scripts/python.sh script.py
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_BUILD_DIR:-$here/build}"
cache="$build/CMakeCache.txt"
if [ ! -f "$cache" ]; then
  echo "scripts/python.sh: no build in $build (run scripts/setup.sh, or set MESOLIGHT_BUILD_DIR)" >&2
  exit 2
fi
setting() { sed -n "s/^$1:[A-Z]*=//p" "$cache" | head -n 1; }
if [ "$(setting MESOLIGHT_WRAP_PYTHON)" != "ON" ]; then
  echo "scripts/python.sh: $build was configured with MESOLIGHT_WRAP_PYTHON=OFF" \
       "(python3-vtk9 missing?)" >&2
  exit 2
fi
python="$(setting Python3_EXECUTABLE)"
package="$build/$(setting MESOLIGHT_PYTHON_DESTINATION)"
if [ ! -f "$package/mesolight/__init__.py" ]; then
  echo "scripts/python.sh: no mesolight package in $package (build first: ninja -C $build)" >&2
  exit 2
fi
export PYTHONPATH="$package${PYTHONPATH:+:$PYTHONPATH}"
if [ -z "${DISPLAY:-}" ]; then
  exec bash "$here/scripts/xvfb.sh" "$python" "$@"
fi
exec "$python" "$@"
