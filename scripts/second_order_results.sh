#!/usr/bin/env bash
# second_order_results.sh [BUILD_DIR] [SIZE] [REPEATS]: the results study of
# docs/SECOND_ORDER.md (issue 4 item 6, El Hajjar et al. 2008 Figures 7-9).
# Renders neghip, fuel, bucky, neghip_spike (a spike narrower than a table
# bin) and neghip_opaque (a steep opaque ramp) at SIZE x SIZE with `exact`
# (tolerance 1e-5),
# preint1 at steps A and B, preint2 at step A (A, B = 2, 1; bucky 4, 1) with
# tables of 256 (the default), 128 and 64 entries a side, and preint2-dual
# (64 entries, 32 lengths), all with the default K (8 chords), and preint1 at step 0.25
# (about as many samples as preint2-dual), and prints a Markdown table: the error
# against exact (worst channel: RMS, max, share of pixels over 1/255 from
# `vri compare`) and the render time (the best of REPEATS, tables excluded),
# with the table build time, on one thread. PNG images of exact, preint1 at A and B, preint2 at A and preint2-dual go
# to docs/second_order/.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; size=${2:-256}; repeats=${3:-5}
vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
out=docs/second_order; mkdir -p "$out"
common=(--width "$size" --height "$size" --threads 1)  # one thread: steadier times on a shared machine

# render SCENE NAME ARGS...: renders to $tmp/NAME.npy and $out; prints "render_s total_s".
render() {
  local scene=$1 name=$2; shift 2
  local best="" total=""
  for ((i = 0; i < repeats; i++)); do
    local t0 t1 s
    t0=$(date +%s.%N)
    s=$("$vri" render "$scene" -o "$tmp/$name.npy" "${common[@]}" "$@" 2>&1 | sed -n 's/.* in \([0-9.e+-]*\) s .*/\1/p')
    t1=$(date +%s.%N)
    best=$(awk -v a="$best" -v b="$s" 'BEGIN { print (a == "" || b < a) ? b : a }')
    total=$(awk -v a="$total" -v b="$(awk -v x="$t0" -v y="$t1" 'BEGIN { print y - x }')" \
      'BEGIN { print (a == "" || b < a) ? b : a }')
  done
  if [ "${image:-1}" = 1 ]; then "$vri" render "$scene" -o "$out/$name.png" "${common[@]}" "$@" 2>/dev/null; fi
  printf "%.4f %.3f\n" "$best" "$total"
}

# error NAME: "rms max share" of the worst channel against exact.
error() {
  "$vri" compare "$tmp/exact.npy" "$tmp/$1.npy" --tolerance 0.00392156862745098 --max-share 1 |
    awk 'NR > 1 { if ($3 > r) r = $3; if ($4 > m) m = $4; if ($2 > s) s = $2 }
         END { printf "%.2e | %.2e | %.2f%%", r, m, 100 * s }'
}

echo "| scene | method | RMS | max | > 1/255 | render s | render + table s |"
echo "|---|---|---|---|---|---|---|"
for name in neghip fuel bucky neghip_spike neghip_opaque; do
  scene=scenes/$name.json
  if [ "$name" = bucky ]; then a=4; b=1; else a=2; b=1; fi
  read -r rt tt < <(image=1 repeats=1 render "$scene" "${name}_exact" --method exact --tolerance 1e-5)
  cp "$tmp/${name}_exact.npy" "$tmp/exact.npy"
  echo "| $name | exact | - | - | - | $rt | $tt |"
  for m in "preint1 $a -" "preint1 $b -" "preint2 $a -" "preint2 $a 128" "preint2 $a 64" "preint2-dual - -" \
           "preint1 0.25 -"; do
    read -r method step table <<<"$m"
    label="$method"; args=(--method "$method")
    if [ "$step" != - ]; then label="$method@$step"; args+=(--step "$step"); fi
    if [ "$table" != - ]; then label="$label N=$table"; args+=(--table-size "$table"); fi
    key="${name}_${label//@/_step}"; key="${key// N=/_table}"
    image=1; if [ "$table" != - ] || [ "$step" = 0.25 ]; then image=0; fi  # images of the issue's methods only
    read -r rt tt < <(image=$image render "$scene" "$key" "${args[@]}")
    echo "| $name | $label | $(error "$key") | $rt | $tt |"
  done
done
