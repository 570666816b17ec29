#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs every Debian 12 package Mesolight needs to build, test and render headless.
# Idempotent: packages already present are left alone; apt-get update runs at most once per call.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libvtk9-dev
  python3-vtk9 python3-dev python3-numpy  # the Python wrapping, its examples and tests
  mpi-default-dev mpi-default-bin  # the distributed light field: MPI headers, mpiexec
  libopenimageio-dev openimageio-tools libopenexr-dev
  libglm-dev
  libembree-dev
  blender-data blender
  googletest libgtest-dev libgmock-dev
  clang libclang-rt-dev  # the fuzz stage of scripts/test.sh: clang and its libFuzzer runtime
  xvfb xauth mesa-utils libgl1-mesa-dri
)
# Real height maps (game textures, about 860 MB) for the relief tests and the real-map benchmarks:
# scripts/test.sh asks for them; scripts/run.sh does not.
if [ "${MESOLIGHT_REAL_MAPS:-0}" = 1 ]; then PACKAGES+=(redeclipse-data); fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "[mesolight] all Debian packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "[mesolight] installing: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
