#!/usr/bin/env bash
# second_order_tables.sh [BUILD_DIR]: the second-order table figures of
# docs/SECOND_ORDER.md and docs/PERFORMANCE.md: build times of `fast` (N^3 at
# K = 8 and 64 chords, one and two threads, medians of 3) and `plain`
# (128^3, K = 8), the weighted build, and |fast - plain| (max, RMS over every
# entry and channel) on presets/bonsai.json and presets/neghip_spike.json.
# Prints the machine first; the benchmark's own output follows.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), load $(cut -d' ' -f1-3 /proc/loadavg)"
"$build/bench/bench_second_order" --benchmark_filter='BM_SecondOrder(Weighted)?/fast/' \
  --benchmark_repetitions=3 --benchmark_report_aggregates_only=true 2>/dev/null | grep -E 'median|Benchmark'
"$build/bench/bench_second_order" --benchmark_filter='BM_SecondOrder/plain/|BM_SecondOrderErrors' 2>/dev/null |
  grep -E '^BM|Benchmark'
