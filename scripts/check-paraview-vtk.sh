#!/usr/bin/env bash
# Checks that the VTK module sources also compile against ParaView 5.11's own VTK (9.2), which
# the ParaView plugin builds them with. Needs paraview-dev (installed here with
# --no-install-recommends, which keeps python3-vtk9 and apt's state intact) and a build of
# Mesolight in ./build for the generated module headers.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MESOLIGHT_BUILD_DIR:-$here/build}"
if [ ! -d /usr/include/paraview-5.11 ]; then
  apt-get install -y -q --no-install-recommends paraview-dev
fi
status=0
for source in "$here"/vtkRelief/*.cxx "$here"/filters/*.cxx; do
  if g++ -std=c++17 -fsyntax-only -w -I/usr/include/paraview-5.11 \
      -I"$build/vtkRelief" -I"$build/filters" -I"$here/vtkRelief" -I"$here/filters" \
      -I"$here/filters/core" $(pkg-config --cflags OpenImageIO) "$source"; then
    echo "ok      ${source#$here/}"
  else
    echo "FAILED  ${source#$here/}"
    status=1
  fi
done
exit $status
