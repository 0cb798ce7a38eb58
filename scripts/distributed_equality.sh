#!/usr/bin/env bash
# distributed_equality.sh [BUILD] [SIZE]: issue 23, item 3, written to
# docs/distributed/equality.txt: every bundled grid scene with `exact`,
# `riemann` (step 0.5), `preint1` and `preint2` (step 1; the scene's table
# size, preint2's 64 a side), at SIZE x SIZE (default 256), rendered by one
# process and by `mpirun -np N` for N = 2, 3, 4 and 8 (one thread a rank,
# oversubscribed past this machine's cores), and the largest difference
# between the two images (SPEC §11: within 1e-6). The last line is the
# largest of the table.
set -euo pipefail
build=${1:-build} size=${2:-256}
source "$(dirname "$0")/distributed_common.sh"
distributed_setup "$build"
echo "# $(date -u '+%F %T') UTC, $(nproc) cores, ${size}x${size}, one thread a rank," \
     "Open MPI $(mpirun --version | head -1 | awk '{print $NF}')"
echo "| scene | method | 2 ranks | 3 ranks | 4 ranks | 8 ranks |"
echo "|---|---|---|---|---|---|"
worst=0
for scene in scenes/*.json; do
  name=$(basename "$scene" .json)
  case $name in blunt_fin*) continue ;; esac  # tetrahedral meshes
  for method in "exact" "riemann --step 0.5" "preint1 --step 1" "preint2 --step 1 --table-size 64"; do
    args=(--method $method --width "$size" --height "$size" -q)
    "$vri" render "$scene" -o "$tmp/one.npy" "${args[@]}" 2>/dev/null
    row="| $name | ${method%% *}"
    for n in 2 3 4 8; do
      mpirun --allow-run-as-root --oversubscribe -np "$n" "$vri" render "$scene" -o "$tmp/many.npy" "${args[@]}" \
        --threads 1 2>/dev/null
      d=$(largest "$tmp/one.npy" "$tmp/many.npy")
      worst=$(awk -v a="$d" -v b="$worst" 'BEGIN { print (a > b) ? a : b }')
      row+=" | $d"
    done
    echo "$row |"
  done
done
echo
echo "largest difference: $worst"
