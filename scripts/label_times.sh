#!/usr/bin/env bash
# label_times.sh [BUILD_DIR]: runs each ctest label of SPEC §12 on its own
# (ctest -L LABEL -j nproc) in a built tree and writes the tests it has and
# the wall time to docs/testing/label_times.md, with the machine and the
# commands (docs/TESTING.md). `fast` must stay under 3 minutes on the 2-core
# CI machine.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
jobs=$(nproc)
out=docs/testing/label_times.md
{
  echo "<!-- written by scripts/label_times.sh $build; do not edit -->"
  echo "| label | tests | wall time (s) |"
  echo "| --- | ---: | ---: |"
} >"$out.tmp"
for label in fast slow gpu mpi browser fuzz; do
  count=$(cd "$build" && ctest -N -L "^$label\$" | sed -n 's/^Total Tests: //p')
  start=$(date +%s.%N)
  status=passed
  (cd "$build" && ctest -L "^$label\$" -j "$jobs" >/dev/null 2>&1) || status=FAILED
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  printf '| %s | %s | %.0f%s |\n' "$label" "$count" "$wall" "$([ $status = passed ] || echo " ($status)")" >>"$out.tmp"
done
{
  echo
  echo "Each row: \`(cd $build && ctest -L '^LABEL\$' -j $jobs)\`, $(date -u +%Y-%m-%d), a Release build"
  echo "(scripts/build.sh), on $(nproc) cores of $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1),"
  echo "load average $(cut -d' ' -f1-3 /proc/loadavg) when it ended. A test carries fast or slow and"
  echo "any of the others, so the rows overlap; fast + slow is the whole suite."
} >>"$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
