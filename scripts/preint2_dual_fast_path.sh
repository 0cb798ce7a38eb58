#!/usr/bin/env bash
# preint2_dual_fast_path.sh [BUILD_DIR] [RUNS]: preint2-dual's fast path
# (float path and empty-space skipping, the defaults; the lit scenes lit in
# their own mode, interpolated) against its plain path
# (--double --no-skip), whole `vri render` processes at the scenes' 512 x 512,
# paired runs with farm-bench (median ratios); checks that skipping changes no
# byte (default against --no-skip) and gives the float path's largest
# difference from the double path. docs/SECOND_ORDER.md, "preint2-dual".
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; runs=${2:-3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| scene | fast wall s | plain wall s | fast / plain, wall | CPU | skipping: same bytes | max abs float - double |"
echo "|---|---|---|---|---|---|---|"
for name in neghip fuel bonsai engine neghip_lit fuel_lit; do
  out=$(farm-bench -n "$runs" --vs "$build/vri render scenes/$name.json -o $tmp/plain.npy --method preint2-dual --double --no-skip" \
    -- "$build/vri" render "scenes/$name.json" -o "$tmp/fast.npy" --method preint2-dual 2>&1)
  med() { echo "$out" | awk -v k="$1" '$0 ~ "^"k { print $(NF-1) }'; }
  "$build/vri" render "scenes/$name.json" -o "$tmp/noskip.npy" --method preint2-dual --no-skip > /dev/null 2>&1
  same=no; cmp -s "$tmp/fast.npy" "$tmp/noskip.npy" && same=yes
  diff=$(/usr/bin/python3 tools/npy_diff.py "$tmp/fast.npy" "$tmp/plain.npy")
  echo "| $name | $(med 'A wall s') | $(med 'B wall s') | $(med 'A/B wall') | $(med 'A/B cpu') | $same | $diff |"
done
