#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The distributed light field measured: `mpiexec -n N mesolight vlf propagate` of the built-in
# Cornell box at 1 and 2 ranks, one thread per rank (VTK_SMP_MAX_THREADS=1, so that two ranks on
# two cores compare with one rank on one), plus one rank with every thread for reference.
# Writes docs/measurements/vlf-mpi/vlf-mpi.csv (or $1): per run the trace and propagation
# seconds (rank 0's clock), the speed-up against one rank, the largest peak RSS of a rank
# (/usr/bin/time), rank 0's allocated maps and textures, and the bytes each rank puts into the
# one sum per iteration, and each rank's CPU seconds (the largest, the sum).
#   MESOLIGHT_TOOL (default build/bin/mesolight), DIRECTIONS (513), RAYS (32), ITERATIONS (4)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tool="${MESOLIGHT_TOOL:-$here/build/bin/mesolight}"
csv="${1:-$here/docs/measurements/vlf-mpi/vlf-mpi.csv}"
directions="${DIRECTIONS:-513}" rays="${RAYS:-32}" iterations="${ITERATIONS:-4}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "ranks,threads_per_rank,directions,rays,iterations,trace_s,propagate_s,total_s,speedup,max_rank_cpu_s,sum_rank_cpu_s,max_rank_peak_rss_bytes,rank0_allocated_bytes,reduced_bytes_per_iteration" > "$csv"
base=""
for run in "1 1" "2 1" "1 0"; do
  set -- $run
  ranks=$1 threads=$2
  env_threads=()
  [ "$threads" != 0 ] && env_threads=(-x VTK_SMP_MAX_THREADS=$threads)
  log="$work/run-$ranks-$threads.txt"
  mpiexec -n "$ranks" "${env_threads[@]}" /usr/bin/time -f "peak_rss_kib %M cpu_s %U %S" "$tool" vlf propagate \
    --directions "$directions" --rays "$rays" --iterations "$iterations" --force \
    --out "$work/field.vlf" > "$log" 2> "$log.err"
  trace=$(sed -n 's/^traced in \([0-9.e-]*\) s.*/\1/p' "$log")
  propagate=$(sed -n 's/^iteration [0-9]*: \([0-9.]*\) s.*/\1/p' "$log" | paste -sd+ | bc -l)
  rss=$(grep -o 'peak_rss_kib [0-9]*' "$log.err" | sed 's/peak_rss_kib //' | sort -n | tail -1)
  # CPU seconds (user + system) of each rank's whole process: the work split even when other
  # load on the machine hides it from the wall clock.
  cpus=$(sed -n 's/.*cpu_s \([0-9.]*\) \([0-9.]*\)$/\1 + \2/p' "$log.err" | bc -l | sort -n)
  cpu_max=$(echo "$cpus" | tail -1)
  cpu_sum=$(echo "$cpus" | paste -sd+ | bc -l)
  reduced=$(sed -n 's/^MPI: [0-9]* ranks, \([0-9]*\) bytes.*/\1/p' "$log")
  allocated=$(sed -n 's/.*rank 0 holds \([0-9]*\) bytes.*/\1/p' "$log")
  total=$(echo "$trace + $propagate" | bc -l)
  [ -z "$base" ] && base=$total
  speedup=$(echo "$base / $total" | bc -l)
  printf "%s,%s,%s,%s,%s,%.3f,%.3f,%.3f,%.2f,%.2f,%.2f,%s,%s,%s\n" "$ranks" \
    "$([ "$threads" = 0 ] && echo all || echo "$threads")" "$directions" "$rays" "$iterations" \
    "$trace" "$propagate" "$total" "$speedup" "$cpu_max" "$cpu_sum" "$((rss * 1024))" "$allocated" "$reduced" | tee -a "$csv"
done
echo "wrote $csv"
