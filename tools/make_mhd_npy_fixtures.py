#!/usr/bin/python3
"""Writes the MetaImage, NumPy and NRRD fixtures of tests/data/volume/
(mhd_*, npy_*, nrrd_*), independently of vri's readers: MetaImage through
VTK's vtkMetaImageWriter (Debian python3-vtk9; ITK MetaIO) and, for what VTK
does not write (big-endian data, axis flips, HeaderSize, 64-bit types), hand
formatted headers over numpy bytes; .npy through numpy.save and
numpy.lib.format.write_array (NEP 1); NRRD headers by hand (teem's format
spec) over numpy bytes and Python's gzip.

The volume: 11 x 7 x 5 points, x fastest; its pattern
p = (7i + 13j + 29k + ijk) mod 97 is written headerless as
mhd_npy_nrrd_pattern_uint8.raw. Each fixture holds scale * p + shift in its
own type (the tables in tests/io/metaimage_test.cpp, npy_volume_test.cpp
and nrrd_test.cpp say which), MetaImage
and NRRD with spacing (0.5, 1.25, 2) and origin (-1, 2, 3.5) -- the position
of the low corner, also in the flipped files, whose headers put their first
sample at the other end of a flipped axis.
Run: /usr/bin/python3 tools/make_mhd_npy_fixtures.py  (from anywhere)."""
import gzip
import os
import zlib

import numpy as np
import vtk
from vtk.util import numpy_support as ns

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = os.path.join(root, "tests", "data", "volume")
os.makedirs(out, exist_ok=True)
os.chdir(out)  # so that .mhd headers name their data files without a folder

nx, ny, nz = 11, 7, 5
spacing = (0.5, 1.25, 2.0)
origin = (-1.0, 2.0, 3.5)
k, j, i = np.meshgrid(np.arange(nz), np.arange(ny), np.arange(nx), indexing="ij")
p = (i * 7 + j * 13 + k * 29 + i * j * k) % 97  # indexed [z, y, x]
p.astype(np.uint8).tofile("mhd_npy_nrrd_pattern_uint8.raw")


def values(dtype, scale=1, shift=0):
    return (p * scale + shift).astype(dtype)


# ---- MetaImage through VTK -------------------------------------------------
def vtk_metaimage(name, data, compress):
    img = vtk.vtkImageData()
    img.SetDimensions(nx, ny, nz)
    img.SetSpacing(*spacing)
    img.SetOrigin(*origin)
    img.GetPointData().SetScalars(ns.numpy_to_vtk(np.ascontiguousarray(data).ravel(), deep=1))
    w = vtk.vtkMetaImageWriter()
    w.SetFileName(name)
    if name.endswith(".mhd"):
        w.SetRAWFileName(name[:-4] + (".zraw" if compress else ".raw"))
    w.SetCompression(compress)
    w.SetInputData(img)
    w.Write()


vtk_metaimage("mhd_uchar.mhd", values(np.uint8), False)
vtk_metaimage("mhd_short_zlib.mhd", values(np.int16, 100, -4800), True)
vtk_metaimage("mhd_float.mha", values(np.float32, 0.5, -10), False)
vtk_metaimage("mhd_ushort_zlib.mha", values(np.uint16, 300), True)
vtk_metaimage("mhd_uchar_zlib.mha", values(np.uint8), True)
vtk_metaimage("mhd_double_zlib.mha", values(np.float64, 0.25, -3), True)
vtk_metaimage("mhd_char.mha", values(np.int8, 1, -48), False)
vtk_metaimage("mhd_int.mha", values(np.int32, 100000, -4800000), False)
vtk_metaimage("mhd_uint_zlib.mha", values(np.uint32, 100000), True)


# ---- MetaImage by hand ----------------------------------------------------
def header(element_type, extra, data_file="LOCAL", offset=origin, spacing_key="ElementSpacing"):
    lines = ["ObjectType = Image", "NDims = 3", "BinaryData = True"] + extra + [
        "Offset = %g %g %g" % offset,
        "CenterOfRotation = 0 0 0",
        "AnatomicalOrientation = RAI",
        "%s = %g %g %g" % ((spacing_key,) + spacing),
        "DimSize = %d %d %d" % (nx, ny, nz),
        "ElementType = " + element_type,
        "ElementDataFile = " + data_file]
    return ("\n".join(lines) + "\n").encode()


def write(name, *parts):
    with open(name, "wb") as f:
        for part in parts:
            f.write(part)


# Big-endian shorts.
write("mhd_msb_short.mha", header("MET_SHORT", ["BinaryDataByteOrderMSB = True"]),
      values(">i2", 100, -4800).tobytes())
# x and z stored backwards: the first sample sits at the high corner.
flipped = np.ascontiguousarray(values(np.uint8)[::-1, :, ::-1])
write("mhd_flip_xz.mha",
      header("MET_UCHAR", ["TransformMatrix = -1 0 0 0 1 0 0 0 -1", "ElementByteOrderMSB = False"],
             offset=(origin[0] + (nx - 1) * spacing[0], origin[1], origin[2] + (nz - 1) * spacing[2])),
      flipped.tobytes())
