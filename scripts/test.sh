#!/usr/bin/env bash
# Every test on a fresh machine: install dependencies, build and run the
# suite three times - a normal Release build, the same with the x86-64 SIMD
# code off (VRI_SIMD=OFF, docs/PORTABILITY.md), then AddressSanitizer + UBSan -
# then run every parser's libFuzzer harness for a bounded time (FUZZ_SECONDS, 10 s each).
# The viewer's browser test runs in each build (its screenshots in BUILD/viewer_e2e).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# The viewer's browser test drives Chromium with puppeteer-core, the one npm
# package (viewer/tests/e2e/package-lock.json); CMake registers the test when it is there.
if [ ! -d viewer/tests/e2e/node_modules/puppeteer-core ]; then
  (cd viewer/tests/e2e && npm ci --no-audit --no-fund --loglevel=error)
fi
jobs=$(nproc)
# ccache lets the VRI_SIMD=OFF build reuse the Release build's objects: only
# the files that include src/core/simd.hpp compile again.
# Paths under the checkout are hashed relative to it, so build and
# build-nosimd (each with its own generated include/) share entries.
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); export CCACHE_BASEDIR="$PWD"; fi
bash scripts/build.sh build "${launcher[@]}" -DVRI_BUILD_TESTS=ON -DVRI_BUILD_BENCH=ON
(cd build && ctest --output-on-failure -j "$jobs")
# Without SIMD only the library's kernels differ: the viewer, which calls
# them, is tested in the other two builds, and so is distributed/ (it adds no
# kernels). (The Python module stays: turning
# it off changes every file's flags, -fPIC, and so loses the ccache hits.)
bash scripts/build.sh build-nosimd "${launcher[@]}" -DVRI_SIMD=OFF -DVRI_BUILD_TESTS=ON -DVRI_BUILD_BENCH=OFF \
  -DVRI_VIEWER=OFF -DVRI_VULKAN=OFF -DVRI_MPI=OFF
# The verification fast tier (docs/VERIFICATION.md) runs its 100 cases in the
# Release build; the other two run the first 20, for their kernels' sake.
(cd build-nosimd && VRI_VERIFY_CASES=20 ctest --output-on-failure -j "$jobs")
# -g1: line tables (stack traces keep file:line) at less compile time than -g;
# -O1: the same checks, and about 0.5-0.7x the compile time of -O2, which set
# the CI's length (float_packet.cpp 27 s against 59 s under ASan,
# client_session.cpp 56 against 85 s; the ASan build was 18 of 34 minutes).
bash scripts/build.sh build-asan "${launcher[@]}" -DVRI_SANITIZE=ON -DVRI_BUILD_TESTS=ON -DVRI_BUILD_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
(cd build-asan && VRI_VERIFY_CASES=20 ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j "$jobs")
bash scripts/fuzz.sh "${FUZZ_SECONDS:-10}" build-fuzz
