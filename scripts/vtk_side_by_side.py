#!/usr/bin/python3
"""VTK's unstructured-grid volume mappers beside vri's mesh methods, on the same
mesh, transfer function and camera: time per frame and error against vri's
`exact` (RGB over black; VTK's framebuffer alpha is not comparable).

Needs Debian's python3-vtk9 and, without a display, Xvfb:
  xvfb-run -a -s "-screen 0 1024x768x24" /usr/bin/python3 scripts/vtk_side_by_side.py \
      scenes/blunt_fin.json 256 /tmp/side
It renders vri's methods with ./build/vri (2 threads) and writes a Markdown
table (docs/PERFORMANCE.md, "Tetrahedral meshes").

Transfer function: vri's (s, r, g, b, tau) points become VTK colour points
(r, g, b) and scalar-opacity points a = 1 - exp(-tau) with
ScalarOpacityUnitDistance 1, so a slab of unit length has the same opacity in
both; VTK's mappers integrate colour and opacity in their own ways, so part of
their error is the model, not only the numerics.
"""
import json, os, subprocess, sys, time
import numpy as np
import vtk
from vtk_frames import render_frames, scene_camera

scene_path, size, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
os.makedirs(out, exist_ok=True)
scene = json.load(open(scene_path))
base = os.path.dirname(os.path.abspath(scene_path))
vri = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "vri")

def vri_render(method, extra=()):
    path = os.path.join(out, f"vri_{method}.npy")
    t0 = time.perf_counter()
    subprocess.run([vri, "render", scene_path, "--method", method, "--width", str(size), "--height", str(size),
                    "--threads", "2", "-o", path, *extra], check=True, capture_output=True)
    r = subprocess.run([vri, "render", scene_path, "--method", method, "--width", str(size), "--height", str(size),
                        "--threads", "2", "-o", path, *extra], check=True, capture_output=True, text=True)
    # vri prints the render time (without loading the mesh or building tables) on stderr.
    seconds = float(r.stderr.split(" in ")[1].split(" s")[0])
    return np.load(path), seconds

reader = vtk.vtkUnstructuredGridReader()
reader.SetFileName(os.path.join(base, scene["volume"]["file"]))
reader.ReadAllScalarsOn()
reader.SetScalarsName(scene["volume"].get("scalars", ""))
reader.Update()
grid = reader.GetOutput()
grid.GetPointData().SetActiveScalars(scene["volume"].get("scalars", grid.GetPointData().GetArrayName(0)))

color = vtk.vtkColorTransferFunction()
opacity = vtk.vtkPiecewiseFunction()
for s, r, g, b, tau in scene["transfer_function"]["points"]:
    color.AddRGBPoint(s, r, g, b)
    opacity.AddPoint(s, 1 - np.exp(-tau))
prop = vtk.vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(1.0)
prop.SetInterpolationTypeToLinear()
prop.ShadeOff()

cam = scene_camera(vri, scene_path, size)
def vtk_render(make_mapper, frames=2):
    mapper = make_mapper()
    mapper.SetInputData(grid)
    img, wall, _ = render_frames(mapper, prop, cam, size, frames)
    return img, wall

def raycast():
    m = vtk.vtkUnstructuredGridVolumeRayCastMapper()
    m.SetRayIntegrator(vtk.vtkUnstructuredGridPreIntegration())
    return m
def zsweep():
    m = vtk.vtkUnstructuredGridVolumeZSweepMapper()
    m.SetRayIntegrator(vtk.vtkUnstructuredGridPreIntegration())
    return m

exact, t_exact = vri_render("exact")
rows = [("vri exact (reference)", exact[..., :3], t_exact)]
for method in ["tet-raycast", "pt", "pt-cylindrical"]:
    img, t = vri_render(method)
    rows.append((f"vri {method}", img[..., :3], t))
for name, make in [("VTK ProjectedTetrahedra", vtk.vtkProjectedTetrahedraMapper),
                   ("VTK RayCast + PreIntegration", raycast), ("VTK ZSweep + PreIntegration", zsweep)]:
    try:
        img, t = vtk_render(make)
        np.save(os.path.join(out, name.split()[1] + ".npy"), img)
        rows.append((name, img, t))
    except Exception as e:  # a mapper that cannot run here is reported, not hidden
        rows.append((f"{name} (failed: {e})", None, float("nan")))

print(f"| renderer, {size}x{size} | time per frame | max RGB error vs exact | RMS |")
print("|---|---|---|---|")
for name, img, t in rows:
    if img is None:
        print(f"| {name} | - | - | - |"); continue
    d = np.abs(img - exact[..., :3])
    print(f"| {name} | {t * 1000:.0f} ms | {d.max():.3f} | {np.sqrt((d ** 2).mean()):.4f} |")
