#!/usr/bin/env python3
"""Independent reference for SPEC §4, sharing no code with vri.

Re-implements, from SPEC.md alone, the camera (§6), trilinear sampling (§1),
the transfer function (§3), shading (§5) and the emission-absorption integral (§4) for a
subset of pixels, and compares them with an image rendered by vri.

The integral is computed along each ray by dense uniform sampling with the
trapezoid rule for both the optical depth and the colour integral, at steps
h and h/2, followed by Richardson extrapolation (the trapezoid rule's error
is O(h^2) for the piecewise-smooth integrand, so (4 I_{h/2} - I_h) / 3 removes
its leading term).

With --riemann H it instead evaluates vri's `riemann` convention (samples at
t0 + k*H*voxel, slabs of min(H, t1 - t_k), composited with exp(-tau h)) so
that the riemann method's implementation can be checked too.

usage: reference_spec4.py SCENE.json IMAGE.npy [--pixels N] [--step H]
                          [--riemann H] [--max-diff E]
prints the maximum and RMS difference per channel over the sampled pixels;
with --max-diff, exits 1 if any difference exceeds E.
"""
import argparse, json, math, os, sys
import numpy as np


def load_scene(path):
    base = os.path.dirname(os.path.abspath(path))
    sc = json.load(open(path))
    v = sc["volume"]
    dims = v["dims"]
    dt = {"uint8": np.uint8, "uint16": "<u2", "int16": "<i2", "float32": "<f4"}[v.get("type", "uint8")]
    data = np.fromfile(os.path.join(base, v["file"]), dtype=dt).astype(np.float64)
    vol = data.reshape(dims[2], dims[1], dims[0])  # [k][j][i], x fastest
    spacing = np.array(v.get("spacing", [1, 1, 1]), float)
    origin = np.array(v.get("origin", [0, 0, 0]), float)
    tf = sc["transfer_function"]
    if "file" in tf:
        tf = json.load(open(os.path.join(base, tf["file"])))
    pts = np.array(tf["points"], float)
    light = sc.get("lighting", {})
    if light.get("enabled", False):
        vol_grad = gradients(vol, spacing)
        light = dict(ka=light.get("ambient", 0.3), kd=light.get("diffuse", 0.7),
                     ks=light.get("specular", 0.4), p=light.get("shininess", 32),
                     grad=vol_grad, flat=1e-6 * (vol.max() - vol.min()) / spacing.min())
    else:
        light = None
    return sc, vol, spacing, origin, pts, light


def gradients(vol, spacing):
    """SPEC §5: central differences (one-sided on the border) over the spacing, per grid point."""
    g = np.empty(vol.shape + (3,))
    for axis_np, axis_xyz in ((2, 0), (1, 1), (0, 2)):
        g[..., axis_xyz] = np.gradient(vol, spacing[axis_xyz], axis=axis_np, edge_order=1)
    return g


def lit_colour(light, spacing, origin, p, d, rgb):
    """c_lit = c (ka + kd |N.d|) + ks |N.d|^p with N the trilinearly interpolated gradient, normalised."""
    g = np.stack([trilinear(light["grad"][..., a], spacing, origin, p) for a in range(3)], axis=1)
    n = np.linalg.norm(g, axis=1)
    x = np.abs(g @ d) / np.where(n > 0, n, 1)
    flat = ~(n >= light["flat"]) | (n == 0)
    a = np.where(flat, light["ka"] + light["kd"], light["ka"] + light["kd"] * x)
    b = np.where(flat, 0.0, light["ks"] * x ** light["p"])
    return rgb * a[:, None] + b[:, None]


def tf_eval(pts, s):
    """r,g,b,tau at scalars s: linear between points, ends held, later point wins at a step."""
    xs = pts[:, 0]
    idx = np.searchsorted(xs, s, side="right")  # points with x <= s
    out = np.empty(s.shape + (4,))
    lo = np.clip(idx - 1, 0, len(xs) - 1)
    hi = np.clip(idx, 0, len(xs) - 1)
    x0, x1 = xs[lo], xs[hi]
    w = np.where(x1 > x0, (s - x0) / np.where(x1 > x0, x1 - x0, 1), 0.0)
    w = np.where(idx == 0, 0.0, np.where(idx == len(xs), 0.0, w))
    for c in range(4):
        out[..., c] = pts[lo, c + 1] * (1 - w) + pts[hi, c + 1] * w
    return out


def trilinear(vol, spacing, origin, p):
    nz, ny, nx = vol.shape[:3]
    u = (p - origin) / spacing
    u = np.clip(u, 0, [nx - 1, ny - 1, nz - 1])
    i = np.minimum(np.floor(u).astype(int), [nx - 2, ny - 2, nz - 2])
    f = u - i
    x, y, z = i[:, 0], i[:, 1], i[:, 2]
    fx, fy, fz = f[:, 0], f[:, 1], f[:, 2]
    def V(dx, dy, dz):
        return vol[z + dz, y + dy, x + dx]
    c00 = V(0, 0, 0) * (1 - fx) + V(1, 0, 0) * fx
    c10 = V(0, 1, 0) * (1 - fx) + V(1, 1, 0) * fx
    c01 = V(0, 0, 1) * (1 - fx) + V(1, 0, 1) * fx
    c11 = V(0, 1, 1) * (1 - fx) + V(1, 1, 1) * fx
    return (c00 * (1 - fy) + c10 * fy) * (1 - fz) + (c01 * (1 - fy) + c11 * fy) * fz


