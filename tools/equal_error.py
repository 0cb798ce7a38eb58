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

Times are whole `vri render` processes (table builds included), the best of
--repeat, wall seconds. A method that does not reach 0 pixels over 1e-3 at
its finest setting is reported with the share of pixels still over.

    /usr/bin/python3 tools/equal_error.py --vri build/vri --scene scenes/neghip.json --size 200
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


MESH_TABLES = [(128, 64), (256, 64), (256, 128), (512, 128)]


def mesh_study(args, scene, label, tmp):
    ref, t_ref = render(args.vri, scene, tmp / "ref.npy", args.size, 1, "--method", "exact", "--tolerance", 1e-6)
    rows = [(label, "exact 1e-6 (reference)", "-", t_ref, 0.0)]
    base = json.loads(pathlib.Path(scene).read_text())
    for name in ["tet-raycast", "pt"]:
        last = None
        for n, m in MESH_TABLES:
            variant = dict(base, method={"name": name, "table_size": n, "length_samples": m})
            path = tmp / "mesh.json"
            path.write_text(json.dumps(variant))
            img, t = render(args.vri, path, tmp / "m.npy", args.size, args.repeat)
            last = (f"table {n}, {m} lengths", t, share_over(img, ref))
            if last[2] == 0:
                break
        rows.append((label, name, last[0] if last[2] == 0 else f"not reached ({last[0]})", last[1], last[2]))
    return rows


def study(args, scene, label, tmp):
    ref, t_ref = render(args.vri, scene, tmp / "ref.npy", args.size, 1, "--method", "exact", "--tolerance", 1e-6)
    rows = [(label, "exact 1e-6 (reference)", "-", t_ref, 0.0)]
    methods = [("riemann", "--step", STEPS), ("preint1", "--step", STEPS), ("preint2", "--step", STEPS),
               ("adaptive guaranteed", "--tolerance", TOLERANCES), ("adaptive coupled", "--tolerance", TOLERANCES)]
    for name, flag, values in methods:
        base = ["--method", "adaptive", "--strategy", name.split()[1]] if name.startswith("adaptive") else \
               ["--method", name]
        last = None
        for v in values:
            img, t = render(args.vri, scene, tmp / "m.npy", args.size, args.repeat, *base, flag, v)
            last = (v, t, share_over(img, ref))
            if last[2] == 0:
                break
        setting = f"{flag[2:]} {last[0]}"
        rows.append((label, name, setting if last[2] == 0 else f"not reached ({setting})", last[1], last[2]))
    img, t = render(args.vri, scene, tmp / "m.npy", args.size, args.repeat, "--method", "preint2-dual")
    s = share_over(img, ref)
    rows.append((label, "preint2-dual", "reached" if s == 0 else "not reached", t, s))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--vri", default="build/vri")
    ap.add_argument("--scene", type=pathlib.Path, default=pathlib.Path("scenes/neghip.json"))
    ap.add_argument("--size", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=2)
    args = ap.parse_args()
    base = json.loads(args.scene.read_text())
    # Paths in the scene are relative to it; the variants live beside it in a temporary folder.
    vol = base["volume"]
    if "file" in vol:
        vol["file"] = str((args.scene.parent / vol["file"]).resolve())
    tf = base["transfer_function"]
    if "file" in tf:
        tf["file"] = str((args.scene.parent / tf["file"]).resolve())
    print("| transfer function | method | coarsest setting with 0 pixels over 1e-3 | wall s | share over |")
    print("|---|---|---|---|---|")
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
            for row in (mesh_study if mesh else study)(args, path, label, tmp):
                print(f"| {row[0]} | {row[1]} | {row[2]} | {row[3]:.3f} | {100 * row[4]:.3f}% |", flush=True)


if __name__ == "__main__":
    main()
