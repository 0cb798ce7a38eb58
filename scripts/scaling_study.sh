#!/usr/bin/env bash
# scaling_study.sh [BUILD_DIR] [REPEATS]: how `preint1` (step 1) and `riemann`
# (step 1) scale on this machine (issue 8, item 5; docs/PERFORMANCE.md,
# "Scaling"). Prints markdown tables:
#  1. time against image size: bonsai at 128², 256², 512², 1024², 2 threads;
#  2. time against volume size: the Marschner–Lobb function (SPEC's test
#     signal, f_M = 6, alpha = 0.25) sampled to N³ uint8, N = 64 .. 512,
#     written as .raw by python3 + numpy, rendered at 512² with the camera of
#     scenes/marschner_lobb.json scaled to the volume, 2 threads, with the
#     peak memory (maximum RSS, /usr/bin/time -v) against the N³ bytes;
#  3. 1 against 2 threads: bonsai at 512².
# TABLES (default "image volume threads") picks the tables and SIZES (default
# "64 128 256 512") the N of table 2: TABLES=volume SIZES=512 gives the peak
# memory row of issue 8's goal alone.
# Each render runs REPEATS times (default 3); the row keeps the fastest wall
# time and that run's CPU time. Times are vri's own "rendered ... in" line
# (the render alone: not loading, the macro cells or the table). The load
# average is printed before each table: on a shared machine compare within
# one run, as ratios, and prefer CPU time.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; reps=${2:-3}
tables=" ${TABLES:-image volume threads} "; sizes=${SIZES:-64 128 256 512}
vri=$build/vri; tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
python=/usr/bin/python3  # Debian's, which has numpy
root=$(pwd)

# render ARGS...: one render; prints "wall_ms cpu_ms max_rss_MiB".
render() {
  /usr/bin/time -v "$vri" render "$@" -o "$tmp/out.npy" >"$tmp/log" 2>&1
  awk '/vri: rendered/ { for (i = 1; i < NF; ++i) { if ($i == "in") w = $(i + 1); if ($i == "(CPU") c = $(i + 1) } }
       /Maximum resident set size/ { r = $NF }
       END { printf "%.0f %.0f %.0f\n", w * 1000, c * 1000, r / 1024 }' "$tmp/log"
}

# best ARGS...: REPEATS renders; prints the fastest "wall_ms cpu_ms max_rss_MiB".
best() {
  local bw="" bc="" br="" w c r
  for _ in $(seq "$reps"); do
    read -r w c r < <(render "$@")
    if [[ -z $bw || $w -lt $bw ]]; then bw=$w; bc=$c; fi
    br=$r
  done
  echo "$bw $bc $br"
}

load() { echo "Load average: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')."; }

if [[ $tables == *" image "* ]]; then
echo "### Image size (bonsai, step 1, 2 threads)"
load
echo
echo "| pixels | preint1 wall / CPU ms | riemann wall / CPU ms | preint1 CPU ns per pixel | riemann CPU ns per pixel |"
echo "|---|---|---|---|---|"
for size in 128 256 512 1024; do
  read -r pw pc _ < <(best scenes/bonsai.json --method preint1 --step 1 --threads 2 --width "$size" --height "$size")
  read -r rw rc _ < <(best scenes/bonsai.json --method riemann --step 1 --threads 2 --width "$size" --height "$size")
  per_pixel() { awk -v c="$1" -v n="$size" 'BEGIN { printf "%.0f", c * 1e6 / (n * n) }'; }
  echo "| ${size}² | $pw / $pc | $rw / $rc | $(per_pixel "$pc") | $(per_pixel "$rc") |"
done
echo

fi

if [[ $tables == *" volume "* ]]; then
echo "### Volume size (Marschner–Lobb N³ uint8, 512², step 1, 2 threads)"
load
echo
echo "| N³ | volume MiB | preint1 wall / CPU ms | riemann wall / CPU ms | preint1 CPU ms / N | max RSS MiB (preint1) | max RSS MiB (riemann) | RSS / volume (preint1) |"
echo "|---|---|---|---|---|---|---|---|"
for n in $sizes; do
  "$python" - "$n" "$tmp/ml_$n.raw" <<'EOF'
