#!/usr/bin/python3
"""The table of docs/PERFORMANCE.md, "Regular grids beside VTK", from the
files `PARTS=vtk_grid bash scripts/performance.sh OUT` writes
(OUT/vtk_grid_*.txt, one a view, each vtk_grid_side_by_side.py's output):

  /usr/bin/python3 scripts/vtk_grid_summary.py OUT

One row a view: VTK FixedPoint's frame (ms, RMS), `preint1` at step 1 with
skipping, `preint1` and `riemann` at VTK's error (step, ms, RMS, and VTK's
wall time over vri's), then the range of `preint1`'s ratio at VTK's error
and on how many views it reaches 2× (the side-by-side script's own verdict).
"""
import glob, os, re, sys

VIEWS = [("neghip", "neghip"), ("neghip_turned", "neghip, azimuth 90"), ("engine", "engine"),
         ("engine_turned", "engine, azimuth 90, elevation 30"), ("bonsai", "bonsai"),
         ("bonsai_turned", "bonsai, azimuth 90"), ("neghip_opaque", "neghip_opaque"),
         ("neghip_spike", "neghip_spike"), ("engine_opaque", "engine_opaque"), ("engine_spike", "engine_spike"),
         ("bonsai_opaque", "bonsai_opaque"), ("bonsai_spike", "bonsai_spike")]


def rows(path):
    """{renderer: [wall ms, cpu ms, ratio, rms]} and the file's first line (date, load)."""
    out, stamp = {}, ""
    for line in open(path):
        if line.startswith("preint1 at VTK's error"):
            out["met"] = "(target 2x: met)" in line
        if line.startswith("# "):
            stamp = stamp or line[2:].strip()
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 5 and re.match(r"^[0-9.]+$", cells[1]):
            out[cells[0]] = [float(cells[1]), float(cells[2]), float(cells[3]), float(cells[4])]
    return out, stamp


def at_vtk_error(table, method):
    for name, row in table.items():
        m = re.match(rf"vri {method} step ([0-9.]+), termination 0.002: at VTK's error", name)
        if m:
            return m.group(1), row
    sys.exit(f"no '{method} at VTK's error' row")


out_dir = sys.argv[1]
print("| view | VTK FixedPoint ms (RMS) | `preint1` step 1 ms (RMS), × | `preint1` at VTK's error: step, ms (RMS), × "
      "| `riemann` at VTK's error: step, × |")
print("|---|---|---|---|---|")
ratios, stamps, met = [], [], 0
for key, label in VIEWS:
    path = os.path.join(out_dir, f"vtk_grid_{key}.txt")
    if not os.path.exists(path):
        sys.exit(f"{path} is missing: run PARTS=vtk_grid bash scripts/performance.sh {out_dir}")
    t, stamp = rows(path)
    stamps.append(stamp)
    vtk = t["VTK FixedPoint, sample distance 1"]
    p1 = t["vri preint1 step 1, skipping"]
    ps, pe = at_vtk_error(t, "preint1")
    rs, re_ = at_vtk_error(t, "riemann")
    ratios.append(pe[2])
    met += t["met"]
    print(f"| {label} | {vtk[0]:.1f} ({vtk[3]:.4f}) | {p1[0]:.1f} ({p1[3]:.4f}), {p1[2]:.2f} "
          f"| {ps}, {pe[0]:.1f} ({pe[3]:.4f}), {pe[2]:.2f} | {rs}, {re_[2]:.2f} |")
print()
print(f"`preint1` at VTK's error: {min(ratios):.2f}–{max(ratios):.2f}× VTK FixedPoint's frame rate; "
      f"2× or more on {met} of {len(ratios)} views (the script's own test, on unrounded times).")
print(f"Runs: {stamps[0]} … {stamps[-1]}.")
