#!/bin/bash
# scripts/bench-capture --quick runs every measurement once (the bare context, the least capture
# and `m3055 render`, warm and cold shader cache, with a second m3055 as the
# "before" build, and a small batch) and checks its table has every row; the
# numbers are not checked (a shared machine).
#   tests/bench_capture_test.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
build="$(realpath "$1")"
table="$(M3055_BUILD_DIR="$build" scripts/bench-capture --quick --before "$build/m3055")"
for row in "| bare context | warm |" "| least capture (one tiny program, one draw) | cold |" "| after: render spec_example | cold |" "| before: render spec_example | warm |" \
  "| before | "; do
  grep -qF -- "$row" <<<"$table" || { echo "FAIL: no row '$row' in:" >&2; echo "$table" >&2; exit 1; }
done
echo "bench_capture_test: the table has every row"
