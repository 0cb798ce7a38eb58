#!/usr/bin/env bash
# preint1_accuracy.sh [BUILD_DIR] [SIZE]: renders every bundled grid scene (lit
# ones lit; the mesh scenes are left out) at
# SIZE x SIZE with `exact` (tolerance 1e-5) and with `preint1` and `riemann`
# at steps 1 and 0.5, and prints the alpha-channel RMS and max error of each
# against `exact` (docs/PREINTEGRATION.md).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; size=${2:-96}
vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
err() { "$vri" compare "$tmp/exact.npy" "$1" --tolerance 1 --max-share 1 | awk '$1 == "a" { printf "%.2e / %.2e", $3, $4 }'; }
echo "| scene | preint1 h=1 | riemann h=1 | preint1 h=0.5 | riemann h=0.5 |"
echo "|---|---|---|---|---|"
for scene in scenes/*.json; do
  name=$(basename "$scene" .json)
  if grep -q '"\(tetrahedralized\)"\|\.vt[ku]"' "$scene"; then continue; fi  # a tetrahedral mesh
  common=(--width "$size" --height "$size")
  "$vri" render "$scene" -o "$tmp/exact.npy" --method exact --tolerance 1e-5 "${common[@]}" 2>/dev/null
  row="| $name"
  for step in 1 0.5; do
    for m in preint1 riemann; do
      "$vri" render "$scene" -o "$tmp/$m.npy" --method $m --step $step "${common[@]}" 2>/dev/null
      row="$row | $(err "$tmp/$m.npy")"
    done
  done
  echo "$row |"
done
