#!/usr/bin/env bash
# run_harness.sh HARNESS SECONDS BUILD_DIR: one libFuzzer harness for SECONDS
# (FUZZ_SECONDS, when set, wins) on its seed corpus: the ctest `fuzz_HARNESS`
# (label fuzz) that scripts/fuzz.sh runs. Its corpus grows in BUILD_DIR/fuzz-corpus/HARNESS; its log,
# BUILD_DIR/fuzz-artifacts/HARNESS.log, ends with libFuzzer's stats and the
# CPU seconds it used; a failing input is left beside it.
set -uo pipefail
h=$1 seconds=${FUZZ_SECONDS:-$2} dir=$3
cd "$(dirname "$0")/.."
# Seeds: small generated files (fuzz/seeds/), what the harness once failed
# on (tests/data/fuzz/), and the bundled inputs of its kind.
declare -A extra=(
  [vtk_legacy]="tests/data/mesh" [vtu]="tests/data/mesh"
  [vti]="tests/data/volume" [vtk_structured_points]="tests/data/volume"
  [scene]="scenes" [transfer_function]="presets"
)
corpus="$dir/fuzz-corpus/$h" log="$dir/fuzz-artifacts/$h.log" seeds=()
mkdir -p "$corpus" "$dir/fuzz-artifacts"
[ -d "fuzz/seeds/$h" ] && seeds+=("fuzz/seeds/$h")
[ -d "tests/data/fuzz/$h" ] && seeds+=("tests/data/fuzz/$h")
[ -n "${extra[$h]:-}" ] && seeds+=("${extra[$h]}")
TIMEFORMAT="cpu_seconds: %U user %S sys" rc=0
{ time "$dir/fuzz/fuzz_$h" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$dir/fuzz-artifacts/$h-" >"$log" 2>&1 || rc=$?; } 2>>"$log"
echo "== fuzz_$h: ${seconds}s: $(grep -E 'stat::number_of_executed_units' "$log" | tr -s ' ') $(grep cpu_seconds "$log")"
if [ $rc -ne 0 ]; then echo "fuzz_$h FAILED: see $log"; grep -A30 -E "ERROR|deadly|Timeout|out-of-memory" "$log" | head -40; fi
exit $rc
