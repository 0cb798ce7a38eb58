#!/usr/bin/env bash
# fuzz.sh [SECONDS] [BUILD_DIR]: builds the libFuzzer harnesses (fuzz/, clang,
# ASan + UBSan) and runs each for SECONDS (default 10) on its seed corpus.
# Exits non-zero if any harness finds a crash, a leak, a timeout or an
# out-of-memory; the failing input is left in BUILD_DIR/fuzz-artifacts/ (keep
# it under tests/data/fuzz/HARNESS/ once fixed). The long campaign of
# docs/RELIABILITY.md is this script with SECONDS=600 or more (FUZZ_PARALLEL=1
# runs the harnesses at once; otherwise FUZZ_JOBS, default one per core, run
# side by side, each for SECONDS).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
dir=${2:-build-fuzz}
CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVRI_FUZZ=ON -DVRI_BUILD_TESTS=OFF \
  -DVRI_BUILD_BENCH=OFF >/dev/null
cmake --build "$dir" -j "$(nproc)"  # the fuzz build holds the harnesses only
# Each harness is the ctest fuzz_HARNESS (label fuzz, fuzz/run_harness.sh).
jobs=${FUZZ_JOBS:-$(nproc)}
[ "${FUZZ_PARALLEL:-0}" = 1 ] && jobs=14  # every harness at once (the long campaign)
status=0
FUZZ_SECONDS=$seconds ctest --test-dir "$dir" -L fuzz -j "$jobs" --timeout $((seconds + 120)) --output-on-failure \
  || status=1
for log in "$dir"/fuzz-artifacts/*.log; do
  echo "== $(basename "$log" .log): ${seconds}s: $(grep -E 'stat::number_of_executed_units' "$log" | tr -s ' ') $(grep cpu_seconds "$log")"
done
exit $status
