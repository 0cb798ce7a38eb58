#!/usr/bin/env bash
# preint2_dual_fast_path.sh [BUILD_DIR] [RUNS]: preint2-dual with empty-space
# skipping (the default) against --no-skip, whole `vri render` processes at the
# scenes' 512 x 512, paired runs with farm-bench (median ratios), and a check
# that both images are the same bytes. docs/SECOND_ORDER.md, "preint2-dual".
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; runs=${2:-3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| scene | skip wall s | --no-skip wall s | skip / no-skip, wall | CPU | same bytes |"
echo "|---|---|---|---|---|---|"
for name in neghip fuel bonsai engine; do
  out=$(farm-bench -n "$runs" --vs "$build/vri render scenes/$name.json -o $tmp/plain.npy --method preint2-dual --no-skip" \
    -- "$build/vri" render "scenes/$name.json" -o "$tmp/skip.npy" --method preint2-dual 2>&1)
  med() { echo "$out" | awk -v k="$1" '$0 ~ "^"k { print $(NF-1) }'; }
  same=no; cmp -s "$tmp/plain.npy" "$tmp/skip.npy" && same=yes
  echo "| $name | $(med 'A wall s') | $(med 'B wall s') | $(med 'A/B wall') | $(med 'A/B cpu') | $same |"
done
