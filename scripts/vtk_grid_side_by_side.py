#!/usr/bin/python3
"""vri's ray casters beside VTK's vtkFixedPointVolumeRayCastMapper on a regular
grid: the same volume, transfer function and camera, rendered back to back in
one run; time per frame (wall and CPU) and error against vri's `exact`
(docs/PERFORMANCE.md, "Regular grids beside VTK").

Needs Debian's python3-vtk9 and, without a display, Xvfb:
  xvfb-run -a -s "-screen 0 1024x768x24" /usr/bin/python3 scripts/vtk_grid_side_by_side.py \
      scenes/neghip.json 512 /tmp/side [--repeat 5] [--exact-tolerance 1e-4]
It runs ./build/vri with 2 threads: `exact` (the reference, kept in OUT as
<scene>_exact.npy and reused when present), `preint1` and `riemann` at step 1
with empty-space skipping (the default), with skipping and early termination
below transmittance 0.002 (under one 8-bit step), and with neither (--no-skip,
the plain path; for preint1 also --double: its double-precision path, with
skipping and as the plain path), then VTK's FixedPoint mapper with 2 threads at
sample distance 1 voxel, and VTK's GPU ray caster (vtkGPUVolumeRayCastMapper,
no jittering, sample distance 1 voxel; on a machine without a GPU it runs on
Mesa's llvmpipe, so set LP_NUM_THREADS=2 for a like-for-like two-thread run;
--no-gpu leaves it out). "VTK wall / this" is the FixedPoint mapper's time over
each row's.
Each vri time is the fastest of --repeat renders as vri reports it (the render
only: not loading the volume, building the macro cells or the table); each VTK
time is the mean of --repeat frames after a first, untimed one.

Equal error (issue 21): the rows "at VTK's error" are each vri method at the
coarsest step of a ladder (preint1: 0.5 to 4 voxels, riemann: 0.25 to 2, in
steps of 0.05 voxel up to 1.5, with early termination below 0.002) whose RMS error is below the FixedPoint
mapper's: the speed a user gets for the same picture quality. The last line says whether preint1 is there at least twice VTK's
frame rate. --azimuth and --elevation turn the scene's camera (VTK's
Azimuth and Elevation, as `vri render` applies them) for more views.

Errors are over RGB composited on black (VTK's framebuffer alpha is not
comparable); VTK's image is 8-bit, so vri's is also scored after rounding to
8 bits ("RMS 8-bit"), which is what a screen shows.

Transfer function: VTK's FixedPoint mapper looks the function up at whole
scalar values, so vri's (s, r, g, b, tau) function is sampled at every whole
scalar of the data's range (and at its control points): colour points (r, g, b)
and scalar-opacity points a = 1 - exp(-tau) with ScalarOpacityUnitDistance 1
voxel, so a slab of one voxel has the same opacity in both. VTK interpolates
a (not tau) and its colour and opacity in 15-bit fixed point: part of its
error is that model, not only the step.
"""
import argparse, gzip, json, os, re, subprocess
import numpy as np
import vtk
from vtk.util import numpy_support as ns
from vtk_frames import render_frames, scene_camera

ap = argparse.ArgumentParser()
ap.add_argument("scene"); ap.add_argument("size", type=int); ap.add_argument("out")
ap.add_argument("--repeat", type=int, default=5)
ap.add_argument("--exact-tolerance", default="1e-4")
ap.add_argument("--no-gpu", action="store_true", help="leave out VTK's GPU mapper")
ap.add_argument("--gl", default="Mesa llvmpipe, 2 threads", help="what OpenGL runs on, for the table")
ap.add_argument("--azimuth", type=float, default=0, help="turn the camera about its up vector (degrees)")
ap.add_argument("--elevation", type=float, default=0, help="raise the camera (degrees)")
args = ap.parse_args()
os.makedirs(args.out, exist_ok=True)
size = args.size
motions = [*(["--azimuth", str(args.azimuth)] if args.azimuth else []),
           *(["--elevation", str(args.elevation)] if args.elevation else [])]
view = "".join(f"_{m[2:4]}{v}" for m, v in zip(motions[::2], motions[1::2]))
name = os.path.splitext(os.path.basename(args.scene))[0] + view
scene = json.load(open(args.scene))
base = os.path.dirname(os.path.abspath(args.scene))
vri = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "vri")


