#!/usr/bin/env bash
# preint_accuracy.sh [BUILD_DIR] [TF] [N] [L]: the accuracy study of
# docs/PREINTEGRATION.md - every builder's table against `brute`, and the
# sliced builder (Roettger & Ertl 2002, Table 1) for 32 .. 1024 steps with
# 8-bit, 12-bit, fp16 and fp32 accumulation. RMS and max over all entries and
# channels, in percent of full scale (as in the paper).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; tf=${2:-presets/bonsai.json}; n=${3:-256}; len=${4:-1}
vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$vri" table --tf "$tf" --size "$n" --length "$len" --builder brute -o "$tmp/brute.npy" 2>/dev/null
# RMS over the four channels' RMS, max over their maxima, in percent.
summary() {
  "$vri" compare "$tmp/brute.npy" "$1" --tolerance 1 --max-share 1 |
    awk 'NR > 1 { s += $3 * $3; if ($4 > m) m = $4 } END { printf "%.3g%% | %.3g%%", 100 * sqrt(s / 4), 100 * m }'
}
echo "| builder | RMS error | max error |"
echo "|---|---|---|"
for b in incremental engel; do
  "$vri" table --tf "$tf" --size "$n" --length "$len" --builder $b -o "$tmp/$b.npy" 2>/dev/null
  echo "| $b | $(summary "$tmp/$b.npy") |"
done
echo
echo "| sliced steps | 8-bit RMS | 8-bit max | 12-bit RMS | 12-bit max | fp16 RMS | fp16 max | fp32 RMS | fp32 max |"
echo "|---|---|---|---|---|---|---|---|---|"
for steps in 32 64 128 256 512 1024; do
  row="| $steps"
  for acc in 8bit 12bit fp16 fp32; do
    "$vri" table --tf "$tf" --size "$n" --length "$len" --builder sliced --steps $steps --accumulation $acc \
      -o "$tmp/s.npy" 2>/dev/null
    row="$row | $(summary "$tmp/s.npy")"
  done
  echo "$row |"
done
