#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Sets up and builds the Mesolight ParaView plugin in ./build-paraview (a separate build tree:
# ParaView 5.11 brings its own VTK 9.2 with the same VTK:: target names as the system VTK 9.1).
# Idempotent: a second run only rebuilds what changed.
#
#  1. Debian packages: paraview + paraview-dev (ParaView 5.11 and its VTK) and mpi-default-bin
#     (mpiexec, for `mpiexec -n 2 pvbatch`).
#  2. python3-paraview (the Python modules pvbatch/pvpython need) is NOT apt-installed: it
#     Conflicts with python3-vtk9, which libvtk9-dev depends on. It is downloaded
#     (apt-get download) and unpacked (dpkg -x) into build-paraview/paraview-python; pvbatch
#     finds it through PYTHONPATH (scripts/pvbatch.sh, the plugin tests). apt's state is untouched.
#  3. paraview-dev's CMake package checks that its Python targets' files exist under
#     /usr/lib/python3/dist-packages, where only python3-paraview puts them. The build uses a
#     copy of that package (build-paraview/paraview-cmake) whose prefix is pinned to /usr and
#     whose Python targets point at the unpacked copy instead. Nothing under /usr is written.
#  4. Configure and build paraview_plugin/ from the same module sources as the main build.
#
#   MESOLIGHT_PARAVIEW_BUILD_DIR  build directory (default: <repo>/build-paraview)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_PARAVIEW_BUILD_DIR:-$here/build-paraview}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

# 1. Packages (plus the main build's, which share compilers and OpenImageIO).
bash "$here/scripts/install-deps.sh"
missing=()
for p in paraview paraview-dev mpi-default-bin python3-dev; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "[mesolight] installing: ${missing[*]}"
  $SUDO apt-get update -q
  # --no-install-recommends: paraview recommends python3-paraview, which would remove python3-vtk9.
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# 2. python3-paraview, unpacked locally, of the same version as paraview.
version="$(dpkg-query -W -f='${Version}' paraview)"
python_root="$build/paraview-python"
python_dir="$python_root/usr/lib/python3/dist-packages"
if [ ! -f "$python_root/.version" ] || [ "$(cat "$python_root/.version")" != "$version" ]; then
  rm -rf "$python_root"
  mkdir -p "$python_root/debs"
  (cd "$python_root/debs" && apt-get download -q "python3-paraview=$version")
  dpkg -x "$python_root"/debs/python3-paraview_*.deb "$python_root"
  rm -rf "$python_root/debs"
  echo "$version" > "$python_root/.version"
fi

# 3. ParaView's CMake package, redirected to the local python3-paraview files it refers to.
system_cmake=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11
overlay="$build/paraview-cmake"
if [ ! -f "$overlay/.version" ] || [ "$(cat "$overlay/.version")" != "$version" ]; then
  rm -rf "$overlay"
  mkdir -p "$build"
  cp -r "$system_cmake" "$overlay"
  # Each file derives the install prefix from its own location: make the copies derive it from
  # the original location, so every library and header still resolves under /usr.
  (cd "$overlay" && find . -name '*.cmake' | while read -r f; do
    dir="$system_cmake/$(dirname "${f#./}")"
    sed -i -e "s|get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_FILE}\" PATH)|set(_IMPORT_PREFIX \"$dir\")|" \
      -e "s|set(_vtk_module_import_prefix \"\${CMAKE_CURRENT_LIST_DIR}\")|set(_vtk_module_import_prefix \"$dir\")|" \
      -e "s|get_filename_component(PACKAGE_PREFIX_DIR \"\${CMAKE_CURRENT_LIST_DIR}/|get_filename_component(PACKAGE_PREFIX_DIR \"$dir/|" \
      "$f"
  done)
  # Files only python3-paraview ships: Python modules, pvpython, the wrapping hierarchies.
  grep -rl 'lib/python3/dist-packages\|bin/pvpython\|vtk/hierarchy/ParaView' "$overlay" | xargs sed -i \
    -e "s|\${_IMPORT_PREFIX}/lib/python3/dist-packages|$python_dir|g" \
    -e "s|\${_IMPORT_PREFIX}/bin/pvpython|$python_root/usr/bin/pvpython|g" \
    -e "s|\${_vtk_module_import_prefix}/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView|$python_root/usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView|g"
  echo "$version" > "$overlay/.version"
fi

# 4. Configure and build.
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here/paraview_plugin" -B "$build" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE=Release -DMESOLIGHT_WARNINGS_AS_ERRORS=ON \
    -DParaView_DIR="$overlay" \
    -DMESOLIGHT_PARAVIEW_PYTHONPATH="$python_dir"
fi
cmake --build "$build" --parallel "$(nproc)"