def load_json(spec):
    return json.load(open(os.path.join(base, spec["file"]))) if "file" in spec else spec


# ---- the volume (raw with dims and type in the scene, or a raw/gzip NRRD) ----
DTYPES = {"uint8": np.uint8, "uint16": np.uint16, "int16": np.int16, "float32": np.float32,
          "unsigned char": np.uint8, "uchar": np.uint8, "float": np.float32, "ushort": np.uint16}
vol = scene["volume"]
path = os.path.join(base, vol["file"])
if path.endswith(".nrrd"):
    raw = open(path, "rb").read()
    head, body = raw.split(b"\n\n", 1)
    fields = dict(l.split(": ", 1) for l in head.decode().splitlines()[1:] if ": " in l and not l.startswith("#"))
    dims = [int(x) for x in fields["sizes"].split()]
    dtype = DTYPES[fields["type"]]
    data = gzip.decompress(body) if fields.get("encoding") in ("gzip", "gz") else body
    spacing = [float(x) for x in fields.get("spacings", "1 1 1").split()]
else:
    dims, dtype, spacing = vol["dims"], DTYPES[vol["type"]], vol.get("spacing", [1, 1, 1])
    data = open(path, "rb").read()
spacing = vol.get("spacing", spacing)
origin = vol.get("origin", [0, 0, 0])
values = np.frombuffer(data, dtype=dtype, count=dims[0] * dims[1] * dims[2])
image = vtk.vtkImageData()
image.SetDimensions(*dims)
image.SetSpacing(*spacing)
image.SetOrigin(*origin)
image.GetPointData().SetScalars(ns.numpy_to_vtk(values.copy(), deep=1))

# ---- the transfer function, evaluated as vri does (SPEC §3) ----
points = load_json(scene["transfer_function"])["points"]


def tf_at(s):
    """(r, g, b, tau) at s: linear between points, ends held, the later of two equal-s points at s."""
    j = max((i for i, p in enumerate(points) if p[0] <= s), default=-1)
    if j < 0:
        return points[0][1:]
    if j == len(points) - 1:
        return points[-1][1:]
    a, b = points[j], points[j + 1]
    w = (s - a[0]) / (b[0] - a[0])
    return [a[k] + w * (b[k] - a[k]) for k in range(1, 5)]


color = vtk.vtkColorTransferFunction()
opacity = vtk.vtkPiecewiseFunction()
scalars = sorted(set(range(int(np.floor(values.min())), int(np.ceil(values.max())) + 1)) |
                 {p[0] for p in points if values.min() <= p[0] <= values.max()})
for s in scalars:
    r, g, b, tau = tf_at(s)
    color.AddRGBPoint(s, r, g, b)
    opacity.AddPoint(s, 1 - np.exp(-tau))
prop = vtk.vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(min(spacing))
prop.SetInterpolationTypeToLinear()
prop.ShadeOff()


# ---- vri ----
def vri_render(method, extra=(), repeat=args.repeat, step=1):
    out = os.path.join(args.out, f"{name}_vri_{method}{'_'.join(extra).replace('-', '_').replace('.', '')}.npy")
    best = None
    for _ in range(repeat):
        r = subprocess.run([vri, "render", args.scene, "--method", method, "--step", str(step), "--width", str(size),
                            "--height", str(size), "--threads", "2", "-o", out, *motions, *extra], check=True,
                           capture_output=True, text=True)
        m = re.search(r" in ([0-9.eE+-]+) s \(CPU ([0-9.eE+-]+) s\)", r.stderr)
        wall, cpu = float(m.group(1)), float(m.group(2))
        if best is None or wall < best[0]:
            best = (wall, cpu)
    return np.load(out)[..., :3], best


exact_path = os.path.join(args.out, f"{name}_exact_{size}.npy")
if not os.path.exists(exact_path):
    subprocess.run([vri, "render", args.scene, "--method", "exact", "--tolerance", args.exact_tolerance,
                    "--width", str(size), "--height", str(size), "--threads", "2", "-o", exact_path, *motions],
                   check=True)
exact = np.load(exact_path)[..., :3]

# ---- VTK ----
cam = scene_camera(vri, args.scene, size, motions)


