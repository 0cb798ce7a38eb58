#!/usr/bin/env bash
# gallery.sh [BUILD_DIR]: renders every bundled scene (scenes/*.json) with its
# own method, longest side 320 pixels, into docs/gallery/SCENE.png, and writes
# docs/gallery/README.md: each picture with the command that made it (issue
# 20, item 6; the README shows the gallery). Re-run when a scene, a preset or
# the renderer changes.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=docs/gallery
mkdir -p "$out"
rm -f "$out"/*.png
{
  echo "# Gallery: the bundled scenes"
  echo
  echo "Made by \`bash scripts/gallery.sh\` ($(date -u '+%Y-%m-%d'), vri $("$build/vri" --version | cut -d' ' -f2)):"
  echo "each scene with its own method and transfer function, the longest side"
  echo "320 pixels. \`tests/scene/bundled_scenes_look_test.cpp\` checks that each one"
  echo "is drawn, inside its frame, and neither near-black nor a flat haze."
  echo
  echo "| scene | picture | command |"
  echo "|---|---|---|"
  for scene in scenes/*.json; do
    name=$(basename "$scene" .json)
    read -r w h < <(/usr/bin/python3 -c "
import json, sys
c = json.load(open('$scene'))['camera']; w, h = c.get('width', 512), c.get('height', 512); k = 320 / max(w, h)
print(round(w * k), round(h * k))")
    cmd="vri render $scene -o $out/$name.png --width $w --height $h"
    "$build/vri" render "$scene" -o "$out/$name.png" --width "$w" --height "$h" 2>/dev/null
    echo "| $name | ![$name]($name.png) | \`$cmd\` |"
  done
} >"$out/README.md.tmp"
mv "$out/README.md.tmp" "$out/README.md"
echo "gallery: $(ls "$out"/*.png | wc -l) scenes in $out"
