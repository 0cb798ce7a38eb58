"""vri: volume rendering with measurable accuracy.

Render regular-grid volumes and tetrahedral meshes with the integration
methods of the field's papers and compare them against the exact integral
(docs/PYTHON.md):

    import numpy as np, vri
    image = vri.render(np.load("ct.npy"), cmap="viridis", clim=(100, 2000))
    image.save("ct.png")            # the bytes `vri render ct.npy -o ct.png --colormap viridis --range 100,2000` writes

vri.render takes a numpy array, a vri.Volume or vri.Mesh, a volume file, a
scene file, a dict of scene keys or a vri.Scene, and returns a vri.Image: a
float32 (H, W, 4) numpy array of premultiplied RGBA (the same bytes as
`vri render -o X.npy`) that a notebook shows as a picture.
"""
import math as _math

import numpy as _np

from . import _vri
from ._vri import *  # noqa: F401,F403 - the extension's public names
from ._vri import __version__, has_vulkan  # noqa: F401

__doc__ += "\n" + (_vri.__doc__ or "")


class Image(_np.ndarray):
    """A rendered image: float32 (H, W, 4), premultiplied RGBA before any
    background (the same bytes as `vri render -o X.npy`), with the scene's
    background to composite over (`background`, r, g, b in [0, 1])."""

    def __new__(cls, array, background=(0.0, 0.0, 0.0)):
        image = _np.asarray(array, dtype=_np.float32).view(cls)
        image.background = tuple(float(c) for c in background)
        return image

    def __array_finalize__(self, obj):
        self.background = getattr(obj, "background", (0.0, 0.0, 0.0))

    def _background(self, background):
        return tuple(float(c) for c in (self.background if background is None else background))

    def composite(self, background=None):
        """(H, W, 3) float32 in [0, 1]: C + (1 - alpha) background, the scene's
        unless given - what a PNG shows before its rounding (plt.imshow takes it)."""
        a = _np.asarray(self, dtype=_np.float32)
        bg = _np.asarray(self._background(background), dtype=_np.float32)
        return _np.clip(a[..., :3] + (1 - a[..., 3:4]) * bg, 0, 1)

    def to_uint8(self, background=None):
        """(H, W, 3) uint8: the colours of `vri render -o x.png`, to the byte."""
        return _vri._rgb8(_np.asarray(self), self._background(background))

    def save(self, path, background=None):
        """Writes .npy (the floats), .png (8 bits over the background) or .exr,
        the bytes `vri render -o PATH` writes for the same image."""
        _vri._save_image(path, _np.asarray(self), self._background(background))

    def _repr_png_(self):
        if self.ndim != 3 or self.shape[2] != 4:
            return None  # a slice: numpy's own repr
        return _vri._png_bytes(_np.asarray(self), self.background)


def _is_path(x):
    import os
    return isinstance(x, (str, os.PathLike))


def _voxel_unit(volume):
    return min(volume.spacing) if isinstance(volume, Volume) else 1.0  # noqa: F405


def _range_text(clim):
    if clim is None:
        return ""
    if isinstance(clim, str):  # "data", "p1,p99" or "lo,hi", as the CLI's --range
        return clim
    lo, hi = (float(c) for c in clim)
    return f"{lo!r},{hi!r}"


def _colours(name):
    """(x, r, g, b) points of a colour map: vri's own (a name with `_r` is
    reversed), else matplotlib's (sampled at 256 entries) when it is installed."""
    reverse = name.endswith("_r")
    points = _vri._colormap(name[:-2] if reverse else name)
    if points is None:
        try:
            import matplotlib
            cmap = matplotlib.colormaps[name]
        except (ImportError, KeyError):
            raise ValueError(f"cmap: unknown colour map '{name}' (vri's: {', '.join(colormaps())}, each "  # noqa: F405
                             "also reversed with _r; any matplotlib colour map when matplotlib is installed)") from None
        return [(x, *cmap(x)[:3]) for x in _np.linspace(0, 1, 256)]
    return [(1 - x, r, g, b) for x, r, g, b in reversed(points)] if reverse else list(points)


