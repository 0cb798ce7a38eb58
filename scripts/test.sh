#!/usr/bin/env bash
# Every test on a fresh machine: install dependencies, build and run the
# suite twice - a normal Release build, then AddressSanitizer + UBSan - then
# run every parser's libFuzzer harness for a bounded time (FUZZ_SECONDS, 10 s each).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)
bash scripts/build.sh build -DVRI_BUILD_TESTS=ON -DVRI_BUILD_BENCH=ON
(cd build && ctest --output-on-failure -j "$jobs")
bash scripts/build.sh build-asan -DVRI_SANITIZE=ON -DVRI_BUILD_TESTS=ON -DVRI_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j "$jobs")
bash scripts/fuzz.sh "${FUZZ_SECONDS:-10}" build-fuzz
