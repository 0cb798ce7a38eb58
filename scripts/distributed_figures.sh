#!/usr/bin/env bash
# distributed_figures.sh [BUILD]: the figures of docs/DISTRIBUTED.md, on this
# machine (ranks past its cores are oversubscribed: times show overhead, not
# speed-up). Three tables, each row one mpirun of `vri render`:
#  1. memory: a 512^3 built-in volume (float, 512 MiB), preint1 at 256x256:
#     one process's peak RSS (GNU time), then per N the largest brick and the
#     largest peak RSS of a rank (as vri reports them), and the largest
#     difference from the one-process image;
#  2. accuracy at size: scenes/engine.json at 256x256, preint1 float and
#     double paths, the largest difference from one process;
#  3. compositing: rank 0's IceT time against image size and N (neghip).
set -euo pipefail
build=${1:-build}
vri=$(realpath "$build/vri")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mpi=(mpirun --allow-run-as-root --oversubscribe)
field() { sed -E "s/.*$1 ([0-9.e+-]+).*/\1/" "$tmp/log"; }
maxdiff() { "$vri" compare "$tmp/one.npy" "$tmp/many.npy" --tolerance 1 | awk 'NR > 1 {print $4}' | sort -g | tail -1; }
echo "# $(date -u '+%F %T') UTC, $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)," \
     "load $(cut -d' ' -f1-3 /proc/loadavg), Open MPI $(mpirun --version | head -1 | awk '{print $NF}')"

cat >"$tmp/ml512.json" <<'JSON'
{"volume": {"builtin": "marschner_lobb", "dims": [512, 512, 512]},
 "transfer_function": {"points": [[0.0, 0.1, 0.2, 0.8, 0.0], [0.5, 0.9, 0.6, 0.2, 1.0], [1.0, 1.0, 1.0, 1.0, 4.0]]},
 "camera": {"azimuth": 30, "elevation": 20, "width": 256, "height": 256},
 "method": {"name": "preint1", "step": 1}}
JSON
echo
echo "## 1. Memory: 512^3 float built-in volume, preint1, 256x256, one thread a rank"
/usr/bin/time -f "%M" -o "$tmp/rss" "$vri" render "$tmp/ml512.json" -o "$tmp/one.npy" -q --threads 1 2>"$tmp/log"
echo "one process: peak RSS $(( $(cat "$tmp/rss") * 1024 )) bytes, render $(field "' in") s (one thread)"
echo "| ranks | largest brick (bytes) | largest peak RSS of a rank (bytes) | rank 0 render s | max difference |"
echo "|---|---|---|---|---|"
for n in 1 2 4 8; do
  "${mpi[@]}" -np "$n" "$vri" render "$tmp/ml512.json" -o "$tmp/many.npy" -q --threads 1 --distributed 2>"$tmp/log"
  echo "| $n | $(field 'largest brick') | $(field 'peak memory of a rank') | $(field 'brick in') | $(maxdiff) |"
done

echo
echo "## 2. scenes/engine.json at 256x256, preint1: largest difference from one process"
echo "| ranks | float path | double path (--double) |"
echo "|---|---|---|"
for n in 2 4 8; do
  row="| $n"
  for extra in "" --double; do
    "$vri" render scenes/engine.json -o "$tmp/one.npy" --width 256 --height 256 --method preint1 -q $extra 2>/dev/null
    "${mpi[@]}" -np "$n" "$vri" render scenes/engine.json -o "$tmp/many.npy" --width 256 --height 256 \
      --method preint1 -q --threads 1 $extra 2>/dev/null
    row+=" | $(maxdiff)"
  done
  echo "$row |"
done

echo
echo "## 3. Compositing: rank 0's IceT time (s) against image size and ranks, scenes/neghip.json, preint1"
echo "| pixels a side | 2 ranks | 4 ranks | 8 ranks |"
echo "|---|---|---|---|"
for size in 128 256 512 1024; do
  row="| $size"
  for n in 2 4 8; do
    "${mpi[@]}" -np "$n" "$vri" render scenes/neghip.json -o "$tmp/many.npy" --width "$size" --height "$size" \
      --method preint1 -q --threads 1 2>"$tmp/log"
    row+=" | $(field 'composited in')"
  done
  echo "$row |"
done
