# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the benchmark scripts that take MESOLIGHT_BINARY OUTDIR (bench-relief-probes.sh,
# bench-relief-shading-normal.sh, bench-vlf-relief.sh): one check of those two arguments and one
# set of the paths every such script needs.
#
#   source "$(dirname "${BASH_SOURCE[0]}")/bench-arguments.sh"
#   bench_arguments /tmp/EXAMPLE-OUTDIR "$@"
#
# Sets bin (the binary, absolute), out (OUTDIR as given), here (scripts/) and source_dir (the
# source tree); a missing argument or a binary that is not executable prints the usage and exits 2.
bench_arguments() {
  local example="$1"
  shift
  if [ $# -ne 2 ] || [ ! -x "$1" ]; then
    echo "usage: scripts/$(basename "$0") MESOLIGHT_BINARY OUTDIR (e.g. build/bin/mesolight" \
      "$example)" >&2
    exit 2
  fi
  bin="$(realpath "$1")"
  out="$2"
  here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
  source_dir="$(dirname "$here")"
}
