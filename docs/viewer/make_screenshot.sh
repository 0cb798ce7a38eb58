#!/usr/bin/env bash
# make_screenshot.sh [BUILD_DIR]: docs/viewer/screenshot.png, the viewer with
# the error map on, from a run of the browser test (viewer/tests/e2e) on
# scenes/bonsai.json. Needs `npm ci` in viewer/tests/e2e and Debian's chromium.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
node viewer/tests/e2e/viewer_e2e.mjs "$build/vri" scenes/bonsai.json "$out"
cp "$out/error_map.png" docs/viewer/screenshot.png
