# Sourced by the timing scripts (adaptive_speed.sh, second_order_speed.sh).
#
# fastest_renders VRI SCENE REPEATS OUT_DIR ARGS...: renders SCENE once with
# each string of ARGS (vri render options), in turn, REPEATS rounds (so that a
# drift in the machine's load falls on all alike), on 2 threads; sets best[i]
# to the fastest render time of ARGS[i] in ms, as vri reports it (the render
# alone), and leaves its image in OUT_DIR/i.npy.
fastest_renders() {
  local vri=$1 scene=$2 reps=$3 out=$4 w i
  shift 4
  local args=("$@")
  best=()
  for _ in $(seq "$reps"); do
    for i in "${!args[@]}"; do
      # shellcheck disable=SC2086
      w=$("$vri" render "$scene" ${args[$i]} --threads 2 -q -o "$out/$i.npy" 2>&1 |
          awk '/rendered/ { for (j = 1; j < NF; ++j) if ($j == "in") printf "%.1f", $(j + 1) * 1000 }')
      if [[ -z ${best[$i]:-} ]] || awk -v a="$w" -v b="${best[$i]}" 'BEGIN { exit !(a < b) }'; then best[$i]=$w; fi
    done
  done
}

# timing_setup [BUILD_DIR] [REPEATS]: the timing scripts' arguments (build,
# default "build"; reps, default 3), vri, a temporary folder tmp removed at
# exit, and the line above their tables: the load, the cores, the time.
timing_setup() {
  build=${1:-build}; reps=${2:-3}; vri=$build/vri; tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  echo "Load average: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores; $(date -u '+%Y-%m-%d %H:%M UTC')."
}
