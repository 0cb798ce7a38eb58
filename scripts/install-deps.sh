#!/usr/bin/env bash
# install-deps.sh [--vtk]: installs vri's build and test dependencies from Debian packages.
# Skips apt entirely when everything is already installed.
set -euo pipefail
pkgs=(cmake g++ make pkg-config nlohmann-json3-dev libcli11-dev libpng-dev zlib1g-dev libtiff-dev
      libtbb-dev libgtest-dev libbenchmark-dev python3 python3-numpy
      ccache  # scripts/test.sh: the VRI_SIMD=OFF build reuses the Release build's objects
      clang libclang-rt-14-dev  # clang + libFuzzer: the fuzz step (scripts/fuzz.sh)
      # the Python module (python/), its tests, examples/ and its notebook
      python3-dev pybind11-dev python3-pybind11 python3-pytest python3-matplotlib
      jupyter-nbconvert python3-ipykernel
      # the viewer (viewer/): Boost.Beast, JPEG frames, and its browser test's Chromium
      libboost-dev libturbojpeg0-dev chromium
      libopenexr-dev  # .exr output
      liblz4-dev  # LZ4-compressed VTK XML files
      libavformat-dev libavcodec-dev libswscale-dev  # vri turntable's .mp4
      # the Vulkan backend (vulkan/): headers and the shader compiler to build;
      # the loader, Mesa's CPU device (lavapipe) and the validation layer to test
      libvulkan-dev glslc libvulkan1 mesa-vulkan-drivers vulkan-validationlayers
      # sort-last rendering (distributed/): Open MPI, and IceT from paraview-dev
      # (--no-install-recommends below keeps out python3-paraview, which
      # conflicts with python3-vtk9)
      libopenmpi-dev openmpi-bin paraview-dev
      time  # GNU time: one process's peak memory beside the ranks' (tests/distributed/)
)
# The browser test's driver (puppeteer-core) comes from npm: node and npm from
# Debian unless the image has a node of its own.
command -v node >/dev/null || pkgs+=(nodejs)
command -v npm >/dev/null || pkgs+=(npm)
# --vtk: also what the VTK side-by-side scripts need (scripts/vtk_*side_by_side.py)
# and the fixture generators (tools/make_*_fixtures.py: VTK, tifffile, tiffcp).
if [ "${1:-}" = --vtk ]; then pkgs+=(python3-vtk9 xvfb xauth python3-tifffile libtiff-tools); fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
