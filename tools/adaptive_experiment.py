#!/usr/bin/env python3
"""Campagnolo, Celes & de Figueiredo 2015, Section IV, reproduced with vri.

For each scene: renders the reference with `exact` (tolerance 1e-6), then
`riemann` at h = 0.5 .. 0.1 and `adaptive` (coupled, decoupled, guaranteed) at
each tolerance, and prints, per channel, the percentage of pixels whose
absolute error against the reference exceeds each tolerance (the paper's
Tables I and II), the render times (Table III) and the hmin = 0.4, hmax = 4
run (Tables V and VI). Times are the renderer's own figures ("rendered ...
in X s (CPU Y s)"), so loading the volume is not counted: wall clock and the
CPU seconds of all threads, the steadier figure on a shared machine.

    python3 tools/adaptive_experiment.py --vri build/vri --size 800x600 \
        --scenes scenes/bonsai.json scenes/engine.json --out out/adaptive

With --repeat N each configuration is rendered N times and the fastest time
is kept (the machine may be shared). Writes OUT/<scene>/*.npy, OUT/results.json and OUT/tables.md.
"""
import argparse
import json
import pathlib
import re
import subprocess

import numpy as np

TOLERANCES = [0.01, 0.005, 0.001]
RIEMANN_STEPS = [0.5, 0.4, 0.3, 0.2, 0.1]
CHANNELS = "RGBA"


REPEAT = 1  # renders per configuration; the fastest time is kept (--repeat)


def render(vri, scene, out, size, threads, *flags):
    w, h = size
    cmd = [vri, "render", str(scene), "-o", str(out), "--width", str(w), "--height", str(h),
           "--threads", str(threads), *map(str, flags)]
    seconds, cpu = [], []
    for _ in range(REPEAT):
        res = subprocess.run(cmd, capture_output=True, text=True, check=True)
        m = re.search(r" in ([0-9.eE+-]+) s \(CPU ([0-9.eE+-]+) s\)", res.stderr)
        seconds.append(float(m.group(1)))
        cpu.append(float(m.group(2)))
    return np.load(out), (min(seconds), min(cpu))


def shares_over(img, ref):
    """Per channel, % of pixels with |img - ref| > eps, for each tolerance eps."""
    d = np.abs(img.astype(np.float64) - ref.astype(np.float64))
    return {str(eps): [100.0 * float(np.mean(~(d[..., c] <= eps))) for c in range(4)] for eps in TOLERANCES}


def run_scene(args, scene):
    name = scene.stem
    out = args.out / name
    out.mkdir(parents=True, exist_ok=True)
    ref, t_ref = render(args.vri, scene, out / "exact.npy", args.size, args.threads,
                        "--method", "exact", "--tolerance", "1e-6")
    rows = [{"label": "exact (reference, 1e-6)", "seconds": t_ref[0], "cpu": t_ref[1]}]
    for h in RIEMANN_STEPS:
        img, t = render(args.vri, scene, out / f"riemann_{h}.npy", args.size, args.threads,
                        "--method", "riemann", "--step", h)
        rows.append({"label": f"Riemann (h = {h})", "seconds": t[0], "cpu": t[1], "over": shares_over(img, ref)})
    for strategy in ["coupled", "decoupled", "guaranteed"]:
        for eps in TOLERANCES:
            flags = ["--method", "adaptive", "--strategy", strategy, "--tolerance", eps]
            if strategy == "guaranteed":
                flags += ["--error-estimate", out / f"{strategy}_{eps}_estimate.npy"]
            img, t = render(args.vri, scene, out / f"{strategy}_{eps}.npy", args.size, args.threads, *flags)
            err = np.abs(img.astype(np.float64) - ref)
            row = {"label": f"{strategy.capitalize()} (eps = {eps})", "strategy": strategy,
                   "eps": eps, "seconds": t[0], "cpu": t[1], "over": shares_over(img, ref),
                   "max_error": float(err.max())}
            if strategy == "guaranteed":
                est = np.load(out / f"{strategy}_{eps}_estimate.npy")
                # The estimate bounds the error up to the early stop's 0.1 eps.
                row["estimate_max"] = float(est.max())
                row["estimate_bounds_pct"] = 100.0 * float(np.mean(err <= est + 0.1 * eps))
            rows.append(row)
    # Tables V and VI: eps = 0.001 with hmin = 0.4, hmax = 4.
    for strategy in ["coupled", "decoupled"]:
        img, t = render(args.vri, scene, out / f"{strategy}_wide.npy", args.size, args.threads,
                        "--method", "adaptive", "--strategy", strategy, "--tolerance", 0.001,
                        "--hmin", 0.4, "--hmax", 4.0)
        rows.append({"label": f"{strategy.capitalize()} (eps = 0.001, hmin = 0.4, hmax = 4)",
                     "strategy": strategy, "wide": True, "seconds": t[0], "cpu": t[1],
                     "over": shares_over(img, ref)})
    return rows


