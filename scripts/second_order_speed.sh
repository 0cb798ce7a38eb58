#!/usr/bin/env bash
# second_order_speed.sh [BUILD_DIR] [REPEATS]: `preint2` and `preint2-dual`
# frames beside `preint1` at equal step (issue 21, item 4; docs/PERFORMANCE.md,
# "Second order beside preint1"). `preint2-dual` has no step: it samples each
# cell segment at its front, middle and back, so its samples lie half a
# segment apart, and a ray in direction d crosses sum_a |d_a| / s_a cells per
# unit length (s: the grid spacing). h, the dual's sample spacing along the
# view direction in voxel units, is the step that gives preint1 and preint2
# as many samples. Each scene at its own 512 x 512, 2 threads, the float
# paths (the defaults), the three renderers in turn REPEATS times (default 3),
# fastest render time as vri reports it.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; reps=${2:-3}; vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "Load average: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores; $(date -u '+%Y-%m-%d %H:%M UTC')."
echo
echo "| scene | h (voxels) | preint1 @ h ms | preint2 @ h ms | preint2-dual ms | preint2 / preint1 | preint2-dual / preint1 |"
echo "|---|---|---|---|---|---|---|"
for s in neghip engine bonsai fuel bucky; do
  h=$(/usr/bin/python3 - "scenes/$s.json" <<'EOF'
import json, sys, numpy as np
scene = json.load(open(sys.argv[1]))
spacing = np.array(scene["volume"].get("spacing", [1, 1, 1]), float)
d = np.array(scene["camera"]["target"], float) - np.array(scene["camera"]["eye"], float)
d /= np.linalg.norm(d)
segment = 1 / np.sum(np.abs(d) / spacing)          # world units per cell segment
print(f"{segment / 2 / spacing.min():.3f}")         # half a segment, in voxels
EOF
)
  args=("--method preint1 --step $h" "--method preint2 --step $h" "--method preint2-dual")
  best=()
  for _ in $(seq "$reps"); do
    for i in "${!args[@]}"; do
      # shellcheck disable=SC2086
      w=$("$vri" render "scenes/$s.json" ${args[$i]} --threads 2 -q -o "$tmp/$i.npy" 2>&1 |
          awk '/rendered/ { for (j = 1; j < NF; ++j) if ($j == "in") printf "%.1f", $(j + 1) * 1000 }')
      if [[ -z ${best[$i]:-} ]] || awk -v a="$w" -v b="${best[$i]}" 'BEGIN { exit !(a < b) }'; then best[$i]=$w; fi
    done
  done
  echo "| $s | $h | ${best[0]} | ${best[1]} | ${best[2]} |" \
       "$(awk -v a="${best[1]}" -v b="${best[0]}" 'BEGIN { printf "%.2f", a / b }') |" \
       "$(awk -v a="${best[2]}" -v b="${best[0]}" 'BEGIN { printf "%.2f", a / b }') |"
done
