#!/usr/bin/python3
"""Writes the regular-grid fixtures in tests/data/volume/ with VTK itself
(Debian python3-vtk9), so the .vti and legacy STRUCTURED_POINTS readers are
tested on files as VTK and ParaView write them.
The volume: 11 x 7 x 5 points (x fastest), spacing (0.5, 1.25, 2), origin
(1, -2, 3), two point arrays: 'scalars' (uint8) and 'height' (float64).
The same samples are written headerless (vtk_scalars_uint8.raw,
vtk_height_float64.raw), each with its scene "volume" block beside it
(.json: dims, type, spacing, origin), so a test can load the reference through
the scene loader.
Run: /usr/bin/python3 tools/make_vtk_volume_fixtures.py  (from the repository root)."""
import json
import os

import numpy as np
import vtk
from vtk.util import numpy_support as ns

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = os.path.join(root, "tests", "data", "volume")
os.makedirs(out, exist_ok=True)

dims = (11, 7, 5)
spacing = (0.5, 1.25, 2.0)
origin = (1.0, -2.0, 3.0)
k, j, i = np.meshgrid(np.arange(dims[2]), np.arange(dims[1]), np.arange(dims[0]), indexing="ij")
scalars = ((i * 23 + j * 41 + k * 67 + i * j * k) % 256).astype(np.uint8).ravel()  # [z, y, x]: x fastest
height = (0.1 * i - 0.37 * j + 0.013 * k * k + np.sin(i * j * 0.5)).astype(np.float64).ravel()


def image(extent_start=(0, 0, 0), direction=None, active="scalars"):
    """The volume as vtkImageData; a non-zero extent start keeps the world
    origin by moving Origin back (origin = Origin + start * Spacing)."""
    img = vtk.vtkImageData()
    s = extent_start
    img.SetExtent(s[0], s[0] + dims[0] - 1, s[1], s[1] + dims[1] - 1, s[2], s[2] + dims[2] - 1)
    img.SetSpacing(*spacing)
    img.SetOrigin(*[origin[a] - s[a] * spacing[a] for a in range(3)])
    if direction is not None:
        img.SetDirectionMatrix(*direction)
    a = ns.numpy_to_vtk(scalars.copy(), deep=1)
    a.SetName("scalars")
    h = ns.numpy_to_vtk(height.copy(), deep=1)
    h.SetName("height")
    pd = img.GetPointData()
    pd.AddArray(a)
    pd.AddArray(h)
    pd.SetActiveScalars(active)
    return img


def vti(name, mode, compressed=False, header64=False, encode=True, big_endian=False, img=None):
    w = vtk.vtkXMLImageDataWriter()
    w.SetFileName(os.path.join(out, name))
    w.SetInputData(img if img is not None else image())
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary,
     "appended": w.SetDataModeToAppended}[mode]()
    w.SetEncodeAppendedData(encode)
    if compressed:
        w.SetCompressorTypeToZLib()
    else:
        w.SetCompressorTypeToNone()
    if header64:
        w.SetHeaderTypeToUInt64()
    if big_endian:
        w.SetByteOrderToBigEndian()
    w.Write()


def legacy(name, binary, version=51, active="scalars"):
    w = vtk.vtkStructuredPointsWriter()
    w.SetFileName(os.path.join(out, name))
    w.SetInputData(image(active=active))
    w.SetFileVersion(version)
    if binary:
        w.SetFileTypeToBinary()
    w.Write()


vti("ascii.vti", "ascii")
vti("base64.vti", "binary")
vti("base64_zlib.vti", "binary", compressed=True)
vti("base64_zlib_uint64.vti", "binary", compressed=True, header64=True)
vti("base64_big_endian.vti", "binary", big_endian=True)
vti("appended_raw.vti", "appended", encode=False)
vti("appended_raw_zlib.vti", "appended", compressed=True, encode=False)
vti("appended_raw_uint64_big_endian.vti", "appended", header64=True, encode=False, big_endian=True)
vti("appended_base64.vti", "appended", encode=True)
vti("appended_base64_zlib_uint64.vti", "appended", compressed=True, header64=True, encode=True)
# Extent starting at (3, -2, 1), Origin moved back: the same world origin.
vti("extent_start.vti", "appended", compressed=True, encode=False, img=image(extent_start=(3, -2, 1)))
# x and z flipped: index i lies at Origin.x - i * Spacing.x.
vti("direction_flip_xz.vti", "binary", img=image(direction=(-1, 0, 0, 0, 1, 0, 0, 0, -1)))

# Legacy: VTK writes the active uint8 scalars as COLOR_SCALARS and the other
# array as a FIELD array; with 'height' active, SCALARS height double.
legacy("legacy_ascii.vtk", False)
legacy("legacy_binary.vtk", True)
legacy("legacy42_binary.vtk", True, version=42)
legacy("legacy_height_ascii.vtk", False, active="height")
legacy("legacy_height_binary.vtk", True, active="height")

for array, type_name in ((scalars, "uint8"), (height, "float64")):
    name = "vtk_%s_%s" % ("scalars" if array is scalars else "height", type_name)
    array.astype("<" + array.dtype.str[1:]).tofile(os.path.join(out, name + ".raw"))
    with open(os.path.join(out, name + ".json"), "w") as f:
        json.dump({"file": name + ".raw", "dims": list(dims), "type": type_name,
                   "spacing": list(spacing), "origin": list(origin)}, f)
        f.write("\n")
