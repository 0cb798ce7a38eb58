#!/usr/bin/env bash
# cross_aarch64.sh [DIR] [extra cmake args...]: cross-builds vri and its tests for aarch64 (Debian's
# g++-aarch64-linux-gnu and arm64 dev packages; cmake/toolchains/) into DIR
# (default build-aarch64) and runs the tests under qemu-user
# (docs/PORTABILITY.md). Installs what it needs with apt (root or sudo).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-aarch64}; shift || true
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
# Header-only packages are architecture-independent; the rest are the arm64
# builds of what scripts/install-deps.sh installs.
pkgs=(g++-aarch64-linux-gnu qemu-user cmake make python3 python3-numpy nlohmann-json3-dev libcli11-dev
      libtbb-dev:arm64 libpng-dev:arm64 zlib1g-dev:arm64 libgtest-dev:arm64)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "cross_aarch64: installing ${missing[*]}"
  dpkg --print-foreign-architectures | grep -qx arm64 || $SUDO dpkg --add-architecture arm64
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
start=$SECONDS
cmake -S . -B "$dir" -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu.cmake -DCMAKE_BUILD_TYPE=Release \
      -DVRI_BUILD_TESTS=ON -DVRI_BUILD_BENCH=OFF -DVRI_PYTHON=OFF "$@" >/dev/null  # no arm64 python3-dev here
cmake --build "$dir" -j "$(nproc)"
echo "cross_aarch64: built in $((SECONDS - start)) s"
start=$SECONDS
(cd "$dir" && ctest --output-on-failure -j "$(nproc)")
echo "cross_aarch64: tests under qemu-aarch64 in $((SECONDS - start)) s"
