#!/usr/bin/python3
"""Writes the TIFF fixtures of tests/data/volume/ (tiff_*), independently of
vri's reader: through VTK's vtkTIFFWriter (Debian python3-vtk9), tifffile
(python3-tifffile) and libtiff's tiffcp (libtiff-tools, for LZW, which
neither of the others encodes here). Each stack has a twin .npy of the same
array (numpy.save), indexed [z, y, x]: page z of the TIFF is a[z] and row y
of that page is a[z, y] (SPEC §11: page = z, row = y), so vri must read the
two into the same volume (tests/io/tiff_test.cpp).

The values: scale * p + shift of p = (7i + 13j + 29k + ijk) mod 97 on each
fixture's own grid (i = column, j = row, k = page), in the fixture's type.

VTK 9.1's vtkTIFFReader reads these files the same way (row 0 of a page at
y = 0, page 0 at z = 0; it flips y only when told SetOrientationType(4)):
checked below for the types it reads.
Run: /usr/bin/python3 tools/make_tiff_fixtures.py  (from anywhere)."""
import os
import shutil
import subprocess
import tempfile

import numpy as np
import tifffile
import vtk
from vtk.util import numpy_support as ns

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = os.path.join(root, "tests", "data", "volume")
os.makedirs(out, exist_ok=True)
os.chdir(out)


def pattern(nx, ny, nz, dtype, scale=1, shift=0):
    k, j, i = np.meshgrid(np.arange(nz), np.arange(ny), np.arange(nx), indexing="ij")
    p = (i * 7 + j * 13 + k * 29 + i * j * k) % 97  # indexed [z, y, x]
    return (p * scale + shift).astype(dtype)


def twin(name, a):
    np.save(name[: name.rindex(".")] + ".npy", a)


def vtk_image(a):
    img = vtk.vtkImageData()
    img.SetDimensions(a.shape[2], a.shape[1], a.shape[0])
    img.GetPointData().SetScalars(ns.numpy_to_vtk(np.ascontiguousarray(a).ravel(), deep=1))
    return img


def vtk_reads_as(name, a):
    """vtkTIFFReader with its defaults gives the same [z, y, x] array."""
    r = vtk.vtkTIFFReader()
    r.SetFileName(name)
    r.Update()
    img = r.GetOutput()
    nx, ny, nz = img.GetDimensions()
    got = ns.vtk_to_numpy(img.GetPointData().GetScalars()).reshape(nz, ny, nx)
    assert got.shape == a.shape and (got == a).all(), name


# ---- vtkTIFFWriter: uint8, PackBits (its default), strips ------------------
a = pattern(11, 7, 5, np.uint8)
w = vtk.vtkTIFFWriter()
w.SetFileName("tiff_u8_packbits.tif")
w.SetInputData(vtk_image(a))
w.Write()
twin("tiff_u8_packbits.tif", a)
vtk_reads_as("tiff_u8_packbits.tif", a)

# ---- tifffile + tiffcp: uint16, LZW with horizontal differencing, 2 rows a strip
a = pattern(9, 6, 4, np.uint16, 300)
with tempfile.TemporaryDirectory() as tmp:
    plain = os.path.join(tmp, "plain.tif")
    tifffile.imwrite(plain, a, photometric="minisblack", rowsperstrip=2)
    subprocess.run(["tiffcp", "-c", "lzw:2", "-r", "2", plain, "tiff_u16_lzw.tif"], check=True)
twin("tiff_u16_lzw.tif", a)
vtk_reads_as("tiff_u16_lzw.tif", a)

# ---- tifffile: float32 in 16 x 16 tiles (2 x 2 per page, the edge ones cut), Deflate
a = pattern(18, 17, 3, np.float32, 0.5, -10)
tifffile.imwrite("tiff_f32_tiled.tif", a, photometric="minisblack", tile=(16, 16), compression="zlib")
twin("tiff_f32_tiled.tif", a)

# ---- tifffile: int16, Deflate, big-endian ("MM") ----------------------------
a = pattern(7, 5, 6, np.int16, 100, -4800)
tifffile.imwrite("tiff_i16_deflate_be.tif", a.astype(">i2"), photometric="minisblack", compression="zlib",
                 byteorder=">")
twin("tiff_i16_deflate_be.tif", a)

# ---- tifffile: int8 and int32 (converted to float32), 3 rows a strip --------
a = pattern(6, 5, 3, np.int8, 1, -48)
tifffile.imwrite("tiff_i8.tif", a, photometric="minisblack", rowsperstrip=3)
twin("tiff_i8.tif", a)
a = pattern(5, 4, 3, np.int32, 100000, -4800000)
tifffile.imwrite("tiff_i32.tif", a, photometric="minisblack")
twin("tiff_i32.tif", a)

# ---- tifffile: float64 in a BigTIFF ("II+") ---------------------------------
a = pattern(5, 4, 3, np.float64, 0.25, -3)
tifffile.imwrite("tiff_f64_bigtiff.tif", a, photometric="minisblack", bigtiff=True)
twin("tiff_f64_bigtiff.tif", a)

# ---- a folder of one-page slices s1.tif .. s11.tif: natural order (s2 before s10)
a = pattern(6, 5, 11, np.uint16, 3)
shutil.rmtree("tiff_slices", ignore_errors=True)
os.makedirs("tiff_slices")
for z in range(a.shape[0]):
    tifffile.imwrite(os.path.join("tiff_slices", "s%d.tif" % (z + 1)), a[z], photometric="minisblack")
with open(os.path.join("tiff_slices", "README.txt"), "w") as f:
    f.write("Slices z = 0..10 of tiff_slices.npy, written by tools/make_tiff_fixtures.py; "
            "vri reads the *.tif files in natural order and ignores this one.\n")
np.save("tiff_slices.npy", a)

# ---- refused --------------------------------------------------------------
# RGB: three samples per pixel.
tifffile.imwrite("tiff_err_rgb.tif", pattern(4, 3, 3, np.uint8).transpose(1, 2, 0), photometric="rgb")
# Pages of different sizes, and of different types.
tifffile.imwrite("tiff_err_sizes.tif", pattern(5, 4, 2, np.uint8), photometric="minisblack")
tifffile.imwrite("tiff_err_sizes.tif", pattern(6, 4, 1, np.uint8), photometric="minisblack", append=True)
tifffile.imwrite("tiff_err_types.tif", pattern(5, 4, 2, np.uint8), photometric="minisblack")
tifffile.imwrite("tiff_err_types.tif", pattern(5, 4, 1, np.uint16), photometric="minisblack", append=True)

for name in sorted(os.listdir(".")):
    if name.startswith("tiff_"):
        size = sum(os.path.getsize(os.path.join(name, f)) for f in os.listdir(name)) if os.path.isdir(name) \
            else os.path.getsize(name)
        print("%6d %s" % (size, name))
