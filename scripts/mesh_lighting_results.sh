#!/usr/bin/env bash
# mesh_lighting_results.sh [BUILD_DIR] [SIZE] [THREADS]: scenes/blunt_fin_lit.json
# (smooth opacity) and scenes/blunt_fin_spikes_lit.json (two narrow spikes:
# transparent isosurfaces) at SIZE x SIZE with lit mesh `exact` (tolerance
# 1e-6) and lit `tet-raycast`, `pt` and `pt-cylindrical` (the scenes' tables:
# 128 resp. 256 scalars x 64 lengths, planes = scalars), lighting.mode
# sampled and interpolated. Writes docs/lighting/<scene>_<method>_<mode>.png
# and prints the table of docs/MESHES.md (Lighting): the colour error against
# exact (worst of r, g, b: RMS, max, share off by more than 1/255, by
# `vri compare`), the shading error (RMS of (lit - unlit) - (lit - unlit) of
# exact, r, g, b; scripts/lighting_common.sh), the render time `vri` reports
# (tables excluded) and the CPU time of the whole process (tables included).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; size=${2:-256}; threads=${3:-2}
vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p docs/lighting
source scripts/lighting_common.sh
cpu() {  # scene out args... -> "render_s | cpu_s"
  local out
  out=$(/usr/bin/time -f "CPU %U %S" "$vri" render "$1" -o "$2" --width "$size" --height "$size" "${@:3}" \
        --threads "$threads" 2>&1)
  printf "%s | %.2f" "$(sed -n 's/.* in \([0-9.e-]*\) s.*/\1/p' <<< "$out")" "$(awk '/^CPU/ {print $2 + $3}' <<< "$out")"
}
echo "| scene | method | mode | colour RMS | colour max | share > 1/255 | shading RMS | render (s) | run CPU (s) |"
echo "|---|---|---|---|---|---|---|---|---|"
for scene in scenes/blunt_fin_lit.json scenes/blunt_fin_spikes_lit.json; do
  name=$(basename "$scene" .json)
  for mode in sampled interpolated unlit; do variant "$scene" $mode "$tmp/$mode.json"; done
  t=$(cpu "$tmp/sampled.json" "$tmp/exact.npy" --method exact --tolerance 1e-6)
  render "$tmp/unlit.json" "$tmp/exact_unlit.npy" --method exact --tolerance 1e-6 --threads "$threads" > /dev/null
  "$vri" render "$tmp/sampled.json" -o "docs/lighting/${name}_exact.png" --method exact --width "$size" --height "$size" > /dev/null 2>&1
  echo "| $name | exact | - | - | - | - | - | $t |"
  for method in tet-raycast pt pt-cylindrical; do
    render "$tmp/unlit.json" "$tmp/unlit.npy" --method $method --threads "$threads" > /dev/null
    echo "| $name | $method | unlit (vs unlit exact) | $(colour_err "$tmp/exact_unlit.npy" "$tmp/unlit.npy") | - | - | - |"
    for mode in sampled interpolated; do
      t=$(cpu "$tmp/$mode.json" "$tmp/$mode.npy" --method $method)
      [ $method = pt ] && "$vri" render "$tmp/$mode.json" -o "docs/lighting/${name}_${method}_${mode}.png" \
                            --method $method --width "$size" --height "$size" > /dev/null 2>&1
      echo "| $name | $method | $mode | $(colour_err "$tmp/exact.npy" "$tmp/$mode.npy") |" \
           "$(shading_err "$tmp/$mode.npy" "$tmp/unlit.npy" "$tmp/exact.npy" "$tmp/exact_unlit.npy") | $t |"
    done
  done
done
