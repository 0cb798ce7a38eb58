#!/usr/bin/python3
"""differential.py BUILD [--first SEED] [--cases N] [--report FILE.md]
[--paths python,vulkan,mpi,threads]: the verification generator's cases
(vri-verify --scenes, docs/VERIFICATION.md) through every front door, each
against the CLI's CPU render of the same case and method:

- python:  vri.render(scene, method=...) equals the CLI's .npy byte for byte
           (SPEC §11);
- threads: the CLI with 1 and 2 threads gives the same bytes;
- vulkan:  --backend vulkan within docs/GPU.md's bounds of the CPU float
           path (riemann, preint1, preint2: 1e-4 plus what a 1e-6 scalar
           error moves on the steepest transfer-function segment, as the
           float-vs-double check; preint2-dual the same; adaptive guaranteed
           within its tolerance of exact);
- mpi:     mpirun -np 2 (even seeds) or 3 (odd) --distributed within 1e-6
           of one process (SPEC §11).

Prints one line per violation and a summary; exits 1 on any violation.
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile

import numpy as np

METHODS = {  # method -> CLI flags; steps as the float-vs-double check's; exact first (adaptive's reference)
    "exact": ["--tolerance", "1e-6"],
    "riemann": ["--step", "0.5"],
    "preint1": ["--step", "0.5"],
    "preint2": ["--step", "0.5", "--iterations", "64"],
    "preint2-dual": ["--iterations", "64"],
    "adaptive": ["--strategy", "guaranteed", "--tolerance", "1e-3"],
}
GPU = {"riemann", "preint1", "preint2", "preint2-dual", "adaptive"}
DISTRIBUTED = set(METHODS)


def steepest(tf_points):
    """1e-6 x the scalar range x the steepest rgb / alpha-per-unit-length slope."""
    pts = sorted(tf_points, key=lambda p: p[0])
    s_range = pts[-1][0] - pts[0][0] if len(pts) > 1 else 0.0
    slope = 0.0
    for a, b in zip(pts, pts[1:]):
        ds = b[0] - a[0]
        if ds <= 1e-9 * max(1.0, abs(a[0])):
            return None  # coincident points: a step, no slope bound
        slope = max(slope, max(abs(b[k] - a[k]) for k in range(1, 4)) / ds, abs(b[4] - a[4]) * 0.5 / ds)
    return 1e-6 * s_range * slope


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--cases", type=int, default=20)
    ap.add_argument("--report")
    ap.add_argument("--paths", default="python,threads,vulkan,mpi")
    args = ap.parse_args()
    build = pathlib.Path(args.build).resolve()
    vri_cli = str(build / "vri")
    paths = set(args.paths.split(","))
    sys.path.insert(0, str(build / "python"))
    import vri  # noqa: E402  (the module of this build)

    if "vulkan" in paths and not vri.has_vulkan:
        paths.discard("vulkan")
    scenes = subprocess.run([str(build / "tests" / "vri-verify"), "--first", str(args.first), "--cases",
                             str(args.cases), "--scenes"], check=True, capture_output=True, text=True).stdout.split("\n")
    violations, checked, refused = [], {p: 0 for p in paths}, {p: 0 for p in paths}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)

        def cli(scene, out, method, *extra, ranks=0):
            cmd = [vri_cli, "render", str(scene), "-o", str(out), "-q", "--method", method, *METHODS[method], *extra]
            if ranks:
                cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), *cmd, "--distributed"]
            r = subprocess.run(cmd, capture_output=True, text=True)
            return r.returncode, (r.stderr.strip().splitlines() or [""])[-1]

        for k, text in enumerate(s for s in scenes if s.strip()):
            seed = args.first + k
            scene = tmp / f"case{seed}.json"
            scene.write_text(text)
            tf = json.loads(text)["transfer_function"]["points"]
            bound = steepest(tf)
            exact_img = None
            for method in METHODS:
                base = tmp / f"{seed}_{method}.npy"
                code, err = cli(scene, base, method, "--threads", "2")
                if code != 0:  # the CPU refuses the case (a cap, say): every door must refuse it too
                    continue
                one = np.load(base)
                if method == "exact":
                    exact_img = one

                def bad(path, detail):
                    violations.append(f"seed {seed}: {method}: {path}: {detail}")

                if "threads" in paths:
                    code, err = cli(scene, tmp / "t1.npy", method, "--threads", "1")
                    checked["threads"] += 1
                    if code != 0:
                        bad("threads", f"1 thread failed: {err}")
                    elif np.load(tmp / "t1.npy").tobytes() != one.tobytes():
                        bad("threads", "1 and 2 threads differ")
                if "python" in paths:
                    checked["python"] += 1
                    kw = {"method": method}
                    flags = METHODS[method]
                    for i in range(0, len(flags), 2):
                        key = flags[i][2:].replace("-", "_")
                        value = flags[i + 1]
                        kw[key] = value if key == "strategy" else (int(value) if key == "iterations" else float(value))
                    try:
                        img = np.asarray(vri.render(vri.load_scene(str(scene)), threads=2, **kw))
                        if img.tobytes() != one.tobytes():
                            bad("python", f"not the CLI's bytes (max {np.abs(img - one).max():.3g})")
                    except Exception as e:  # noqa: BLE001  (any failure is the finding)
                        bad("python", f"raised {type(e).__name__}: {e}")
                if "vulkan" in paths and method in GPU:
                    code, err = cli(scene, tmp / "gpu.npy", method, "--backend", "vulkan")
                    checked["vulkan"] += 1
                    if code != 0:
                        refused["vulkan"] += 1
                        if "not on the GPU" not in err and "at least" not in err:
                            bad("vulkan", f"failed: {err}")
                    else:
                        gpu = np.load(tmp / "gpu.npy")
                        if method == "adaptive":
                            ref, limit = exact_img, 1e-3 + 1e-6
                        else:
                            ref, limit = one, None if bound is None else 1e-4 + bound
                        if ref is None or limit is None:
                            refused["vulkan"] += 1  # no bound (coincident points) or no exact image
                        else:
                            d = float(np.abs(gpu.astype(np.float64) - ref).max())
                            if not np.isfinite(d) or d > limit:
                                bad("vulkan", f"max {d:.3g} over {limit:.3g}")
                if "mpi" in paths and method in DISTRIBUTED:
                    ranks = 2 + seed % 2  # 2 ranks on even seeds, 3 on odd ones
                    code, err = cli(scene, tmp / "mpi.npy", method, "--threads", "1", ranks=ranks)
                    checked["mpi"] += 1
                    if code != 0:
                        bad("mpi", f"{ranks} ranks failed: {err}")
                    else:
                        d = float(np.abs(np.load(tmp / "mpi.npy").astype(np.float64) - one).max())
                        if not np.isfinite(d) or d > 1e-6:
                            bad("mpi", f"{ranks} ranks: max {d:.3g} over 1e-6")
            print(f"case {seed}: {len(violations)} violations so far", file=sys.stderr, flush=True)
    summary = ", ".join(f"{p} {n} renders ({refused[p]} refused or unbounded)" for p, n in sorted(checked.items()))
    lines = [f"{args.cases} cases from seed {args.first}: {summary}; {len(violations)} violations"] + violations
    print("\n".join(lines))
    if args.report:
        pathlib.Path(args.report).write_text("\n".join(lines) + "\n")
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
