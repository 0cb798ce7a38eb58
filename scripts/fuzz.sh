#!/usr/bin/env bash
# fuzz.sh [SECONDS] [BUILD_DIR]: builds the libFuzzer harnesses (fuzz/, clang,
# ASan + UBSan) and runs each for SECONDS (default 10) on its seed corpus.
# Exits non-zero if any harness finds a crash, a leak, a timeout or an
# out-of-memory; the failing input is left in BUILD_DIR/fuzz-artifacts/ (keep
# it under tests/data/fuzz/HARNESS/ once fixed). The long campaign of
# docs/RELIABILITY.md is this script with SECONDS=600 or more.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
dir=${2:-build-fuzz}
CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVRI_FUZZ=ON -DVRI_BUILD_TESTS=OFF \
  -DVRI_BUILD_BENCH=OFF >/dev/null
cmake --build "$dir" -j "$(nproc)" --target fuzz_raw fuzz_nrrd fuzz_nrrd_gzip fuzz_volvis_dat fuzz_vtk_legacy \
  fuzz_vtu fuzz_scene fuzz_transfer_function
mkdir -p "$dir/fuzz-artifacts"
# Seeds: small generated files (fuzz/seeds/) and the bundled small inputs.
declare -A extra=(
  [raw]="" [nrrd]="" [nrrd_gzip]="" [volvis_dat]=""
  [vtk_legacy]="tests/data/mesh" [vtu]="tests/data/mesh"
  [scene]="scenes" [transfer_function]="presets"
)
status=0
for h in raw nrrd nrrd_gzip volvis_dat vtk_legacy vtu scene transfer_function; do
  corpus="$dir/fuzz-corpus/$h"
  mkdir -p "$corpus"
  seeds=()
  [ -d "fuzz/seeds/$h" ] && seeds+=("fuzz/seeds/$h")
  [ -d "tests/data/fuzz/$h" ] && seeds+=("tests/data/fuzz/$h")
  [ -n "${extra[$h]}" ] && seeds+=("${extra[$h]}")
  echo "== fuzz_$h: ${seconds}s"
  if ! "$dir/fuzz/fuzz_$h" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       -max_len=65536 -print_final_stats=1 \
       -artifact_prefix="$dir/fuzz-artifacts/$h-" >"$dir/fuzz-artifacts/$h.log" 2>&1; then
    echo "fuzz_$h FAILED: see $dir/fuzz-artifacts/$h.log"; tail -40 "$dir/fuzz-artifacts/$h.log"; status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$dir/fuzz-artifacts/$h.log" | tr '\n' ' '; echo
done
exit $status