def vtk_render(mapper, frames=args.repeat):
    mapper.SetInputData(image)
    mapper.SetAutoAdjustSampleDistances(0)
    mapper.SetSampleDistance(min(spacing))  # 1 voxel
    img, wall, cpu = render_frames(mapper, prop, cam, size, frames)
    return img, (wall, cpu)


def fixed_point_mapper():
    mapper = vtk.vtkFixedPointVolumeRayCastMapper()
    mapper.SetNumberOfThreads(2)
    mapper.SetImageSampleDistance(1.0)
    return mapper


def gpu_mapper():
    """VTK's GPU ray caster (vtkOpenGLGPUVolumeRayCastMapper); without a GPU it
    runs on Mesa's llvmpipe, software OpenGL on the CPU (LP_NUM_THREADS=2)."""
    mapper = vtk.vtkGPUVolumeRayCastMapper()
    mapper.SetUseJittering(0)
    return mapper


def rms(img):
    return float(np.sqrt(((img - exact) ** 2).mean()))


rows = []
img, t = vtk_render(fixed_point_mapper())
np.save(os.path.join(args.out, f"{name}_vtk_fixedpoint.npy"), img)
vtk_row = ("VTK FixedPoint, sample distance 1", img, t, False)
vtk_ms, vtk_rms = t[0] * 1000, rms(img)
for method in ["preint1", "riemann"]:
    variants = [((), "skipping"), (("--termination", "0.002"), "skipping + termination 0.002")]
    if method == "preint1":  # its float path is the default; --double is its double-precision reference
        variants += [(("--double",), "skipping, double"), (("--no-skip", "--double"), "plain")]
    else:
        variants += [(("--no-skip",), "plain")]
    for extra, label in variants:
        img, t = vri_render(method, extra)
        rows.append((f"vri {method} step 1, {label}", img, t, True))
# At VTK's error: the coarsest step of each ladder below the FixedPoint mapper's RMS.
# Steps of 0.05 voxel where the views' answers lie (the error is not monotone
# in the step: sample positions move against the data), coarser beyond.
fine = lambda lo, hi: [round(lo + 0.05 * i, 2) for i in range(int(round((hi - lo) / 0.05)) + 1)]
ladders = {"preint1": fine(0.5, 1.5) + [1.75, 2, 2.5, 3, 3.5, 4], "riemann": fine(0.25, 1.5) + [1.75, 2]}
equal = {}
for method, steps in ladders.items():
    extra = ("--termination", "0.002")
    under = [step for step in steps if rms(vri_render(method, extra, repeat=1, step=step)[0]) < vtk_rms]
    equal[method] = None
    if under:
        img, t = vri_render(method, extra, step=max(under))
        rows.append((f"vri {method} step {max(under)}, termination 0.002: at VTK's error", img, t, True))
        equal[method] = (max(under), t[0] * 1000)
rows.append(vtk_row)
if not args.no_gpu:
    img, t = vtk_render(gpu_mapper())
    np.save(os.path.join(args.out, f"{name}_vtk_gpu.npy"), img)
    rows.append((f"VTK GPU ray cast ({args.gl}), sample distance 1", img, t, False))

print(f"### {name}, {size}x{size}, 2 threads\n")
print("| renderer | ms per frame (wall) | CPU ms per frame | VTK wall / this | RMS RGB vs exact | RMS 8-bit | max |")
print("|---|---|---|---|---|---|---|")
for label, img, (wall, cpu), is_vri in rows:
    d = img - exact
    d8 = (np.round(np.clip(img, 0, 1) * 255) / 255 - exact) if is_vri else d
    print(f"| {label} | {wall * 1000:.1f} | {cpu * 1000:.1f} | {vtk_ms / (wall * 1000):.2f} | "
          f"{np.sqrt((d ** 2).mean()):.5f} | {np.sqrt((d8 ** 2).mean()):.5f} | {np.abs(d).max():.3f} |")
p = equal["preint1"]
print()
if p:
    print(f"preint1 at VTK's error (step {p[0]}): {vtk_ms / p[1]:.2f}x VTK FixedPoint's frame rate "
          f"(target 2x: {'met' if vtk_ms / p[1] >= 2 else 'not met'})")
else:
    print("preint1: no step of the ladder is below VTK FixedPoint's RMS error (target 2x: not met)")
r = equal["riemann"]
print(f"riemann at VTK's error: " + (f"step {r[0]}, {vtk_ms / r[1]:.2f}x VTK" if r else "not reached on the ladder"))