def tables(rows):
    """The paper's layout: accuracy (Tables I/II: an adaptive row takes each
    column group from its run at that eps), times (Table III), and the
    hmin = 0.4, hmax = 4 run (Tables V/VI)."""
    head = "| method | " + " | ".join(f"{c} >{e}" for e in TOLERANCES for c in CHANNELS) + " |"
    rule = "|---" * (1 + 4 * len(TOLERANCES)) + "|"
    fmt = lambda vals: " | ".join(f"{v:.4f}" for v in vals)
    acc = [head, rule]
    for r in rows:
        if r["label"].startswith("Riemann"):
            acc.append(f"| {r['label']} | " + " | ".join(fmt(r["over"][str(e)]) for e in TOLERANCES) + " |")
    for strategy in ["coupled", "decoupled", "guaranteed"]:
        by_eps = {r["eps"]: r for r in rows if r.get("strategy") == strategy and not r.get("wide")}
        acc.append(f"| {strategy.capitalize()} | " +
                   " | ".join(fmt(by_eps[e]["over"][str(e)]) for e in TOLERANCES) + " |")
    times = ["| method | wall (s) | CPU (s) | max error | max error estimate | error <= estimate + 0.1 eps |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        if not r.get("wide"):
            err = f"{r['max_error']:.2e}" if "max_error" in r else ""
            est = f"{r['estimate_max']:.2e} | {r['estimate_bounds_pct']:.3f}%" if "estimate_max" in r else " |"
            times.append(f"| {r['label']} | {r['seconds']:.2f} | {r['cpu']:.2f} | {err} | {est} |")
    wide = ["| method | wall (s) | CPU (s) | " + " | ".join(f"{c} >0.001" for c in CHANNELS) + " |", "|---" * 7 + "|"]
    for r in rows:
        if r.get("wide") or r["label"] == "Riemann (h = 0.1)":
            wide.append(f"| {r['label']} | {r['seconds']:.2f} | {r['cpu']:.2f} | " + fmt(r["over"]["0.001"]) + " |")
    return "\n".join(acc), "\n".join(times), "\n".join(wide)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--vri", default="build/vri")
    ap.add_argument("--size", default="800x600")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--scenes", nargs="+", type=pathlib.Path,
                    default=[pathlib.Path("scenes/bonsai.json"), pathlib.Path("scenes/engine.json")])
    ap.add_argument("--out", type=pathlib.Path, default=pathlib.Path("out/adaptive"))
    ap.add_argument("--repeat", type=int, default=1, help="renders per configuration, fastest time kept")
    args = ap.parse_args()
    global REPEAT
    REPEAT = args.repeat
    args.size = tuple(int(x) for x in args.size.split("x"))
    args.out.mkdir(parents=True, exist_ok=True)
    results, md = {}, []
    for scene in args.scenes:
        rows = run_scene(args, scene)
        results[scene.stem] = rows
        acc, times, wide = tables(rows)
        size = f"{args.size[0]}x{args.size[1]}"
        md.append(f"### {scene.stem}, {size}: % of pixels with error > eps (Tables I/II)\n\n{acc}\n\n"
                  f"### {scene.stem}, {size}: render time (Table III)\n\n{times}\n\n"
                  f"### {scene.stem}, {size}: hmin = 0.4, hmax = 4, eps = 0.001 (Tables V/VI)\n\n{wide}\n")
        (args.out / "results.json").write_text(json.dumps(results, indent=1))
        (args.out / "tables.md").write_text("\n".join(md))
        print(md[-1], flush=True)


if __name__ == "__main__":
    main()
