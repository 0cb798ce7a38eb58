#!/usr/bin/env bash
# second_order_rays.sh [BUILD_DIR]: the ray table of docs/SECOND_ORDER.md ("One
# ray"): for neghip, fuel and bucky and the samplings step 2, step 1 and cell
# faces + midpoints, the mean samples per ray and mean xi of the 0th/1st/2nd-
# order approximations over a 9 x 9 grid of pixels (160 ... 352 of 512), and
# the plots of one ray (pixel 240 250) in docs/second_order/
set -euo pipefail
cd "$(dirname "$0")/.."
vri=${1:-build}/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for name in neghip fuel bucky; do
  for sampling in 2 1 dual; do
    args=(); [ "$sampling" != dual ] && args=(--step "$sampling")
    for x in $(seq 160 24 352); do for y in $(seq 160 24 352); do
      # prints "samples N  xi0 A  xi1 B  xi2 C"; a ray that misses the volume prints nothing
      "$vri" ray "scenes/$name.json" --pixel "$x" "$y" "${args[@]}" -o "$tmp/ray.csv" 2>/dev/null || true
    done; done | awk -v nm="$name" -v st="$sampling" '{ n++; k += $2; a += $4; b += $6; c += $8 }
      END { printf "| %s | %s | %d | %.0f | %.3g | %.3g | %.3g | %.2f |\n", nm, st, n, k / n, a / n, b / n, c / n, c / b }'
  done
done
# The two plots of one neghip ray linked from the same section.
"$vri" ray scenes/neghip.json --pixel 240 250 --step 2 -o "$tmp/ray.csv" --plot docs/second_order/neghip_ray_240_250_2.svg
"$vri" ray scenes/neghip.json --pixel 240 250 -o "$tmp/ray.csv" --plot docs/second_order/neghip_ray_240_250_dual.svg
