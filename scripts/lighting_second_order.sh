#!/usr/bin/env bash
# lighting_second_order.sh [BUILD_DIR] [SIZE] [SCENES...]: lit preint2 against
# lit preint1 (docs/LIGHTING.md, "Second order"). Per scene (default
# scenes/neghip_lit.json) at SIZE x SIZE: lit `exact` (tolerance 1e-6), then
# preint1 sampled / interpolated at steps 2 and 1 and preint2 sampled /
# interpolated at steps 2 and 1 (table 256, the scene's). Prints the colour
# error against exact (worst of r, g, b: RMS, max, share of pixels off by more
# than 1/255), the shading error (as scripts/lighting_results.sh), the render
# time (wall, without the table build) and the whole run's wall and CPU time
# (table build included). Writes docs/lighting/<scene>_preint2_<mode>_step2.png.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; size=${2:-256}; shift $(( $# > 2 ? 2 : $# ))
scenes=("${@:-scenes/neghip_lit.json}")
vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p docs/lighting
source scripts/lighting_common.sh
# render plus the whole run's wall and CPU (user + system) seconds: "render | wall | cpu".
timed() {  # scene out args...
  local TIMEFORMAT='%R %U %S' t
  t=$( { time render "$@" > "$tmp/render_s"; } 2>&1 )
  echo "$(cat "$tmp/render_s") | $(awk '{ printf "%.2f | %.2f", $1, $2 + $3 }' <<< "$t")"
}
echo "| scene | method | step | colour RMS | colour max | share > 1/255 | shading RMS | render (s) | run wall (s) | run CPU (s) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .json)
  for mode in sampled interpolated unlit; do variant "$scene" $mode "$tmp/$mode.json"; done
  echo "| $name | exact | - | - | - | - | - | $(timed "$tmp/sampled.json" "$tmp/exact.npy" --method exact --tolerance 1e-6) |"
  render "$tmp/unlit.json" "$tmp/exact_unlit.npy" --method exact --tolerance 1e-6 > /dev/null
  for method in preint1 preint2; do
    for step in 2 1; do
      render "$tmp/unlit.json" "$tmp/unlit.npy" --method $method --step $step > /dev/null
      for mode in sampled interpolated; do
        t=$(timed "$tmp/$mode.json" "$tmp/$mode.npy" --method $method --step $step)
        [ "$method$step" = preint22 ] &&
          render "$tmp/$mode.json" "docs/lighting/${name}_preint2_${mode}_step2.png" --method preint2 --step 2 > /dev/null
        echo "| $name | $method $mode | $step | $(colour_err "$tmp/exact.npy" "$tmp/$mode.npy") |" \
             "$(shading_err "$tmp/$mode.npy" "$tmp/unlit.npy" "$tmp/exact.npy" "$tmp/exact_unlit.npy") | $t |"
      done
    done
  done
done
