#!/usr/bin/env bash
# Every tracked C++ file is formatted by .clang-format (VTK's style, reduced to what Debian 12's
# clang-format 14 understands). Exit 1 and the files that drifted otherwise; reformat them with
# `clang-format -i FILE`. Usage: scripts/check-format.sh [CLANG_FORMAT]
set -u
cd "$(dirname "$0")/.."
tool="${1:-clang-format}"
drifted=0
while IFS= read -r file; do
  if ! "$tool" --dry-run -Werror "$file" > /dev/null 2>&1; then
    echo "not formatted: $file (clang-format -i $file)"
    drifted=$((drifted + 1))
  fi
done < <(git ls-files '*.cxx' '*.h')
echo "$drifted C++ files not formatted"
[ "$drifted" -eq 0 ]