import sys
import numpy as np
n, path = int(sys.argv[1]), sys.argv[2]
f_m, alpha = 6.0, 0.25
x = np.linspace(-1, 1, n)
X, Y = np.meshgrid(x, x, indexing="xy")  # one z slice, x fastest
rho = np.cos(2 * np.pi * f_m * np.cos(np.pi * np.sqrt(X * X + Y * Y) / 2))
with open(path, "wb") as out:
    for z in x:  # slice by slice: the whole float64 volume would be 1 GiB at 512³
        v = (1 - np.sin(np.pi * z / 2) + alpha * (1 + rho)) / (2 * (1 + alpha))
        out.write(np.round(255 * v).astype(np.uint8).tobytes())
EOF
  c=$(awk -v n="$n" 'BEGIN { print (n - 1) / 2 }')
  k=$(awk -v n="$n" 'BEGIN { print (n - 1) / 40 }')
  cat >"$tmp/ml_$n.json" <<EOF
{"volume": {"file": "$tmp/ml_$n.raw", "dims": [$n, $n, $n], "type": "uint8"},
 "transfer_function": {"file": "$root/presets/marschner_lobb.json"},
 "camera": {"eye": [$(awk -v c="$c" -v k="$k" 'BEGIN { printf "%g, %g, %g", c + 75.274 * k, c + 61.588 * k, c + 95.803 * k }')],
            "target": [$c, $c, $c], "up": [0, 0, 1], "fov_y": 30, "width": 512, "height": 512},
 "background": [0, 0, 0], "method": {"name": "preint1", "step": 1}}
EOF
  read -r pw pc pr < <(best "$tmp/ml_$n.json" --method preint1 --step 1 --threads 2)
  read -r rw rc rr < <(best "$tmp/ml_$n.json" --method riemann --step 1 --threads 2)
  mib=$(awk -v n="$n" 'BEGIN { printf "%.2f", n * n * n / 1048576 }')
  echo "| ${n}³ | $mib | $pw / $pc | $rw / $rc | $(awk -v c="$pc" -v n="$n" 'BEGIN { printf "%.2f", c / n }') | $pr | $rr | $(awk -v r="$pr" -v m="$mib" 'BEGIN { printf "%.1f", r / m }') |"
  rm -f "$tmp/ml_$n.raw"
done
echo

fi

if [[ $tables == *" threads "* ]]; then
echo "### Threads (bonsai, 512², step 1)"
load
echo
echo "| method | 1 thread wall / CPU ms | 2 threads wall / CPU ms | wall 1 → 2 | CPU / wall at 2 |"
echo "|---|---|---|---|---|"
for m in preint1 riemann; do
  row=()
  for t in 1 2; do  # alternating, so both see the same load
    read -r w c _ < <(reps=1 best scenes/bonsai.json --method "$m" --step 1 --threads "$t" --width 512 --height 512)
    row+=("$w" "$c")
  done
  for _ in $(seq 2 "$reps"); do
    for t in 1 2; do
      read -r w c _ < <(reps=1 best scenes/bonsai.json --method "$m" --step 1 --threads "$t" --width 512 --height 512)
      i=$((2 * (t - 1)))
      if [[ $w -lt ${row[$i]} ]]; then row[$i]=$w; row[$((i + 1))]=$c; fi
    done
  done
  echo "| $m | ${row[0]} / ${row[1]} | ${row[2]} / ${row[3]} | $(awk -v a="${row[0]}" -v b="${row[2]}" 'BEGIN { printf "%.2f×", a / b }') | $(awk -v c="${row[3]}" -v w="${row[2]}" 'BEGIN { printf "%.2f", c / w }') |"
done
echo
fi
load
