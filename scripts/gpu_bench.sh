#!/usr/bin/env bash
# gpu_bench.sh [BUILD_DIR] [REPEATS]: the GPU figures of docs/GPU.md (issue
# 22, item 6), --backend vulkan beside --backend cpu (2 threads) in the same
# run: the frame time of `preint1`, `preint2`, `preint2-dual`, `riemann`
# (step 1), `adaptive` (coupled, tolerance 1e-3) and `adaptive` guaranteed
# (tolerance 1e-3, "guaranteed" below) at 512 x 512 on neghip
# and bonsai, and `tet-raycast` on the blunt fin mesh, the fastest of REPEATS renders as `vri render` reports them
# (the render alone: rays set up, the dispatch, the image read back; not the volume
# upload or the table build), with the largest difference between the two
# images (adaptive: step decisions in float against double, docs/GPU.md)
# and the GPU's time without empty-space skipping (--no-skip);
# then the build time of the 256² sliced and incremental and the 256³
# second-order tables as `vri table` reports it (on the GPU: the transfer
# function up, the dispatches, the table back). Prints the machine and the Vulkan device
# first: on a machine without a GPU that device is lavapipe, Mesa's CPU
# emulation, and its times are labelled so.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
repeats=${2:-3}
vri="$build/vri"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)), load $(cut -d' ' -f1-3 /proc/loadavg)"
device=$("$vri" devices | head -1)
echo "# Vulkan device: $device"
case "$device" in *llvmpipe*|*lavapipe*|*", CPU,"*) label="lavapipe (CPU emulation, not a GPU)";; *) label="GPU";; esac
# The fastest time of `vri COMMAND ARGS` over the repeats, as it reports it
# ("... in T s (CPU ...)" for render, "... in T s -> ..." for table).
best() {
  local t best=
  for _ in $(seq "$repeats"); do
    t=$("$vri" "$@" 2>&1 >/dev/null | sed -n "s/.* in \([0-9.e-]*\) s [(-].*/\1/p")
    best=$(awk -v a="$t" -v b="${best:-$t}" 'BEGIN { print (a < b ? a : b) }')
  done
  echo "$best"
}
echo
echo "| scene | method | CPU ms (2 threads) | Vulkan ms ($label) | CPU / Vulkan | Vulkan ms, no skipping | max difference |"
echo "|---|---|---|---|---|---|---|"
runs=()
for scene in neghip bonsai; do
  for method in preint1 preint2 preint2-dual riemann adaptive guaranteed; do runs+=("$scene $method"); done
done
runs+=("blunt_fin tet-raycast")  # a tetrahedral mesh (187k tetrahedra), the default 256² x 64 table
for run in "${runs[@]}"; do
  read -r scene method <<< "$run"
  args=(scenes/$scene.json --method "$method" --width 512 --height 512)
  [ "$method" != tet-raycast ] && args+=(--step 1)
  [ "$method" = adaptive ] && args+=(--strategy coupled --tolerance 1e-3)
  [ "$method" = guaranteed ] && args=(scenes/$scene.json --method adaptive --strategy guaranteed --tolerance 1e-3
                                      --width 512 --height 512)
  cpu=$(best render "${args[@]}" -o "$tmp/cpu.npy" --threads 2)
  gpu=$(best render "${args[@]}" -o "$tmp/gpu.npy" --backend vulkan)
  # Empty-space skipping off (meshes have none).
  march=-1
  [ "$method" != tet-raycast ] && march=$(best render "${args[@]}" -o "$tmp/march.npy" --backend vulkan --no-skip)
  diff=$("$vri" compare "$tmp/gpu.npy" "$tmp/cpu.npy" --tolerance 1e-4 | awk 'NR > 1 { if ($4 > m) m = $4 } END { printf "%.1e", m }')
  awk -v s="$scene" -v m="$method" -v c="$cpu" -v g="$gpu" -v n="$march" -v d="$diff" \
    'BEGIN { printf "| %s | %s | %.1f | %.1f | %.2f | %s | %s |\n", s, m, 1000 * c, 1000 * g, c / g,
             n < 0 ? "—" : sprintf("%.1f", 1000 * n), d }'
done
echo
echo "| table (bonsai's transfer function) | CPU s (2 threads) | Vulkan s ($label) | CPU / Vulkan | max difference |"
echo "|---|---|---|---|---|"
for spec in "first order 256², sliced (Roettger & Ertl)|--size 256 --builder sliced" \
            "first order 256², incremental (Lum et al.)|--size 256 --builder incremental" \
            "second order 256³, fast (El Hajjar et al.)|--size 256 --order 2 --builder fast"; do
  name=${spec%%|*}
  read -r -a args <<< "${spec#*|}"
  args=(--tf presets/bonsai.json "${args[@]}")
  cpu=$(best table "${args[@]}" -o "$tmp/cpu.npy")
  gpu=$(best table "${args[@]}" -o "$tmp/gpu.npy" --backend vulkan)
  diff=$(/usr/bin/python3 tools/npy_diff.py "$tmp/cpu.npy" "$tmp/gpu.npy")
  awk -v s="$name" -v c="$cpu" -v g="$gpu" -v d="$diff" \
    'BEGIN { printf "| %s | %.3f | %.3f | %.2f | %s |\n", s, c, g, c / g, d }'
done
