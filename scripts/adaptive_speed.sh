#!/usr/bin/env bash
# adaptive_speed.sh [BUILD_DIR] [REPEATS]: `adaptive` beside `riemann` at
# h = 0.1 (issue 21, item 2; docs/PERFORMANCE.md, "Adaptive"): bonsai and
# neghip at 512², 2 threads, each strategy at tolerance 1e-3 and riemann at
# h = 0.1 (float path, skipping) rendered in turn REPEATS times (default 3),
# fastest wall time as vri reports it, and each image's error against
# `exact` at 1e-6: the largest and the share of pixels over 1e-3 (riemann
# reaches no pixel over 1e-3 at any step down to 1/32 on these scenes:
# docs/ACCURACY.md).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/fastest_renders.sh
timing_setup "$@"
echo
echo "| scene | renderer | wall ms | riemann h = 0.1 / this | largest error | pixels over 1e-3 |"
echo "|---|---|---|---|---|---|"
for s in bonsai neghip; do
  "$vri" render "scenes/$s.json" --method exact --tolerance 1e-6 -q -o "$tmp/exact.npy" 2>/dev/null
  names=("riemann h = 0.1" "adaptive coupled 1e-3" "adaptive decoupled 1e-3" "adaptive guaranteed 1e-3")
  args=("--method riemann --step 0.1" "--method adaptive --strategy coupled --tolerance 1e-3"
        "--method adaptive --strategy decoupled --tolerance 1e-3" "--method adaptive --strategy guaranteed --tolerance 1e-3")
  fastest_renders "$vri" "scenes/$s.json" "$reps" "$tmp" "${args[@]}"
  for i in "${!args[@]}"; do
    err=$(/usr/bin/python3 -c "
import numpy as np, sys
a, e = np.load('$tmp/$i.npy').astype(float), np.load('$tmp/exact.npy').astype(float)
d = np.abs(a - e)
print(f'{d.max():.2e} | {100 * np.mean(np.any(d > 1e-3, axis=-1)):.3f}%')")
    echo "| $s | ${names[$i]} | ${best[$i]} | $(awk -v r="${best[0]}" -v w="${best[$i]}" 'BEGIN { printf "%.2f", r / w }') | $err |"
  done
done
