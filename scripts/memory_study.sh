#!/usr/bin/env bash
# memory_study.sh [BUILD_DIR]: peak memory of every grid method (issue 21,
# item 6; docs/PERFORMANCE.md, "Memory"). One `vri render` per method on
# bonsai (256³ uint8, 16 MiB) at 512², 2 threads, under GNU time: its maximum
# RSS beside the volume and the method's tables (their sizes from the table
# layouts: RGBA float32 entries, N² for preint1, N³ for preint2 and the
# 32 lengths × N³ for preint2-dual), and what is left:
# the process, the image, the macro cells and the per-thread workspace. The
# last rows render preint1 at 1024² and on 1 thread: the rest grows with the
# image (16 bytes a pixel) and not with the threads.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
rss() {  # rss ARGS...: maximum RSS of one render, MiB
  /usr/bin/time -v "$vri" render scenes/bonsai.json -q -o "$tmp/out.npy" "$@" >"$tmp/log" 2>&1
  awk '/Maximum resident set size/ { printf "%.1f", $NF / 1024 }' "$tmp/log"
}
echo "Load average: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores; $(date -u '+%Y-%m-%d %H:%M UTC')."
echo
echo "| method | size, threads | tables | peak RSS MiB | volume MiB | tables MiB | rest MiB |"
echo "|---|---|---|---|---|---|---|"
volume=16.0
row() {  # row LABEL SIZE THREADS TABLES TABLE_MIB ARGS...
  local label=$1 size=$2 threads=$3 tables=$4 table_mib=$5; shift 5
  local r; r=$(rss --width "$size" --height "$size" --threads "$threads" "$@")
  echo "| $label | ${size}², $threads | $tables | $r | $volume | $table_mib | $(awk -v r="$r" -v v="$volume" -v t="$table_mib" 'BEGIN { printf "%.1f", r - v - t }') |"
}
mib() { awk -v b="$1" 'BEGIN { printf "%.1f", b / 1048576 }'; }
row "riemann step 1" 512 2 "none" 0 --method riemann --step 1
row "preint1 step 1" 512 2 "256² first order" "$(mib $((256 * 256 * 16)))" --method preint1 --step 1
row "preint2 step 1" 512 2 "256³ second order" "$(mib $((256 * 256 * 256 * 16)))" --method preint2 --step 1
row "preint2 step 1, N = 64" 512 2 "64³" "$(mib $((64 * 64 * 64 * 16)))" --method preint2 --step 1 --table-size 64
row "preint2-dual" 512 2 "32 × 64³" "$(mib $((32 * 64 * 64 * 64 * 16)))" --method preint2-dual
row "adaptive guaranteed 1e-3" 512 2 "none" 0 --method adaptive --strategy guaranteed --tolerance 1e-3
row "adaptive coupled 1e-3" 512 2 "none" 0 --method adaptive --strategy coupled --tolerance 1e-3
row "exact 1e-4" 512 2 "none" 0 --method exact --tolerance 1e-4
row "preint1 step 1" 1024 2 "256²" "$(mib $((256 * 256 * 16)))" --method preint1 --step 1
row "preint1 step 1" 512 1 "256²" "$(mib $((256 * 256 * 16)))" --method preint1 --step 1
