#!/usr/bin/env bash
# exact_vs_reference.sh VRI SOURCE_DIR: renders bundled scenes with vri and
# checks them against tools/reference_spec4.py, an independent NumPy
# implementation of SPEC §4 (and of the riemann convention).
set -euo pipefail
vri=$(realpath "$1"); src=$(cd "$2" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
py=/usr/bin/python3
# an orthographic, anisotropic variant of bucky, written with absolute paths
cat >"$tmp/ortho.json" <<JSON
{"volume": {"file": "$src/data/bucky_32x32x32_uint8.raw", "dims": [32, 32, 32], "type": "uint8",
            "spacing": [1, 0.8, 1.3], "origin": [2, -1, 0.5]},
 "transfer_function": {"file": "$src/presets/bucky.json"},
 "camera": {"eye": [70, 40, 60], "target": [17.5, 11.4, 20.65], "up": [0, 0, 1],
            "projection": "orthographic", "ortho_height": 50, "width": 64, "height": 48}}
JSON
# neghip lit with the SPEC §5 defaults
sed -e 's|"../data/|"'"$src"'/data/|; s|"../presets/|"'"$src"'/presets/|' "$src/scenes/neghip.json" |
  $py -c 'import json,sys; s=json.load(sys.stdin); s["lighting"]={"enabled": True}; json.dump(s, sys.stdout)' >"$tmp/lit.json"
for scene in "$src/scenes/neghip.json" "$src/scenes/silicium.json" "$tmp/ortho.json" "$tmp/lit.json"; do
  "$vri" render "$scene" -o "$tmp/exact.npy" --method exact --tolerance 1e-5 --width 96 --height 72 2>/dev/null
  echo "exact, $(basename "$scene"):"
  # the lit integrand's specular peaks need a finer reference step
  step=0.01; [ "$scene" = "$tmp/lit.json" ] && step=0.0025
  $py "$src/tools/reference_spec4.py" "$scene" "$tmp/exact.npy" --pixels 150 --step $step --max-diff 1e-4
  "$vri" render "$scene" -o "$tmp/riemann.npy" --method riemann --step 0.1 --width 96 --height 72 2>/dev/null
  echo "riemann 0.1, $(basename "$scene"):"
  $py "$src/tools/reference_spec4.py" "$scene" "$tmp/riemann.npy" --pixels 150 --riemann 0.1 --max-diff 1e-4
done
