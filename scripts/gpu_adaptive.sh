#!/usr/bin/env bash
# gpu_adaptive.sh [BUILD_DIR]: the adaptive table of docs/GPU.md. For every
# bundled grid scene at 128 x 128, `adaptive` (coupled at tolerance 1e-3,
# decoupled at 1e-4, guaranteed at 1e-3 and 1e-4) rendered by --backend
# vulkan and by the CPU, and `exact` (tolerance 1e-7) as the reference: the
# share of pixels where the two adaptive images differ by more than 1e-4
# (float against double step decisions), each one's share of pixels over
# the tolerance against exact and each one's largest error against it.
set -euo pipefail
cd "$(dirname "$0")/.."
vri="${1:-build}/vri"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), Vulkan device: $("$vri" devices | head -1)"
echo
echo "| scene | strategy, tolerance | pixels GPU ≠ CPU (> 1e-4) | over tolerance vs exact: CPU | GPU | largest error vs exact: CPU | GPU |"
echo "|---|---|---|---|---|---|---|"
render() {  # vri render ARGS, its report kept out of the table (shown on failure)
  "$vri" render "$@" 2> "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
}
largest() {  # the largest difference between A and B (.npy) in any channel
  /usr/bin/python3 tools/npy_diff.py "$1" "$2"
}
share() {  # share of pixels of A and B (.npy) differing by more than E in some channel
  /usr/bin/python3 tools/npy_diff.py "$1" "$2" --over "$3"
}
for scene in scenes/*.json; do
  name=$(basename "$scene" .json)
  case "$name" in blunt_fin*) continue ;; esac  # meshes: not on the GPU
  size=(--width 128 --height 128)
  render "$scene" "${size[@]}" --method exact --tolerance 1e-7 -o "$tmp/exact.npy"
  for run in "coupled 1e-3" "decoupled 1e-4" "guaranteed 1e-3" "guaranteed 1e-4"; do
    read -r strategy tol <<< "$run"
    flags=("${size[@]}" --method adaptive --strategy "$strategy" --tolerance "$tol")
    render "$scene" "${flags[@]}" -o "$tmp/cpu.npy"
    render "$scene" "${flags[@]}" --backend vulkan -o "$tmp/gpu.npy"
    echo "| $name | $strategy, $tol | $(share "$tmp/gpu.npy" "$tmp/cpu.npy" 1e-4) | $(share "$tmp/cpu.npy" "$tmp/exact.npy" "$tol") | $(share "$tmp/gpu.npy" "$tmp/exact.npy" "$tol") | $(largest "$tmp/cpu.npy" "$tmp/exact.npy") | $(largest "$tmp/gpu.npy" "$tmp/exact.npy") |"
  done
done
