#!/usr/bin/env bash
# performance.sh OUT_DIR [BUILD_DIR]: re-runs every measurement of
# docs/PERFORMANCE.md, one file per section in OUT_DIR (a section's file holds
# its command's own output, the date and the load average at its start), so
# the page is re-made from one command. PARTS (default: all, in this order)
# picks sections. Needs a Release build (scripts/build.sh), python3-vtk9 and
# Xvfb for the VTK parts (scripts/install-deps.sh --vtk), and `npm ci` in
# viewer/tests/e2e for the viewer part. Takes about 20 minutes on the
# project's 2-core machine; run it with nothing else busy.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: performance.sh OUT_DIR [BUILD_DIR]}; build=${2:-build}
parts=" ${PARTS:-render tables lighting preint_render second_order mesh vtk_mesh vtk_grid float_paths skipping macro_cells scaling brick_layout viewer adaptive memory equal_error} "
mkdir -p "$out"
stamp() { echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"; }
want() { [[ "$parts" == *" $1 "* ]]; }
display=
vtk_display() {  # one Xvfb for the VTK parts (xvfb-run has failed to connect here)
  [ -n "$display" ] && return
  Xvfb :55 -screen 0 1024x768x24 >/dev/null 2>&1 & xvfb=$!; trap 'kill $xvfb 2>/dev/null || true' EXIT
  sleep 2; display=:55
}
if want render; then
  { stamp; "$build/bench/bench_render" --benchmark_min_time=1; } >"$out/render.txt" 2>&1
fi
if want tables; then
  { stamp; "$build/bench/bench_tables" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
      --benchmark_min_time=0.2; } >"$out/tables.txt" 2>&1
fi
if want lighting; then
  { stamp; "$build/bench/bench_lighting" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true; } \
    >"$out/lighting.txt" 2>&1
fi
if want preint_render; then
  { stamp; "$build/bench/bench_preint_render" --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true \
      --benchmark_report_aggregates_only=true; } >"$out/preint_render.txt" 2>&1
fi
if want second_order; then
  bash scripts/second_order_speed.sh "$build" 3 >"$out/second_order.txt" 2>&1
fi
if want mesh; then
  { stamp; "$build/bench/bench_mesh" --benchmark_min_time=1; } >"$out/mesh.txt" 2>&1
fi
if want vtk_mesh; then
  vtk_display
  for s in blunt_fin blunt_fin_opaque; do
    { stamp; DISPLAY=$display LP_NUM_THREADS=2 /usr/bin/python3 scripts/vtk_side_by_side.py "scenes/$s.json" 256 "$out/side"; } \
      >"$out/vtk_mesh_$s.txt" 2>&1
  done
fi
if want vtk_grid; then
  vtk_display
  # The bundled views, each dataset turned, and the engine and the bonsai
  # under an opaque ramp and a spike (scripts/views/; issue 21: several
  # cameras and transfer functions per dataset).
  for view in "neghip" "engine" "bonsai" "neghip_opaque" "neghip_spike" "neghip --azimuth 90" \
              "engine --azimuth 90 --elevation 30" "bonsai --azimuth 90" \
              "views/engine_opaque" "views/engine_spike" "views/bonsai_opaque" "views/bonsai_spike"; do
    read -r s motions <<<"$view"
    scene="scenes/$s.json"
    [[ "$s" == views/* ]] && scene="scripts/$s.json"
    # shellcheck disable=SC2086
    { stamp; DISPLAY=$display LP_NUM_THREADS=2 /usr/bin/python3 scripts/vtk_grid_side_by_side.py \
        "$scene" 512 "$out/side" --repeat 5 $motions; } >"$out/vtk_grid_${s#views/}${motions:+_turned}.txt" 2>&1
  done
  # The table of docs/PERFORMANCE.md from the eight files.
  /usr/bin/python3 scripts/vtk_grid_summary.py "$out" >"$out/vtk_grid_summary.md"
fi
if want float_paths; then { stamp; bash scripts/float_paths_ab.sh "$build" 5; } >"$out/float_paths.txt" 2>&1; fi
if want skipping; then { stamp; bash scripts/skipping_study.sh "$build" 3; } >"$out/skipping.txt" 2>&1; fi
if want macro_cells; then { stamp; "$build/bench/bench_macro_cells"; } >"$out/macro_cells.txt" 2>&1; fi
if want scaling; then
  { stamp; bash scripts/scaling_study.sh "$build" 3; } >"$out/scaling.txt" 2>&1
  /usr/bin/python3 scripts/scaling_plot.py "$out/scaling.txt" docs/performance/scaling.png
fi
if want viewer; then { stamp; node viewer/bench/viewer_latency.mjs "$build/vri"; } >"$out/viewer.txt" 2>&1; fi
if want brick_layout; then
  { stamp; "$build/bench/bench_brick_layout" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true; } \
    >"$out/brick_layout.txt" 2>&1
fi
if want adaptive; then { stamp; bash scripts/adaptive_speed.sh "$build" 3; } >"$out/adaptive.txt" 2>&1; fi
if want memory; then { stamp; bash scripts/memory_study.sh "$build"; } >"$out/memory.txt" 2>&1; fi
if want equal_error; then
  for s in neghip bonsai; do
    { stamp; /usr/bin/python3 tools/equal_error.py --vri "$build/vri" --scene "scenes/$s.json" --size 200 --repeat 2 \
        --plot "docs/performance/equal_error_$s.png"; } >"$out/equal_error_$s.txt" 2>&1
  done
fi
