"""vri: volume rendering with measurable accuracy (type stubs for editors)."""
import os
from typing import Any, Dict, List, Optional, Sequence, Tuple, TypedDict, Union

import numpy as np
import numpy.typing as npt

__version__: str

SceneLike = Union["Scene", Dict[str, Any], str, os.PathLike, "Volume", "Mesh", npt.ArrayLike]

class Image(np.ndarray):
    """float32 (H, W, 4), premultiplied RGBA (the bytes of `vri render -o X.npy`), with the scene's background."""
    background: Tuple[float, float, float]
    def composite(self, background: Optional[Sequence[float]] = None) -> npt.NDArray[np.float32]:
        """(H, W, 3) in [0, 1]: C + (1 - alpha) background (the scene's by default)."""
    def to_uint8(self, background: Optional[Sequence[float]] = None) -> npt.NDArray[np.uint8]:
        """(H, W, 3): the colours of `vri render -o x.png`."""
    def save(self, path: Union[str, os.PathLike], background: Optional[Sequence[float]] = None) -> None:
        """.npy, .png or .exr: the bytes `vri render -o PATH` writes."""
    def _repr_png_(self) -> Optional[bytes]: ...

def colormaps() -> List[str]:
    """vri's named colour maps."""
TransferFunctionLike = Union[Dict[str, Any], str, os.PathLike, "Scene"]

class Volume:
    """A scalar field on a regular grid (SPEC §1)."""
    @staticmethod
    def from_numpy(array: npt.ArrayLike, *, spacing: Sequence[float] = (1.0, 1.0, 1.0),
                   origin: Sequence[float] = (0.0, 0.0, 0.0)) -> "Volume":
        """A volume from a 3-D numeric array indexed [z, y, x]; spacing and origin are (x, y, z).
        uint8, uint16, int16 and float32 arrays in C order are viewed without a copy."""
    @property
    def dims(self) -> Tuple[int, int, int]: """(nx, ny, nz)"""
    @property
    def shape(self) -> Tuple[int, int, int]: """(nz, ny, nx)"""
    @property
    def spacing(self) -> Tuple[float, float, float]: ...
    @property
    def origin(self) -> Tuple[float, float, float]: ...
    @property
    def dtype(self) -> str: """uint8, uint16, int16 or float32"""
    @property
    def range(self) -> Tuple[float, float]: ...
    def to_numpy(self) -> npt.NDArray[Any]:
        """The samples, read-only, indexed [z, y, x] (no copy)."""

class Mesh:
    """A tetrahedral mesh with one scalar per point (SPEC §2)."""
    @staticmethod
    def from_numpy(points: npt.ArrayLike, cells: npt.ArrayLike, scalars: npt.ArrayLike) -> "Mesh":
        """points (N, 3), cells (M, 4) point indices, scalars (N,)."""
    @property
    def n_points(self) -> int: ...
    @property
    def n_cells(self) -> int: ...
    @property
    def dropped(self) -> int: ...
    @property
    def range(self) -> Tuple[float, float]: ...

class Scene:
    """A scene (SPEC §8): volume, transfer function, camera, lighting, background, method."""
    def __init__(self, scene: Dict[str, Any], *, base_dir: Optional[Union[str, os.PathLike]] = None) -> None:
        """A scene from a dict of SPEC §8 keys; its "volume" may be a Volume or a Mesh."""
    @property
    def kind(self) -> str: """'grid' or 'mesh'"""
    @property
    def volume(self) -> Union[Volume, Mesh]: ...
    @property
    def method(self) -> str: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def background(self) -> Tuple[float, float, float]: ...
    @property
    def transfer_function(self) -> List[Tuple[float, float, float, float, float]]: ...

def load_scene(path: Union[str, os.PathLike]) -> Scene:
    """Loads a scene file (SPEC §8)."""

def load_volume(path: Union[str, os.PathLike]) -> Union[Volume, Mesh]:
    """A volume file of any format `vri info` reads: a grid (Volume) or tetrahedra (Mesh)."""

