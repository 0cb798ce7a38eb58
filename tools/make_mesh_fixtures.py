#!/usr/bin/python3
"""Writes the mesh-reader fixtures in tests/data/mesh/ with VTK itself (Debian
python3-vtk9), so the readers are tested on files as VTK and ParaView write them.
Input: data/tetra_mesh_small_ascii.vtk (55 points, 160 tetrahedra, int scalars).
Two point arrays are written: 'scalars' (the file's) and 'height' (= z).
Run: /usr/bin/python3 tools/make_mesh_fixtures.py  (from the repository root)."""
import os
import vtk
from vtk.util import numpy_support as ns

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = os.path.join(root, "tests", "data", "mesh")
os.makedirs(out, exist_ok=True)

r = vtk.vtkUnstructuredGridReader()
r.SetFileName(os.path.join(root, "data", "tetra_mesh_small_ascii.vtk"))
r.Update()
grid = r.GetOutput()
pts = ns.vtk_to_numpy(grid.GetPoints().GetData())
height = ns.numpy_to_vtk(pts[:, 2].astype("float64").copy(), deep=1)
height.SetName("height")
grid.GetPointData().AddArray(height)

def legacy(name, version, binary):
    w = vtk.vtkUnstructuredGridWriter()
    w.SetFileName(os.path.join(out, name))
    w.SetInputData(grid)
    w.SetFileVersion(version)
    if binary:
        w.SetFileTypeToBinary()
    w.Write()

def xml(name, mode, compressed=False, header64=False, encode=True):
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(os.path.join(out, name))
    w.SetInputData(grid)
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary,
     "appended": w.SetDataModeToAppended}[mode]()
    w.SetEncodeAppendedData(encode)
    if compressed:
        w.SetCompressorTypeToZLib()
    else:
        w.SetCompressorTypeToNone()
    if header64:
        w.SetHeaderTypeToUInt64()
    w.Write()

legacy("legacy42_binary.vtk", 42, True)
legacy("legacy51_binary.vtk", 51, True)
legacy("legacy51_ascii.vtk", 51, False)
xml("ascii.vtu", "ascii")
xml("base64.vtu", "binary")
xml("base64_zlib_uint64.vtu", "binary", compressed=True, header64=True)
xml("appended_raw.vtu", "appended", encode=False)
xml("appended_raw_zlib.vtu", "appended", compressed=True, encode=False)
xml("appended_base64_zlib_uint64.vtu", "appended", compressed=True, header64=True, encode=True)
