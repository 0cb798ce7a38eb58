#!/usr/bin/env bash
# float_paths_ab.sh BUILD_DIR [REPEATS]: the float paths of riemann, preint1 and
# preint2 (packets of 8 rays with AVX2) against their double paths (--double),
# unlit on neghip, engine, bonsai and neghip's opaque and spiky transfer
# functions, lit on neghip_lit and fuel_lit in both
# modes (`interpolated` as the scenes say, `sampled` in a copy of the scene,
# deleted after), 512x512, step 1, one thread.
# Each render REPEATS times (default 5), float and double interleaved; prints
# the fastest render CPU time vri reports (not loading or building tables)
# and the largest difference between the two images (docs/PERFORMANCE.md,
# "Float paths and packets").
set -euo pipefail
build=${1:?usage: float_paths_ab.sh BUILD_DIR [REPEATS]}
repeats=${2:-5}
vri="$build/vri"
root="$(cd "$(dirname "$0")/.." && pwd)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp" "$root"/scenes/.ab_*_sampled.json' EXIT
for lit in neghip_lit fuel_lit; do  # beside the original: its paths are relative
  sed 's/"interpolated"/"sampled"/' "$root/scenes/$lit.json" >"$root/scenes/.ab_${lit}_sampled.json"
done
cpu_ms() { grep -o "CPU [0-9.e-]* s" | awk '{printf "%.1f", $2 * 1000}'; }
echo "| scene | method | double CPU ms | float CPU ms | double / float | max difference |"
echo "|---|---|---|---|---|---|"
for scene in neghip engine bonsai neghip_opaque neghip_spike .ab_neghip_lit_sampled neghip_lit .ab_fuel_lit_sampled fuel_lit; do
  for method in riemann preint1 preint2; do
    best_d=; best_f=
    for _ in $(seq "$repeats"); do
      for path in double float; do
        extra=(); [ "$path" = double ] && extra=(--double)
        t=$("$vri" render "$root/scenes/$scene.json" -o "$tmp/$path.npy" --method "$method" --step 1 \
              --width 512 --height 512 --threads 1 "${extra[@]}" 2>&1 | cpu_ms)
        if [ "$path" = double ]; then
          best_d=$(python3 -c "print(min(x for x in [$t, ${best_d:-1e9}]))")
        else
          best_f=$(python3 -c "print(min(x for x in [$t, ${best_f:-1e9}]))")
        fi
      done
    done
    diff=$(/usr/bin/python3 tools/npy_diff.py "$tmp/double.npy" "$tmp/float.npy")
    label=${scene#.ab_}
    if [ "$label" != "$scene" ]; then label="${label%_sampled} (sampled)"
    elif [ "${scene%_lit}" != "$scene" ]; then label="$scene (interpolated)"; fi
    echo "| $label | $method | $best_d | $best_f | $(python3 -c "print('%.2f' % ($best_d / $best_f))") | $diff |"
  done
done
