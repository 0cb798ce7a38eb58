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
source scripts/fastest_renders.sh
timing_setup "$@"
echo
echo "| scene | h (voxels) | preint1 @ h ms | preint2 @ h ms | preint2-dual ms | preint2 / preint1 | preint2-dual / preint1 |"
echo "|---|---|---|---|---|---|---|"
for s in neghip engine bonsai fuel bucky; do
  h=$(/usr/bin/python3 - "$vri" "scenes/$s.json" <<'PY'
import json, os, subprocess, sys
import numpy as np
vri, path = sys.argv[1:]
# The camera as vri resolves it (fit, motions) and the spacing as vri reads the volume.
camera = json.loads(subprocess.run([vri, "camera", path], capture_output=True, check=True).stdout)
volume = json.load(open(path))["volume"]
raw = ["--dims", *map(str, volume["dims"]), "--type", volume["type"]] if "dims" in volume else []
info = subprocess.run([vri, "info", os.path.join(os.path.dirname(path), volume["file"]), *raw],
                      capture_output=True, check=True, text=True).stdout
spacing = np.array([float(x) for x in next(l for l in info.splitlines() if l.startswith("spacing:")).split()[1:4]])
d = np.array(camera["target"], float) - np.array(camera["eye"], float)
d /= np.linalg.norm(d)
segment = 1 / np.sum(np.abs(d) / spacing)  # world units per cell segment
print(f"{segment / 2 / spacing.min():.3f}")  # half a segment, in voxels
PY
)
  args=("--method preint1 --step $h" "--method preint2 --step $h" "--method preint2-dual")
  fastest_renders "$vri" "scenes/$s.json" "$reps" "$tmp" "${args[@]}"
  echo "| $s | $h | ${best[0]} | ${best[1]} | ${best[2]} |" \
       "$(awk -v a="${best[1]}" -v b="${best[0]}" 'BEGIN { printf "%.2f", a / b }') |" \
       "$(awk -v a="${best[2]}" -v b="${best[0]}" 'BEGIN { printf "%.2f", a / b }') |"
done