def render(scene: SceneLike, *, cmap: Optional[str] = None,
           clim: Optional[Union[Tuple[float, float], str]] = None,
           opacity: Optional[Union[str, npt.ArrayLike]] = None,
           spacing: Optional[Sequence[float]] = None, scale: Optional[Sequence[float]] = None,
           camera: Optional[Dict[str, Any]] = None, method: Optional[str] = None, step: Optional[float] = None,
           tolerance: Optional[float] = None, table_size: Optional[int] = None,
           iterations: Optional[int] = None, width: Optional[int] = None, height: Optional[int] = None,
           threads: int = 0, termination: Optional[float] = None, skip_empty: Optional[bool] = None,
           double: Optional[bool] = None, h0: Optional[float] = None, hmin: Optional[float] = None,
           hmax: Optional[float] = None, strategy: Optional[str] = None, max_samples: Optional[float] = None,
           max_work: Optional[float] = None, jitter: Optional[int] = None, fit: Optional[bool] = None,
           azimuth: Optional[float] = None, elevation: Optional[float] = None, roll: Optional[float] = None,
           zoom: Optional[float] = None, backend: Optional[str] = None,
           clip: Optional[dict] = None) -> Image:
    """float32 (H, W, 4), premultiplied RGBA: the same bytes as `vri render -o OUT.npy`.
    An array, a Volume, a Mesh or a volume file is seen as `vri render VOLUME` sees it, with
    cmap (vri's or matplotlib's), clim (lo, hi), opacity ('linear', 'sigmoid' or an array),
    spacing (x, y, z) or scale (z, y, x), camera (keys over the fitted camera).
    `clip`: {"planes": [[nx, ny, nz, d], ...], "box": [[x0, y0, z0], [x1, y1, z1]]}
    in world units, replacing the scene's "clip" (SPEC §12; docs/CLIPPING.md)."""

has_vulkan: bool
"""Whether this build has the GPU backend (backend="vulkan")."""

class MethodInfo(TypedDict):
    name: str
    paper: str
    grid: bool
    mesh: bool
    gpu_grid: bool
    gpu_mesh: bool
    distributed: bool
    termination: bool
    jitter: bool
    parameters: List[str]

class MethodParameter(TypedDict):
    key: str
    flag: str
    expects: str

def methods() -> List[MethodInfo]:
    """The integration methods (SPEC §9) and what each supports (vri/methods.hpp)."""

def method_parameters() -> List[MethodParameter]:
    """The numeric method parameters and the one rule each is checked by (vri/methods.hpp)."""

def devices() -> List[str]:
    """The Vulkan devices backend='vulkan' can use (`vri devices`)."""

def error_estimate(scene: SceneLike, *, method: Optional[str] = None, tolerance: Optional[float] = None,
                   width: Optional[int] = None, height: Optional[int] = None, threads: int = 0,
                   h0: Optional[float] = None, hmin: Optional[float] = None, hmax: Optional[float] = None,
                   strategy: Optional[str] = None, max_samples: Optional[float] = None,
                   max_work: Optional[float] = None) -> npt.NDArray[np.float32]:
    """The per-pixel error estimate of method 'adaptive', float32 (H, W, 4)."""

class Trace(TypedDict):
    outer: npt.NDArray[np.bool_]
    t: npt.NDArray[np.float64]
    h: npt.NDArray[np.float64]
    alpha: npt.NDArray[np.float64]

def trace(scene: SceneLike, pixel: Tuple[int, int], *, method: Optional[str] = None,
          tolerance: Optional[float] = None, width: Optional[int] = None, height: Optional[int] = None,
          threads: int = 0, h0: Optional[float] = None, hmin: Optional[float] = None,
          hmax: Optional[float] = None, strategy: Optional[str] = None, max_samples: Optional[float] = None,
          max_work: Optional[float] = None) -> Trace:
    """The steps method 'adaptive' accepts along one pixel's ray."""

def table(tf: TransferFunctionLike, *, size: int = 256, order: int = 1, length: float = 1.0,
          lengths: Optional[int] = None, max_length: Optional[float] = None, builder: Optional[str] = None,
          iterations: Optional[int] = None, steps: int = 0,
          accumulation: str = "fp32", backend: str = "cpu") -> npt.NDArray[np.float32]:
    """A pre-integration table as `vri table` writes it (SPEC §10)."""

class ChannelDifference:
    @property
    def share_over(self) -> float: ...
    @property
    def rms(self) -> float: ...
    @property
    def max(self) -> float: ...
    @property
    def nan(self) -> int: ...

def compare(a: npt.ArrayLike, b: npt.ArrayLike, tolerance: float = ...) -> List[ChannelDifference]:
    """Per channel: share of pixels over tolerance, RMS and maximum difference (`vri compare`)."""

class RaySignal(TypedDict):
    t: npt.NDArray[np.float64]
    signal: npt.NDArray[np.float64]
    order0: npt.NDArray[np.float64]
    order1: npt.NDArray[np.float64]
    order2: npt.NDArray[np.float64]
    is_sample: npt.NDArray[np.bool_]
    xi: Tuple[float, float, float]
    samples: int

def ray(scene: SceneLike, pixel: Tuple[int, int], *, step: Optional[float] = None) -> RaySignal:
    """The scalar signal along one pixel's ray and its order 0/1/2 approximations (`vri ray`)."""

def set_max_memory(size: Union[int, str]) -> None:
    """The memory budget for volumes, meshes and tables: bytes or '512M', '4G'; 0 restores the default."""

def max_memory() -> int: ...
