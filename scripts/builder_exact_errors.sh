#!/usr/bin/env bash
# builder_exact_errors.sh [BUILD_DIR]: the figure of docs/PREINTEGRATION.md
# §4 "Builders against exact" - every first-order builder's table against
# `--builder exact` for spiky transfer functions whose features fall between
# the table scalars (presets/neghip_spike.json: a spike 0.6 scalar units wide;
# presets/bonsai.json), N = 64 and 256, l = 1: max |entry - exact| over all
# entries and channels, and the build time `vri table` reports.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "| TF | N | builder | max abs error vs exact | build time |"
echo "|---|---|---|---|---|"
for tf in presets/neghip_spike.json presets/bonsai.json; do
  for n in 64 256; do
    "$vri" table --tf "$tf" --size $n --builder exact -o "$tmp/exact.npy" 2>/dev/null
    for b in brute incremental engel sliced; do
      t=$("$vri" table --tf "$tf" --size $n --builder $b -o "$tmp/$b.npy" 2>&1 | sed -n 's/.* in \([0-9.e-]*\) s .*/\1/p')
      err=$("$vri" compare "$tmp/exact.npy" "$tmp/$b.npy" --tolerance 1 --max-share 1 | awk 'NR > 1 { if ($4 > m) m = $4 } END { printf "%.3g", m }')
      echo "| $(basename "$tf" .json) | $n | $b | $err | $(awk -v t="$t" 'BEGIN { printf "%.3g ms", 1000 * t }') |"
    done
  done
done
