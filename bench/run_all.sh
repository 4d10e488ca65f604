#!/bin/sh
# Regenerates every benchmark result of the documentation in one command:
#   bench/run_benchmarks.sh  speed (mpm_bench, Google Benchmark) -> doc/MPM/Performance.md
#   bench/run_quality.sh     quality CSVs, gnuplot plots           -> doc/MPM/results/, doc/MPM/Quality.md
# Usage: bench/run_all.sh [BUILD_DIR]   (default: build-bench)
# Builds mpm_bench and the quality programs in BUILD_DIR first (configuring
# it in Release when it has no cache yet). Environment as for the two scripts
# (MPM_DATA_DIR, VERTICES, POSES, COUNTS); SKIP_SPEED=1 or SKIP_QUALITY=1
# leaves one part out.
# Duration, measured 2026-11-22 on 2 cores under a load average of about 5:
# run_benchmarks.sh 7 minutes (with CHOLMOD, so every MPM variant twice),
# run_quality.sh 2 minutes at its defaults; about 10 minutes in all, plus
# the build (10-15 minutes) when BUILD_DIR is fresh. Timings are only
# comparable within one run; an idle machine gives steadier numbers.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build-bench}
start=$(date +%s)
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD" -j"$(nproc 2>/dev/null || echo 2)" --target mpm_bench quality_reconstruction quality_shape_space
if [ -z "${SKIP_SPEED:-}" ]; then
  echo "run_all.sh: speed benchmarks (bench/run_benchmarks.sh)" >&2
  "$ROOT/bench/run_benchmarks.sh" "$BUILD"
fi
if [ -z "${SKIP_QUALITY:-}" ]; then
  echo "run_all.sh: quality benchmarks (bench/run_quality.sh)" >&2
  "$ROOT/bench/run_quality.sh" "$BUILD"
fi
echo "run_all.sh: done in $(( $(date +%s) - start )) s; see doc/MPM/Performance.md and doc/MPM/Quality.md" >&2
