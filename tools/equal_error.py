#!/usr/bin/env python3
"""Methods compared at equal error (issue 16, item 7; docs/ACCURACY.md).

For one volume and three transfer functions - the scene's own, an opaque one
(a steep ramp to tau = 40 per voxel unit) and a high-frequency one (a comb of
spikes one scalar unit wide) - finds, for each method, the coarsest setting
that leaves 0 pixels off by more than 1e-3 (in any channel) from `exact` at
tolerance 1e-6, and its time:

  riemann, preint1, preint2   step 2, 1, 1/2, ... down to 1/32 voxel
  adaptive (guaranteed)       tolerance 1e-2, 1e-3, ... down to 1e-5
  adaptive (coupled)          tolerance 1e-2, ... down to 1e-5
  preint2-dual                its one setting (no step): reached or not

and for a tetrahedral mesh (a scene whose volume is a .vtk/.vtu file):

  tet-raycast, pt             (table size, length samples) (128, 64),
                              (256, 64), (256, 128), (512, 128)

and the coarsest setting whose RMS error (over all channels and pixels) is
at most 1e-3. Every setting is rendered, so that --plot can draw each
method's error against its time (RMS and largest error, one panel per
transfer function, log-log; issue 21, item 3): the method to pick for an
error is the leftmost curve at that height.

Times are whole `vri render` processes (table builds included), the best of
--repeat, wall seconds. A method that does not reach 0 pixels over 1e-3 at
its finest setting is reported with the share of pixels still over.

    /usr/bin/python3 tools/equal_error.py --vri build/vri --scene scenes/neghip.json --size 200 \
        [--plot docs/performance/equal_error_neghip.png]
"""
import argparse
import json
import pathlib
import subprocess
import tempfile
import time

import numpy as np

TOL = 1e-3
STEPS = [2, 1, 0.5, 0.25, 0.125, 0.0625, 0.03125]
TOLERANCES = [1e-2, 1e-3, 1e-4, 1e-5]


def opaque_tf():
    # A steep opaque ramp: tau 0 -> 40 over 60..64, then flat and opaque.
    return {"points": [[0, 0, 0, 0, 0], [60, 0.9, 0.5, 0.2, 0], [64, 0.9, 0.8, 0.3, 40],
                       [255, 1, 1, 1, 40]]}


def comb_tf():
    # Spikes one scalar unit wide every 16 units from 24 on, tau 4 at their tops.
    pts = [[0, 0, 0, 0, 0]]
    for k, s in enumerate(range(24, 250, 16)):
        c = [round(0.2 + 0.8 * f, 3) for f in (((k * 37) % 11) / 10, ((k * 53) % 7) / 6, ((k * 29) % 5) / 4)]
        pts += [[s - 0.5] + c + [0], [s] + c + [4], [s + 0.5] + c + [0]]
    pts.append([255, 0, 0, 0, 0])
    return {"points": pts}


def render(vri, scene, out, size, repeat, *flags):
    cmd = [vri, "render", str(scene), "-o", str(out), "--width", str(size), "--height", str(size),
           *map(str, flags)]
    best = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(cmd, capture_output=True, text=True, check=True)
        t = time.perf_counter() - t0
        best = t if best is None else min(best, t)
    return np.load(out).astype(np.float64), best


def share_over(img, ref):
    return float(np.mean(np.any(np.abs(img - ref) > TOL, axis=-1)))


def errors(img, ref):
    """(share of pixels over 1e-3, RMS error, largest error) over all channels."""
    d = img - ref
    return share_over(img, ref), float(np.sqrt(np.mean(d ** 2))), float(np.abs(d).max())


def summary(label, name, flag, points):
    """The table row of one method from its (setting, time, share, rms, max)
    points, coarsest first: the first setting with 0 pixels over, and the
    first with RMS <= 1e-3."""
    over = next((p for p in points if p[2] == 0), None)
    rms = next((p for p in points if p[3] <= TOL), None)
    last = points[-1]
    where = f"{flag} {over[0]}" if over else f"not reached ({flag} {last[0]}: {100 * last[2]:.3f}% over)"
    by_rms = f"{flag} {rms[0]} ({rms[1]:.3f} s)" if rms else "not reached"
    return (label, name, where, (over or last)[1], by_rms)


MESH_TABLES = [(128, 64), (256, 64), (256, 128), (512, 128)]