def _volume_scene(volume, cmap, clim, opacity, camera):
    """The scene dict of a volume, as `vri render VOLUME --colormap --opacity --range` makes it."""
    import json
    shape = "" if opacity is None or not isinstance(opacity, str) else opacity
    if shape == "linear":
        shape = "ramp"
    own = cmap is None or _vri._colormap(cmap) is not None
    custom_opacity = opacity is not None and not isinstance(opacity, str)
    if own and not custom_opacity:  # the C++ scene itself: the CLI's bytes
        scene = json.loads(_vri._volume_scene_json(volume, cmap or "", shape, _range_text(clim)))
    else:
        # the C++ scene for its opacity curve and "range" (checked as --opacity and --range)
        base = json.loads(_vri._volume_scene_json(volume, "grayscale", shape or "ramp", _range_text(clim)))
        if custom_opacity:  # opacities a in [0, 1) per voxel, even over the range (VTK's unit distance)
            a = _np.clip(_np.asarray(opacity, dtype=float).ravel(), 0, 1 - 1e-6)
            if a.size < 2:
                raise ValueError("opacity: expected 'linear', 'sigmoid' or an array of at least 2 opacities")
            curve = [[float(x), -_math.log1p(-float(v)) / _voxel_unit(volume)] for x, v in zip(_np.linspace(0, 1, a.size), a)]
        else:
            curve = base["transfer_function"]["opacity"]
        xs, taus = [c[0] for c in curve], [c[1] for c in curve]
        colours = _colours(cmap or "cool_to_warm")
        cx = [c[0] for c in colours]
        grid = sorted(set(xs) | set(cx))
        points = [[x, *(float(_np.interp(x, cx, [c[k] for c in colours])) for k in (1, 2, 3)),
                   float(_np.interp(x, xs, taus))] for x in grid]
        scene = base
        scene["transfer_function"] = {"points": points, "range": base["transfer_function"].get("range", "data")}
    if camera is not None:
        scene["camera"].update(camera)
    scene["volume"] = volume
    return Scene(scene)  # noqa: F405


def _scene(scene, cmap=None, clim=None, opacity=None, spacing=None, scale=None, camera=None):
    """A vri.Scene from whatever vri.render takes."""
    look = any(v is not None for v in (cmap, clim, opacity, camera))
    if isinstance(scene, (Volume, Mesh)):  # noqa: F405
        volume = scene
    elif _is_path(scene) and _vri._is_volume_file(scene):
        volume = load_volume(scene)  # noqa: F405
    elif isinstance(scene, Scene) or isinstance(scene, dict) or _is_path(scene):  # noqa: F405
        if look or spacing is not None or scale is not None:
            raise ValueError("cmap, clim, opacity, camera, spacing and scale apply to an array or a volume; "
                             "a scene sets its own transfer_function and camera")
        if isinstance(scene, Scene):  # noqa: F405
            return scene
        return Scene(scene) if isinstance(scene, dict) else load_scene(scene)  # noqa: F405
    elif isinstance(scene, (_np.ndarray, list, tuple)) or hasattr(scene, "__array__"):
        array = _np.asarray(scene)
        if scale is not None:  # napari's (z, y, x)
            from_scale = tuple(float(s) for s in scale)[::-1]
            if spacing is not None and tuple(float(s) for s in spacing) != from_scale:
                raise ValueError(f"spacing {tuple(spacing)} (x, y, z) and scale {tuple(scale)} (z, y, x) disagree")
            spacing = from_scale
        volume = Volume.from_numpy(array, spacing=spacing) if spacing is not None else Volume.from_numpy(array)  # noqa: F405
        return _volume_scene(volume, cmap, clim, opacity, camera)
    else:
        raise TypeError("expected a vri.Scene, a dict of scene keys, a scene or volume file path, a numpy array, "
                        f"a vri.Volume or a vri.Mesh, got {type(scene).__name__}")
    if spacing is not None or scale is not None:
        raise ValueError("spacing and scale apply to an array (a volume holds its own)")
    return _volume_scene(volume, cmap, clim, opacity, camera)


def render(scene, *, cmap=None, clim=None, opacity=None, spacing=None, scale=None, camera=None, **overrides):
    """Renders `scene` - a numpy array indexed [z, y, x], a vri.Volume or vri.Mesh,
    a volume file, a scene file, a dict of scene keys or a vri.Scene - and
    returns a vri.Image (float32 (H, W, 4), premultiplied RGBA: the bytes of
    `vri render -o X.npy`).

    An array or a volume is seen as `vri render VOLUME` sees it: the transfer
    function `vri info` suggests, the camera framing its box, preint1 (fast;
    tet-raycast on meshes) - or, with
      cmap     a colour map: vri's (vri.colormaps(), `_r` reversed) or, when
               matplotlib is installed, any of matplotlib's;
      clim     (lo, hi) the scalar range it spans (default: the data's; also
               "data" or "p1,p99" for percentiles);
      opacity  "linear" (a ramp; the default) or "sigmoid", or an array of
               opacities in [0, 1) spread evenly over the range (per voxel,
               as VTK's opacity at unit distance);
      spacing  an array's voxel size (x, y, z), or scale the same in napari's
               (z, y, x) order;
      camera   a dict of camera keys over the fitted one (eye, target, up,
               fov_y, azimuth, elevation, zoom, ...).
    The other keyword arguments are the `vri render` flags by name:
    """
    made = _scene(scene, cmap, clim, opacity, spacing, scale, camera)
    return Image(_vri.render(made, **overrides), made.background)


render.__doc__ += _vri.render.__doc__.split("\n\n", 1)[-1] if _vri.render.__doc__ else ""
