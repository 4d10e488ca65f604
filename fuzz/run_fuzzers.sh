#!/usr/bin/env bash
# Runs every libFuzzer target of CGAL-MPM for a bounded time and reports the
# executions per target and in total (doc/MPM/Fuzzing.md).
#
#   fuzz/run_fuzzers.sh [SECONDS_PER_TARGET]        (default 60)
#
# Environment:
#   BUILD_DIR  the clang build directory (default: <repo>/build-fuzz); it is
#              configured with -DMPM_BUILD_FUZZERS=ON when it has no cache yet,
#              and the targets are (re)built with `--target fuzzers`.
#   TARGETS    the targets to run (default: all five).
#   FUZZ_SEED  libFuzzer's -seed (default 1, so runs are reproducible).
#   JOBS       build parallelism (default 2).
#   SKIP_BUILD=1  run the targets as built (e.g. while another run uses them).
#
# Seeds come from fuzz/corpus/<target> (read only); inputs the fuzzer finds
# go to $BUILD_DIR/corpus/<target>, crash/leak/timeout inputs to
# $BUILD_DIR/artifacts/. The exit status is 1 when any target failed.
set -euo pipefail

duration="${1:-60}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/.." && pwd)"
build="${BUILD_DIR:-$repo/build-fuzz}"
seed="${FUZZ_SEED:-1}"
jobs="${JOBS:-2}"
targets="${TARGETS:-fuzz_mesh_io fuzz_annotation_io fuzz_model_io fuzz_part_graph_io fuzz_handle_set}"

if [ "${SKIP_BUILD:-0}" != 1 ]; then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    CC=clang CXX=clang++ cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DMPM_BUILD_FUZZERS=ON -DMPM_BUILD_TESTS=OFF -DMPM_BUILD_BENCHMARKS=OFF \
      -DMPM_BUILD_EXAMPLES=OFF -DMPM_BUILD_DEMO=OFF
  fi
  cmake --build "$build" --target fuzzers -j "$jobs"
fi

mkdir -p "$build/artifacts"
total=0
failed=0
summary=""
for t in $targets; do
  work="$build/corpus/$t"
  log="$build/$t.log"
  mkdir -p "$work"
  echo "== $t: ${duration}s (log $log)"
  status=0
  "$build/fuzz/$t" "$work" "$here/corpus/$t" \
    -max_total_time="$duration" -seed="$seed" -timeout=25 -rss_limit_mb=4096 \
    -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" >"$log" 2>&1 || status=$?
  runs="$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$log" | tail -n 1)"
  runs="${runs:-0}"
  total=$((total + runs))
  if [ "$status" -ne 0 ]; then
    failed=1
    summary+="$(printf '%-20s %12s executions  FAILED (exit %s, see %s)' "$t" "$runs" "$status" "$log")"$'\n'
    grep -E '^(==[0-9]+==ERROR|SUMMARY|artifact_prefix|Test unit written)' "$log" | head -n 5 || true
  else
    summary+="$(printf '%-20s %12s executions' "$t" "$runs")"$'\n'
  fi
done
echo
printf '%s' "$summary"
printf '%-20s %12s executions\n' "total" "$total"
exit "$failed"