def mesh_study(args, scene, label, tmp):
    ref, t_ref = render(args.vri, scene, tmp / "ref.npy", args.size, 1, "--method", "exact", "--tolerance", 1e-6)
    rows, curves = [(label, "exact 1e-6 (reference)", "-", t_ref, "-")], {}
    base = json.loads(pathlib.Path(scene).read_text())
    for name in ["tet-raycast", "pt"]:
        points = []
        for n, m in MESH_TABLES:
            variant = dict(base, method={"name": name, "table_size": n, "length_samples": m})
            path = tmp / "mesh.json"
            path.write_text(json.dumps(variant))
            img, t = render(args.vri, path, tmp / "m.npy", args.size, args.repeat)
            points.append((f"{n}/{m}", t, *errors(img, ref)))
        rows.append(summary(label, name, "table/lengths", points))
        curves[name] = points
    return rows, curves


def study(args, scene, label, tmp):
    ref, t_ref = render(args.vri, scene, tmp / "ref.npy", args.size, 1, "--method", "exact", "--tolerance", 1e-6)
    rows, curves = [(label, "exact 1e-6 (reference)", "-", t_ref, "-")], {}
    methods = [("riemann", "--step", STEPS), ("preint1", "--step", STEPS), ("preint2", "--step", STEPS),
               ("adaptive guaranteed", "--tolerance", TOLERANCES), ("adaptive coupled", "--tolerance", TOLERANCES)]
    for name, flag, values in methods:
        base = ["--method", "adaptive", "--strategy", name.split()[1]] if name.startswith("adaptive") else \
               ["--method", name]
        points = []
        for v in values:
            img, t = render(args.vri, scene, tmp / "m.npy", args.size, args.repeat, *base, flag, v)
            points.append((v, t, *errors(img, ref)))
        rows.append(summary(label, name, flag[2:], points))
        curves[name] = points
    img, t = render(args.vri, scene, tmp / "m.npy", args.size, args.repeat, "--method", "preint2-dual")
    points = [("-", t, *errors(img, ref))]
    rows.append(summary(label, "preint2-dual", "its one setting", points))
    curves["preint2-dual"] = points
    return rows, curves


def plot(path, title, panels):
    """Error against time, one column per transfer function: RMS above, the
    largest error below, each method a curve through its settings."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, len(panels), figsize=(4.2 * len(panels), 6.4), squeeze=False)
    for col, (label, curves) in enumerate(panels):
        for row, (k, what) in enumerate([(3, "RMS error"), (4, "largest error")]):
            ax = axes[row][col]
            for name, points in curves.items():
                ax.plot([p[1] for p in points], [max(p[k], 1e-8) for p in points], "o-", ms=3, label=name)
            ax.axhline(TOL, color="grey", lw=0.8, ls="--")
            ax.set_xscale("log"), ax.set_yscale("log")
            ax.set_xlabel("wall s (whole process)"), ax.set_ylabel(what)
            if row == 0:
                ax.set_title(label)
    axes[0][0].legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--vri", default="build/vri")
    ap.add_argument("--scene", type=pathlib.Path, default=pathlib.Path("scenes/neghip.json"))
    ap.add_argument("--size", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--plot", type=pathlib.Path, help="write the error-against-time plot (PNG) here")
    args = ap.parse_args()
    base = json.loads(args.scene.read_text())
    # Paths in the scene are relative to it; the variants live beside it in a temporary folder.
    vol = base["volume"]
    if "file" in vol:
        vol["file"] = str((args.scene.parent / vol["file"]).resolve())
    tf = base["transfer_function"]
    if "file" in tf:
        tf["file"] = str((args.scene.parent / tf["file"]).resolve())
    print("| transfer function | method | coarsest setting with 0 pixels over 1e-3 | wall s | coarsest with RMS <= 1e-3 |")
    print("|---|---|---|---|---|")
    panels = []
    mesh = vol.get("file", "").endswith((".vtk", ".vtu"))
    with tempfile.TemporaryDirectory() as d:
        tmp = pathlib.Path(d)
        # The opaque ramp and the comb are written in scalar units 0..255; on
        # a mesh the scene's own transfer function is the study.
        tfs = [("the scene's", tf)] if mesh else [("the scene's", tf), ("opaque ramp", opaque_tf()),
                                                   ("comb of spikes", comb_tf())]
        for label, tfj in tfs:
            scene = dict(base, transfer_function=tfj)
            path = tmp / "scene.json"
            path.write_text(json.dumps(scene))
            rows, curves = (mesh_study if mesh else study)(args, path, label, tmp)
            for row in rows:
                print(f"| {row[0]} | {row[1]} | {row[2]} | {row[3]:.3f} | {row[4]} |", flush=True)
            panels.append((label, curves))
    if args.plot:
        plot(args.plot, f"{args.scene.stem}, {args.size}x{args.size}: error against time", panels)


if __name__ == "__main__":
    main()
