#!/usr/bin/env bash
# distributed_figures.sh [BUILD] [SCENE] [SIZE]: the figures of docs/DISTRIBUTED.md.
# For N = 1, 2, 4, 8 ranks (oversubscribed past the machine's cores): the
# largest brick's samples, rank 0's render and compositing times as vri
# reports them, and the largest difference from the one-process image.
set -euo pipefail
build=${1:-build} scene=${2:-scenes/engine.json} size=${3:-256}
vri=$build/vri
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "# $(date -u '+%F %T') UTC, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# $scene at ${size}x$size, method preint1 ${EXTRA:-}, 1 thread a rank"
flags=(--width "$size" --height "$size" --method preint1 --threads 1 -q ${EXTRA:-})
"$vri" render "$scene" -o "$tmp/one.npy" "${flags[@]}" 2>"$tmp/log"
echo "one process: $(grep -o 'in [0-9.e-]* s' "$tmp/log" | head -1)"
echo "| ranks | largest brick (bytes) | rank 0 render s | composite s | max difference |"
echo "|---|---|---|---|---|"
for n in 1 2 4 8; do
  mpirun --allow-run-as-root --oversubscribe -np "$n" "$vri" render "$scene" -o "$tmp/many.npy" "${flags[@]}" \
    --distributed 2>"$tmp/log"
  line=$(grep 'ranks:' "$tmp/log")
  render=$(sed -E 's/.*brick in ([0-9.e-]+) s.*/\1/' <<<"$line")
  composite=$(sed -E 's/.*composited in ([0-9.e-]+) s.*/\1/' <<<"$line")
  bytes=$(sed -E 's/.*largest brick ([0-9]+) bytes.*/\1/' <<<"$line")
  diff=$("$vri" compare "$tmp/one.npy" "$tmp/many.npy" --tolerance 1 | awk 'NR > 1 {print $4}' | sort -g | tail -1)
  echo "| $n | $bytes | $render | $composite | $diff |"
done