# A data file with 16 bytes before the samples: HeaderSize 16, and -1 (the
# samples are the file's last bytes); ElementSize, Origin and Position keys.
write("mhd_headersize.dat", b"sixteen  bytes\r\n", values("<u2", 300).tobytes())
write("mhd_headersize.mhd", header("MET_USHORT", ["HeaderSize = 16"], "mhd_headersize.dat",
                                   spacing_key="ElementSize").replace(b"Offset", b"Origin"))
write("mhd_headersize_end.mhd", header("MET_USHORT", ["HeaderSize = -1"], "mhd_headersize.dat")
      .replace(b"Offset", b"Position"))
# 64-bit and MetaIO's 4-byte MET_ULONG.
write("mhd_long_long_msb.mha", header("MET_LONG_LONG", ["ElementByteOrderMSB = True"]),
      values(">i8", 2 ** 33, -48 * 2 ** 33).tobytes())
write("mhd_ulong.mha", header("MET_ULONG", []), values("<u4", 100000).tobytes())
packed = zlib.compress(values("<u8", 2 ** 40).tobytes())
write("mhd_ulong_long_zlib.mha",
      header("MET_ULONG_LONG", ["CompressedData = True", "CompressedDataSize = %d" % len(packed)]), packed)

# ---- NumPy -----------------------------------------------------------------
np.save("npy_u1.npy", values(np.uint8))
np.save("npy_u1_fortran.npy", np.asfortranarray(values(np.uint8)))
np.save("npy_b1.npy", (p % 2) == 1)
np.save("npy_i1.npy", values(np.int8, 1, -48))
np.save("npy_u2_le.npy", values("<u2", 300))
np.save("npy_u2_be.npy", values(">u2", 300))
np.save("npy_i2_le_fortran.npy", np.asfortranarray(values("<i2", 100, -4800)))
np.save("npy_i2_be.npy", values(">i2", 100, -4800))
np.save("npy_i4_le.npy", values("<i4", 100000, -4800000))
np.save("npy_i4_be.npy", values(">i4", 100000, -4800000))
np.save("npy_u4_be.npy", values(">u4", 100000))
np.save("npy_i8_be.npy", values(">i8", 2 ** 33, -48 * 2 ** 33))
np.save("npy_u8_le.npy", values("<u8", 2 ** 40))
np.save("npy_f2_le.npy", values("<f2", 0.5, -10))
np.save("npy_f4_le.npy", values("<f4", 0.5, -10))
np.save("npy_f4_be_fortran.npy", np.asfortranarray(values(">f4", 0.5, -10)))
np.save("npy_f8_le.npy", values("<f8", 0.25, -3))
np.save("npy_f8_be.npy", values(">f8", 0.25, -3))
for version, dtype in (((2, 0), "<f4"), ((3, 0), ">u2")):
    with open("npy_v%d.npy" % version[0], "wb") as f:
        np.lib.format.write_array(f, values(dtype, 0.5 if dtype == "<f4" else 300, -10 if dtype == "<f4" else 0),
                                  version=version)
# Refused: not numeric, or not 3-D.
small = np.arange(8).reshape(2, 2, 2)
np.save("npy_err_complex.npy", small.astype(np.complex64))
np.save("npy_err_structured.npy", np.zeros((2, 2, 2), dtype=[("a", "<f4"), ("b", "<i2")]))
np.save("npy_err_object.npy", small.astype(object), allow_pickle=True)
np.save("npy_err_string.npy", small.astype("<U2"))
np.save("npy_err_2d.npy", values(np.float32)[0])
np.save("npy_err_4d.npy", values(np.float32).reshape(1, nz, ny, nx))


# ---- NRRD with space directions ---------------------------------------------
def nrrd(name, type_, endian, encoding, directions, space_origin, payload):
    text = ("NRRD0004\n# written by tools/make_mhd_npy_fixtures.py\ntype: %s\ndimension: 3\nsizes: %d %d %d\n"
            "space: right-anterior-superior\nspace directions: %s\nspace origin: (%g,%g,%g)\n"
            "endian: %s\nencoding: %s\n\n" % ((type_, nx, ny, nz, directions) + space_origin + (endian, encoding)))
    write(name, text.encode(), payload)


# x runs backwards: file sample i sits at x = 4 - 0.5 i.
nrrd("nrrd_neg_x.nrrd", "ushort", "little", "raw", "(-0.5,0,0) (0,1.25,0) (0,0,2)", (4, 2, 3.5),
     np.ascontiguousarray(values("<u2", 300)[:, :, ::-1]).tobytes())
# y and z run backwards; big-endian floats, gzip.
nrrd("nrrd_neg_yz_gzip.nrrd", "float", "big", "gzip", "(0.5,0,0) (0,-1.25,0) (0,0,-2)", (-1, 9.5, 11.5),
     gzip.compress(np.ascontiguousarray(values(">f4", 0.5, -10)[::-1, ::-1, :]).tobytes(), mtime=0))
# A rotated grid: refused.
nrrd("nrrd_oblique.nrrd", "uchar", "little", "raw", "(0.5,0.5,0) (-0.5,0.5,0) (0,0,2)", (0, 0, 0),
     values(np.uint8).tobytes())
