#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Fuzzes Mesolight's own parsers with libFuzzer (docs/fuzzing.md):
#   scripts/fuzz.sh [SECONDS] [TARGET...]
# configures ./build-fuzz with clang (-DMESOLIGHT_FUZZ=ON: the fuzz targets only, no VTK), builds,
# and runs each target (default: all) for SECONDS (default 60) on one core, starting from its
# committed corpus fuzz/corpus/<target>/. New interesting inputs go to build-fuzz/corpus/<target>/,
# crash, leak, timeout and out-of-memory inputs to build-fuzz/artifacts/<target>/; copy a crash
# input into fuzz/corpus/<target>/ once it is fixed, so that ctest fuzz.<target>.corpus replays it.
# Prints executions, coverage and crashes per target; exit 1 when any target failed.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
build="${MESOLIGHT_FUZZ_BUILD_DIR:-$here/build-fuzz}"
targets=("$@")
[ "${#targets[@]}" -gt 0 ] || targets=(obj_scene snapshot command_line object_path lights_csv image_file)

launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$here" -B "$build" -G Ninja -DMESOLIGHT_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" > /dev/null
cmake --build "$build" -j"${MESOLIGHT_FUZZ_BUILD_JOBS:-2}"

status=0
summary=()
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target"
  artifacts="$build/artifacts/$target"
  log="$build/logs/$target.log"
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  dict=()
  [ -f "$here/fuzz/$target.dict" ] && dict=(-dict="$here/fuzz/$target.dict")
  # image_file: leaks are OpenImageIO's own (fuzz/lsan.supp), whose suppression needs slow full
  # unwinding on every malloc; the corpus replay (ctest fuzz.image_file.corpus under
  # scripts/sanitize-cores.sh) still checks leaks.
  # Its resident memory also ratchets up over many inputs (AddressSanitizer's quarantine holding
  # OpenImageIO's freed buffers of up to the 64 MiB budget, and the allocator keeping what it
  # mapped: 2.2 GB after 13,840 inputs in 30 s here), which tripped the 2 GB limit after 9 s in a
  # CI run on an input that reads in 217 MB alone. A 16 MiB quarantine (945 MB after 11,365
  # inputs) and a 4 GB limit for this target; -malloc_limit_mb still catches one large allocation.
  env=()
  rss_limit=2048
  if [ "$target" = image_file ]; then
    dict+=(-detect_leaks=0)
    env=(ASAN_OPTIONS=detect_leaks=0:quarantine_size_mb=16)
    rss_limit=4096
  fi
  echo "[fuzz] $target: ${seconds} s (log: $log)"
  # -malloc_limit_mb: one allocation above 512 MiB is a finding (the snapshot target reads with a
  # 256 MiB budget, so a field that needs more must be refused before it is allocated).
  code=0
  start=$SECONDS
  env "${env[@]}" "$build/bin/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb="$rss_limit" \
    -malloc_limit_mb=512 -print_final_stats=1 -artifact_prefix="$artifacts/" "${dict[@]}" \
    "$corpus" "$here/fuzz/corpus/$target" > "$log" 2>&1 || code=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<< "$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$last")
  found=$(find "$artifacts" -type f | wc -l)
  line="$target: ${runs:-?} executions in $((SECONDS - start)) s, cov ${cov:-?}, ft ${ft:-?}, exit $code, artifacts $found"
  summary+=("$line")
  if [ "$code" -ne 0 ] || [ "$found" -gt 0 ]; then
    status=1
    grep -m1 -E 'ERROR: |==ERROR|deadly signal|Timeout|out-of-memory' "$log" || true
    find "$artifacts" -type f | sed 's/^/  input: /'
  fi
done
# A target that crashed (or a merge child) exits without removing its scratch directory
# (fuzz/FuzzSupport.h): remove those of processes that are gone.
for dir in "${TMPDIR:-/tmp}"/mesolight-fuzz-*; do
  [ -d "$dir" ] && ! kill -0 "${dir##*-}" 2> /dev/null && rm -rf "$dir"
done
printf '[fuzz] %s\n' "${summary[@]}"
exit "$status"
