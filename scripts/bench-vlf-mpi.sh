#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The distributed light field measured: `mpiexec -n N mesolight vlf propagate --rank-report` of
# the built-in Cornell box, REPEATS rounds of three runs interleaved (so that the load of the
# machine falls on all alike): 1 rank x 1 thread, 2 ranks x 1 thread (the default on 2 cores:
# ranks split the cores), 1 rank x every thread. Then scripts/vlf-mpi-model.py fits the cost model
# of docs/vlf-mpi-cost-model.md to the rows and writes its predictions and the chart.
# Writes under docs/measurements/vlf-mpi/ (or $1):
#   vlf-mpi-runs.csv     one row per run: wall seconds of mpiexec, the slowest rank's trace,
#                        iteration and snapshot-write seconds and its seconds inside MPI calls
#                        during the iterations, CPU seconds (largest, sum), peak RSS (largest,
#                        rank 0), bytes held (largest), bytes summed per iteration, bytes sent
#   vlf-mpi-speedup.csv  per round, 1x1 over 2x1: iterations, trace + iterations, wall, and the
#                        slowest rank's CPU seconds of iteration work (what an idle machine
#                        would show)
#   vlf-mpi-model.csv, vlf-mpi.svg (vlf-mpi-model.py)
#   MESOLIGHT_TOOL (default build/bin/mesolight), DIRECTIONS (2049), RAYS (32), ITERATIONS (4),
#   REPEATS (3), SNAPSHOT_EVERY (1: FIELD written after every iteration; ITERATIONS: once, at the
#   end, which leaves the propagation alone in the iteration seconds and the wall)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tool="${MESOLIGHT_TOOL:-$here/build/bin/mesolight}"
out="${1:-$here/docs/measurements/vlf-mpi}"
directions="${DIRECTIONS:-2049}" rays="${RAYS:-32}" iterations="${ITERATIONS:-4}"
repeats="${REPEATS:-3}" every="${SNAPSHOT_EVERY:-1}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
runs="$out/vlf-mpi-runs.csv" speedup="$out/vlf-mpi-speedup.csv"
echo "round,ranks,threads_per_rank,directions,rays,iterations,wall_s,trace_s,iterations_s,writes_s,iterations_in_mpi_s,max_rank_iteration_work_cpu_s,max_rank_cpu_s,sum_rank_cpu_s,max_rank_peak_rss_bytes,rank0_peak_rss_bytes,max_rank_held_bytes,reduced_bytes_per_iteration,max_rank_sent_bytes,rank0_peak_rss_after_trace_bytes,snapshot_every" > "$runs"
echo "round,directions,iterations_speedup,trace_and_iterations_speedup,wall_speedup,iteration_work_cpu_speedup" > "$speedup"
# The largest of column $1 over the rank-report lines of a log.
largest() { grep '^rank [0-9]*: trace' "$2" | awk -v c="$1" '{print $c}' | sort -g | tail -1; }
for round in $(seq 1 "$repeats"); do
  declare -A it=() ti=() wall=() wk=()
  for run in "1 1" "2 1" "1 all"; do
    set -- $run
    ranks=$1 threads=$2
    env_threads=()
    [ "$threads" != all ] && env_threads=(-x VTK_SMP_MAX_THREADS=$threads)
    log="$work/run-$round-$ranks-$threads.txt"
    start=$(date +%s.%N)
    mpiexec -n "$ranks" "${env_threads[@]}" "$tool" vlf propagate --rank-report \
      --directions "$directions" --rays "$rays" --iterations "$iterations" --force \
      --snapshot-every "$every" \
      --out "$work/field.vlf" > "$log" 2> "$log.err"
    seconds=$(echo "$(date +%s.%N) - $start" | bc -l)
    # rank R: trace T s (in MPI M s), iterations I s (in MPI M s), snapshot writes W s (in MPI
    # M s), cpu C s, peak RSS B bytes, holds H bytes, D directions, sent S bytes
    trace=$(largest 4 "$log") iter=$(largest 11 "$log") iter_mpi=$(largest 15 "$log")
    writes=$(largest 19 "$log") cpu_max=$(largest 26 "$log") rss=$(largest 30 "$log")
    held=$(largest 33 "$log") sent=$(largest 38 "$log")
    # The CPU seconds of each rank's own iteration work (excluding the polling inside MPI calls):
    # what an idle machine turns into wall time; the largest over the ranks.
    own_cpu=$(grep '^rank [0-9]*: trace' "$log" | awk '{print $42 - $46}' | sort -g | tail -1)
    cpu_sum=$(grep '^rank [0-9]*: trace' "$log" | awk '{s += $26} END {print s}')
    rss0=$(grep '^rank 0: trace' "$log" | awk '{print $30}')
    rss0_trace=$(grep '^rank 0: trace' "$log" | awk '{print $52}')
    reduced=$(sed -n 's/^MPI: [0-9]* ranks, \([0-9]*\) bytes.*/\1/p' "$log")
    printf "%s,%s,%s,%s,%s,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%s,%s,%s,%s,%s,%s,%s\n" "$round" \
      "$ranks" "$threads" "$directions" "$rays" "$iterations" "$seconds" "$trace" "$iter" "$writes" \
      "$iter_mpi" "$own_cpu" "$cpu_max" "$cpu_sum" "$rss" "$rss0" "$held" "$reduced" "$sent" "$rss0_trace" "$every" | tee -a "$runs"
    it[$run]=$iter ti[$run]=$(echo "$trace + $iter" | bc -l) wall[$run]=$seconds wk[$run]=$own_cpu
  done
  printf "%s,%s,%.3f,%.3f,%.3f,%.3f\n" "$round" "$directions" \
    "$(echo "${it[1 1]} / ${it[2 1]}" | bc -l)" "$(echo "${ti[1 1]} / ${ti[2 1]}" | bc -l)" \
    "$(echo "${wall[1 1]} / ${wall[2 1]}" | bc -l)" "$(echo "${wk[1 1]} / ${wk[2 1]}" | bc -l)" |
    tee -a "$speedup"
  unset it ti wall wk
done
python3 "$here/scripts/vlf-mpi-model.py" "$out"
echo "wrote $runs, $speedup and the model's files in $out"
