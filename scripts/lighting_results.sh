#!/usr/bin/env bash
# lighting_results.sh [BUILD_DIR] [SIZE]: the lit grid scenes (scenes/*_lit.json,
# four narrow transfer-function spikes) at SIZE x SIZE with lit `exact`
# (tolerance 1e-6) and lit `preint1`, lighting.mode sampled and interpolated,
# at steps 1 and 2. Writes docs/lighting/<scene>_<method>.png and prints the
# table of docs/LIGHTING.md: per method the colour error against exact (worst
# of r, g, b: RMS, max, share of pixels off by more than 1/255, by
# `vri compare`), the shading error (RMS of (lit - unlit) - (lit - unlit) of
# exact, r, g, b) and the render time.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; size=${2:-256}
vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p docs/lighting
source scripts/lighting_common.sh
echo "| scene | method | step | colour RMS | colour max | share > 1/255 | shading RMS | time (s) |"
echo "|---|---|---|---|---|---|---|---|"
for scene in scenes/*_lit.json; do
  name=$(basename "$scene" .json)
  if grep -q '"\(tetrahedralized\)"\|\.vt[ku]"' "$scene"; then continue; fi  # meshes: mesh_lighting_results.sh
  for mode in sampled interpolated unlit; do variant "$scene" $mode "$tmp/$mode.json"; done
  t=$(render "$tmp/sampled.json" "$tmp/exact.npy" --method exact --tolerance 1e-6)
  render "$tmp/unlit.json" "$tmp/exact_unlit.npy" --method exact --tolerance 1e-6 > /dev/null
  render "$tmp/sampled.json" "docs/lighting/${name}_exact.png" --method exact --tolerance 1e-6 > /dev/null
  echo "| $name | exact | - | - | - | - | - | $t |"
  for step in 1 2; do
    render "$tmp/unlit.json" "$tmp/unlit.npy" --method preint1 --step $step > /dev/null
    for mode in sampled interpolated; do
      t=$(render "$tmp/$mode.json" "$tmp/$mode.npy" --method preint1 --step $step)
      render "$tmp/$mode.json" "docs/lighting/${name}_${mode}_step${step}.png" --method preint1 --step $step > /dev/null
      echo "| $name | preint1 $mode | $step | $(colour_err "$tmp/exact.npy" "$tmp/$mode.npy") |" \
           "$(shading_err "$tmp/$mode.npy" "$tmp/unlit.npy" "$tmp/exact.npy" "$tmp/exact_unlit.npy") | $t |"
    done
  done
done