def camera_ray(cam, px, py):
    eye = np.array(cam["eye"], float); target = np.array(cam["target"], float)
    up = np.array(cam.get("up", [0, 1, 0]), float)
    W, H = cam["width"], cam["height"]
    w = eye - target; w /= np.linalg.norm(w)
    u = np.cross(up, w); u /= np.linalg.norm(u)
    v = np.cross(w, u)
    a = W / H
    ortho = cam.get("projection", "perspective") == "orthographic"
    half = cam["ortho_height"] / 2 if ortho else math.tan(math.radians(cam.get("fov_y", 30)) / 2)
    x = (2 * (px + 0.5) / W - 1) * half * a
    y = (1 - 2 * (py + 0.5) / H) * half
    if ortho:
        return eye + x * u + y * v, -w
    d = x * u + y * v - w
    return eye, d / np.linalg.norm(d)


def clip(vol, spacing, origin, o, d):
    lo = origin; hi = origin + (np.array(vol.shape[::-1]) - 1) * spacing
    t0, t1 = 0.0, math.inf
    for a in range(3):
        if d[a] == 0:
            if o[a] < lo[a] or o[a] > hi[a]:
                return None, None
            continue
        ta, tb = sorted(((lo[a] - o[a]) / d[a], (hi[a] - o[a]) / d[a]))
        t0, t1 = max(t0, ta), min(t1, tb)
    return (t0, t1) if t1 > t0 else (None, None)


def integrate(vol, spacing, origin, pts, light, o, d, h):
    t0, t1 = clip(vol, spacing, origin, o, d)
    if t0 is None:
        return np.zeros(4)
    n = max(2, int(math.ceil((t1 - t0) / h)) + 1)
    t = np.linspace(t0, t1, n)
    dt = t[1] - t[0]
    p = o + t[:, None] * d
    v = tf_eval(pts, trilinear(vol, spacing, origin, p))
    if light:
        v[:, :3] = lit_colour(light, spacing, origin, p, d, v[:, :3])
    tau = v[:, 3]
    depth = np.concatenate([[0.0], np.cumsum(0.5 * (tau[1:] + tau[:-1]) * dt)])
    T = np.exp(-depth)
    g = v[:, :3] * (tau * T)[:, None]
    C = 0.5 * (g[1:] + g[:-1]).sum(axis=0) * dt
    return np.array([C[0], C[1], C[2], 1 - T[-1]])


def riemann(vol, spacing, origin, pts, light, o, d, h):
    t0, t1 = clip(vol, spacing, origin, o, d)
    if t0 is None:
        return np.zeros(4)
    n = max(1, int(math.ceil((t1 - t0) / h)))
    t = t0 + h * np.arange(n)
    hk = np.minimum(h, t1 - t)
    p = o + t[:, None] * d
    v = tf_eval(pts, trilinear(vol, spacing, origin, p))
    if light:
        v[:, :3] = lit_colour(light, spacing, origin, p, d, v[:, :3])
    a = 1 - np.exp(-v[:, 3] * hk)
    T = np.concatenate([[1.0], np.cumprod(1 - a)])
    C = (v[:, :3] * (T[:-1] * a)[:, None]).sum(axis=0)
    return np.array([C[0], C[1], C[2], 1 - T[-1]])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene"); ap.add_argument("image")
    ap.add_argument("--pixels", type=int, default=400)
    ap.add_argument("--step", type=float, default=0.01, help="world units")
    ap.add_argument("--riemann", type=float, help="check riemann at this step (voxel units)")
    ap.add_argument("--max-diff", type=float)
    args = ap.parse_args()
    sc, vol, spacing, origin, pts, light = load_scene(args.scene)
    img = np.load(args.image)
    H, W = img.shape[:2]
    cam = dict(sc["camera"]); cam["width"], cam["height"] = W, H
    rng = np.random.default_rng(7)
    # pixels where the image is not empty, plus a few random ones
    ys, xs = np.nonzero(img[..., 3] > 1e-3)
    pick = rng.choice(len(xs), size=min(args.pixels, len(xs)), replace=False)
    diffs = []
    for k in pick:
        o, d = camera_ray(cam, xs[k], ys[k])
        if args.riemann:
            ref = riemann(vol, spacing, origin, pts, light, o, d, args.riemann * spacing.min())
        else:
            a = integrate(vol, spacing, origin, pts, light, o, d, args.step)
            b = integrate(vol, spacing, origin, pts, light, o, d, args.step / 2)
            ref = (4 * b - a) / 3
        diffs.append(img[ys[k], xs[k]].astype(np.float64) - ref)
    diffs = np.abs(np.array(diffs))
    for c, name in enumerate("rgba"):
        print(f"{name}: max {diffs[:, c].max():.3e}  rms {math.sqrt((diffs[:, c] ** 2).mean()):.3e}")
    print(f"pixels compared: {len(diffs)}")
    if args.max_diff is not None and diffs.max() > args.max_diff:
        print(f"FAIL: difference {diffs.max():.3e} exceeds {args.max_diff:g}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
