#!/usr/bin/env bash
# The main job on a fresh machine: install dependencies, build, render the
# bundled neghip dataset with the reference `exact` method to out/neghip.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh build -DVRI_BUILD_TESTS=OFF -DVRI_BUILD_BENCH=OFF
mkdir -p out
./build/vri render scenes/neghip.json -o out/neghip.png
./build/vri render scenes/neghip.json -o out/neghip.npy
echo "demo: wrote $(pwd)/out/neghip.png (and the float image out/neghip.npy)"
