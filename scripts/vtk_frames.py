"""Timed off-screen frames of one VTK volume mapper, shared by the side-by-side
scripts (vtk_side_by_side.py for meshes, vtk_grid_side_by_side.py for grids)."""
import json
import subprocess
import time
import numpy as np
import vtk
from vtk.util import numpy_support as ns


def scene_camera(vri, scene_path, size, motions=()):
    """The camera vri renders `scene_path` through at size x size (SPEC §6 keys),
    after its "fit" and motions and any more `motions` (vri's flags, such as
    --azimuth 90): `vri camera`."""
    out = subprocess.run([vri, "camera", scene_path, "--width", str(size), "--height", str(size), *motions],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def render_frames(mapper, prop, cam, size, frames):
    """Renders `frames` frames of `mapper` (its input set) with `prop` through the
    scene camera `cam` (SPEC §6 keys) at size x size after a first, untimed one
    (tables, sorting, min/max volumes). Returns the RGB image on black as floats
    in [0, 1], row 0 at the top, and the mean wall and CPU seconds per frame."""
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtk.vtkRenderer()
    ren.SetBackground(0, 0, 0)
    ren.AddVolume(volume)
    c = ren.GetActiveCamera()
    c.SetPosition(*cam["eye"]); c.SetFocalPoint(*cam["target"]); c.SetViewUp(*cam.get("up", [0, 1, 0]))
    c.SetViewAngle(cam.get("fov_y", 30))
    ren.ResetCameraClippingRange()
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetSize(size, size)
    win.AddRenderer(ren)
    win.Render()
    t0, c0 = time.perf_counter(), time.process_time()
    for _ in range(frames):
        win.Modified(); volume.Modified()
        win.Render()
        win.WaitForCompletion()  # an OpenGL mapper's frame is done only when the GL queue is
    wall, cpu = (time.perf_counter() - t0) / frames, (time.process_time() - c0) / frames
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    img = ns.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(size, size, 3)
    return img[::-1].astype(np.float32) / 255.0, wall, cpu
