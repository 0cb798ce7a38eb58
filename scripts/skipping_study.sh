#!/usr/bin/env bash
# skipping_study.sh [BUILD_DIR] [REPEATS]: empty-space skipping (the default)
# and early termination (--termination 0.002) against the plain march
# (--no-skip) for `preint1` and `preint2`, step 1, 512 x 512, 2 threads, on
# neghip, engine, bonsai, neghip's opaque and spiky transfer functions and
# the lit neghip (interpolated). Each render REPEATS times (default 5), the
# three variants interleaved; the row keeps the fastest render time vri
# reports (the render alone: not loading, macro cells or table) with its CPU
# time, checks that skipping changes no byte and gives termination's largest
# change to a pixel. docs/PERFORMANCE.md, "Empty space and early termination".
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; repeats=${2:-5}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| scene | method | plain wall / CPU ms | skipping wall / CPU ms | plain / skipping (CPU) | same bytes | + termination wall / CPU ms | plain / termination (CPU) | termination's max change |"
echo "|---|---|---|---|---|---|---|---|---|"
# best VARIANT: the fastest "wall cpu" (ms) seen so far for VARIANT, from $tmp/VARIANT.best
for name in neghip engine bonsai neghip_opaque neghip_spike neghip_lit; do
  for method in preint1 preint2; do
    rm -f "$tmp"/*.best
    for _ in $(seq "$repeats"); do
      for variant in plain skip term; do
        extra=(); [ $variant = plain ] && extra=(--no-skip); [ $variant = term ] && extra=(--termination 0.002)
        line=$("$build/vri" render "scenes/$name.json" -o "$tmp/$variant.npy" --method "$method" --step 1 \
          --threads 2 --width 512 --height 512 "${extra[@]}" 2>&1 | grep -o "in [0-9.e-]* s (CPU [0-9.e-]* s)")
        read -r wall cpu < <(echo "$line" | awk '{gsub(/[()]/,""); printf "%.1f %.1f\n", $2 * 1000, $5 * 1000}')
        if [ ! -f "$tmp/$variant.best" ] || awk -v w="$wall" '{exit !(w < $1)}' "$tmp/$variant.best"; then
          echo "$wall $cpu" >"$tmp/$variant.best"
        fi
      done
    done
    read -r pw pc <"$tmp/plain.best"; read -r sw sc <"$tmp/skip.best"; read -r tw tc <"$tmp/term.best"
    same=no; cmp -s "$tmp/skip.npy" "$tmp/plain.npy" && same=yes
    change=$(/usr/bin/python3 tools/npy_diff.py "$tmp/term.npy" "$tmp/plain.npy")
    echo "| $name | $method | $pw / $pc | $sw / $sc | $(python3 -c "print('%.2f' % ($pc / $sc))") | $same | $tw / $tc | $(python3 -c "print('%.2f' % ($pc / $tc))") | $change |"
  done
done

# What a frame costs before any sample: each scene with a transfer function of
# zero opacity everywhere (every macro cell empty), preint1 step 1, one
# thread, fastest of REPEATS: camera rays, clipping, the macro-cell walk and
# the packets' set-up, per pixel.
echo
echo "| scene, zero-opacity transfer function | preint1 step 1, one thread: wall ms | ns per pixel |"
echo "|---|---|---|"
for name in neghip engine bonsai; do
  /usr/bin/python3 - "scenes/$name.json" "$tmp/$name.empty.json" <<'PY'
import json, os, sys
scene = json.load(open(sys.argv[1]))
base = os.path.dirname(os.path.abspath(sys.argv[1]))
scene["volume"]["file"] = os.path.join(base, scene["volume"]["file"])
scene["transfer_function"] = {"points": [[0, 0, 0, 0, 0], [1, 0, 0, 0, 0]]}
json.dump(scene, open(sys.argv[2], "w"))
PY
  best=
  for _ in $(seq "$repeats"); do
    wall=$("$build/vri" render "$tmp/$name.empty.json" -o "$tmp/empty.npy" --method preint1 --step 1 --threads 1 \
      --width 512 --height 512 2>&1 | sed -n 's/.* in \([0-9.e-]*\) s.*/\1/p')
    best=$(awk -v a="$wall" -v b="${best:-1e9}" 'BEGIN { print (a < b) ? a : b }')
  done
  awk -v n="$name" -v w="$best" 'BEGIN { printf "| %s | %.1f | %.0f |\n", n, w * 1000, w * 1e9 / (512 * 512) }'
done
