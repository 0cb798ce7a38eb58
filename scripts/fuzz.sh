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
cmake --build "$dir" -j "$(nproc)" --target fuzz_raw fuzz_nrrd fuzz_nrrd_gzip fuzz_volvis_dat fuzz_vtk_legacy \
  fuzz_vtu fuzz_vti fuzz_vtk_structured_points fuzz_metaimage fuzz_npy_volume fuzz_tiff fuzz_scene fuzz_transfer_function \
  fuzz_viewer_protocol
mkdir -p "$dir/fuzz-artifacts"
# Seeds: small generated files (fuzz/seeds/) and the bundled small inputs.
declare -A extra=(
  [raw]="" [nrrd]="" [nrrd_gzip]="" [volvis_dat]="" [metaimage]="" [npy_volume]="" [tiff]=""
  [vtk_legacy]="tests/data/mesh" [vtu]="tests/data/mesh"
  [vti]="tests/data/volume" [vtk_structured_points]="tests/data/volume"
  [scene]="scenes" [transfer_function]="presets" [viewer_protocol]=""
)
# One harness: its corpus grows in BUILD_DIR/fuzz-corpus/HARNESS; its log
# ends with libFuzzer's stats and the CPU seconds it used.
fuzz_one() {
  local h=$1 corpus="$dir/fuzz-corpus/$1" log="$dir/fuzz-artifacts/$1.log" seeds=()
  mkdir -p "$corpus"
  [ -d "fuzz/seeds/$h" ] && seeds+=("fuzz/seeds/$h")
  [ -d "tests/data/fuzz/$h" ] && seeds+=("tests/data/fuzz/$h")
  [ -n "${extra[$h]}" ] && seeds+=("${extra[$h]}")
  local TIMEFORMAT="cpu_seconds: %U user %S sys" rc=0
  { time "$dir/fuzz/fuzz_$h" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len=65536 -print_final_stats=1 -artifact_prefix="$dir/fuzz-artifacts/$h-" >"$log" 2>&1 || rc=$?; } 2>>"$log"
  echo "== fuzz_$h: ${seconds}s: $(grep -E 'stat::number_of_executed_units' "$log" | tr -s ' ') $(grep cpu_seconds "$log")"
  if [ $rc -ne 0 ]; then echo "fuzz_$h FAILED: see $log"; grep -A30 -E "ERROR|deadly|Timeout|out-of-memory" "$log" | head -40; fi
  return $rc
}
harnesses=(raw nrrd nrrd_gzip volvis_dat vtk_legacy vtu vti vtk_structured_points metaimage npy_volume tiff scene
           transfer_function viewer_protocol)
jobs=${FUZZ_JOBS:-$(nproc)}
[ "${FUZZ_PARALLEL:-0}" = 1 ] && jobs=${#harnesses[@]}  # every harness at once (the long campaign)
status=0 running=0
for h in "${harnesses[@]}"; do
  fuzz_one "$h" &
  if (( ++running >= jobs )); then wait -n || status=1; running=$((running - 1)); fi
done
while (( running > 0 )); do wait -n || status=1; running=$((running - 1)); done
exit $status
