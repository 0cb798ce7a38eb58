#!/usr/bin/python3
"""Writes vri's named colour maps and the fixtures that test them (issue 20).

    /usr/bin/python3 tools/make_colormaps.py      (from the repository root)

Outputs:
  src/transfer/colormap_data.cpp          the named maps as RGB control points over [0, 1]
  tests/data/tf/colormap_reference.json   each map's dense reference, which the points must
                                          reproduce within 1/512 (tests/transfer/colormap_test.cpp)
  tests/data/tf/paraview_presets.json     ParaView colour-map presets in every colour space vri
                                          imports, with midpoint/sharpness opacity
  tests/data/tf/paraview_single.json      a file holding one preset ("name" may be left out)
  tests/data/tf/paraview_expected.json    VTK's own tables of those presets
                                          (vtkColorTransferFunction, vtkPiecewiseFunction)

Sources of the named maps (Debian's packages, nothing downloaded):
  viridis, magma, inferno, plasma, cividis: matplotlib.colormaps[name], its 256 entries,
      entry i at x = i/255 (as ParaView's "(matplotlib)" presets place them);
  cool_to_warm: VTK's vtkColorTransferFunction, SetColorSpaceToDiverging, 0 -> (0.231373,
      0.298039, 0.752941), 1 -> (0.705882, 0.0156863, 0.14902) (ParaView's "Cool to Warm"),
      sampled at 1025 points;
  rainbow_uniform: the "RGBPoints" of ParaView's preset "Rainbow Uniform" (ColorSpace RGB),
      Remoting/Views/ColorMaps.json of Kitware/ParaView (commit 004d7c1c17ae), copied below;
  grayscale: (0, 0, 0) -> (1, 1, 1).
Each dense reference is reduced to the fewest of its own points whose piecewise-linear
interpolation stays within 1/512 of every reference point in r, g and b (a shortest path over
the points: exact for the matplotlib and ParaView maps, which are piecewise linear between
their points; for cool_to_warm between 1025 samples of a smooth curve).

The generator also carries its own implementation of VTK's colour spaces (sRGB <-> XYZ <->
CIE Lab, Msh, HSV) and of vtkPiecewiseFunction's midpoint/sharpness curve, the formulas
src/transfer/paraview_colormap.cpp implements, and checks them against VTK before writing.
"""
import json
import math
import os
import sys

import matplotlib
import numpy as np
import vtk

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOL = 1.0 / 512

# ParaView's "Rainbow Uniform" (Creator: Colin Ware; ColorSpace RGB): its RGBPoints, x r g b.
RAINBOW_UNIFORM = [
    0.0, 0.02, 0.3813, 0.9981,
    0.023809523809523808, 0.02000006, 0.424267768, 0.96906969,
    0.047619047619047616, 0.02, 0.467233763, 0.940033043,
    0.07142857142857142, 0.02, 0.5102, 0.911,
    0.09523809523809523, 0.02000006, 0.546401494, 0.872669438,
    0.11904761904761904, 0.02, 0.582600362, 0.83433295,
    0.14285714285714285, 0.02, 0.6188, 0.796,
    0.16666666666666666, 0.02000006, 0.652535156, 0.749802434,
    0.19047619047619047, 0.02, 0.686267004, 0.703599538,
    0.21428571428571427, 0.02, 0.72, 0.6574,
    0.23809523809523808, 0.02000006, 0.757035456, 0.603735359,
    0.2619047619047619, 0.02, 0.794067037, 0.55006613,
    0.2857142857142857, 0.02, 0.8311, 0.4964,
    0.30952380952380953, 0.021354336738172372, 0.8645368555261631, 0.4285579460761159,
    0.3333333333333333, 0.023312914349117714, 0.897999359924484, 0.36073871343115577,
    0.35714285714285715, 0.015976108242848862, 0.9310479513349017, 0.2925631815088092,
    0.38095238095238093, 0.27421074700988196, 0.952562960995083, 0.15356836602739213,
    0.40476190476190477, 0.4933546281681699, 0.9619038625309482, 0.11119493614749336,
    0.42857142857142855, 0.6439, 0.9773, 0.0469,
    0.4523809523809524, 0.762401813, 0.984669591, 0.034600153,
    0.47619047619047616, 0.880901185, 0.992033407, 0.022299877,
    0.5, 0.9995285432627147, 0.9995193706781492, 0.0134884641450013,
    0.5238095238095238, 0.999402998, 0.955036376, 0.079066628,
    0.5476190476190477, 0.9994, 0.910666223, 0.148134024,
    0.5714285714285714, 0.9994, 0.8663, 0.2172,
    0.5952380952380952, 0.999269665, 0.818035981, 0.217200652,
    0.6190476190476191, 0.999133332, 0.769766184, 0.2172,
    0.6428571428571429, 0.999, 0.7215, 0.2172,
    0.6666666666666666, 0.99913633, 0.673435546, 0.217200652,
    0.6904761904761905, 0.999266668, 0.625366186, 0.2172,
    0.7142857142857143, 0.9994, 0.5773, 0.2172,
    0.7380952380952381, 0.999402998, 0.521068455, 0.217200652,
    0.7619047619047619, 0.9994, 0.464832771, 0.2172,
    0.7857142857142857, 0.9994, 0.4086, 0.2172,
    0.8095238095238095, 0.9947599917687346, 0.33177297300202935, 0.2112309638520206,
    0.8333333333333334, 0.9867129505479589, 0.2595183410914934, 0.19012239549291934,
    0.8571428571428571, 0.9912458875646419, 0.14799417507952672, 0.21078892136920357,
    0.8809523809523809, 0.949903037, 0.116867171, 0.252900603,
    0.9047619047619048, 0.903199533, 0.078432949, 0.291800389,
    0.9285714285714286, 0.8565, 0.04, 0.3307,
    0.9523809523809523, 0.798902627, 0.04333345, 0.358434298,
    0.9761904761904762, 0.741299424, 0.0466667, 0.386166944,
    1.0, 0.6837, 0.05, 0.4139,
]
COOL = (0.231373, 0.298039, 0.752941)
WARM = (0.705882, 0.0156863, 0.14902)


# --- the dense references -------------------------------------------------------------

def matplotlib_map(name):
    lut = matplotlib.colormaps[name](np.arange(256))[:, :3]  # integer input: the entries themselves
    return np.arange(256) / 255.0, lut.astype(np.float64)


def cool_to_warm():
    f = vtk.vtkColorTransferFunction()
    f.SetColorSpaceToDiverging()
    f.AddRGBPoint(0.0, *COOL)
    f.AddRGBPoint(1.0, *WARM)
    n = 1025
    table = np.array([f.GetColor(x) for x in np.linspace(0.0, 1.0, n)])
    return np.linspace(0.0, 1.0, n), table


def rainbow_uniform():
    a = np.array(RAINBOW_UNIFORM).reshape(-1, 4)
    return a[:, 0], a[:, 1:]


# --- reduction to the fewest linear pieces --------------------------------------------

def reduce_points(x, v, tol=TOL):
    """Indices of the fewest points of (x, v) whose linear interpolation is within tol
    (strictly) of every point, in each channel; the first and last are always kept."""
    n = len(x)
    best = np.full(n, np.inf)
    prev = np.full(n, -1)
    best[0] = 0
    for i in range(n - 1):
        if not np.isfinite(best[i]):
            continue
        misses = 0
        for j in range(i + 1, n):
            if j > i + 1:
                t = (x[i + 1:j] - x[i]) / (x[j] - x[i])
                err = np.abs(v[i] + t[:, None] * (v[j] - v[i]) - v[i + 1:j]).max()
                if err >= tol:
                    misses += 1
                    if misses > 8 or err > 16 * tol:
                        break
                    continue
            if best[i] + 1 < best[j]:
                best[j] = best[i] + 1
                prev[j] = i
    keep = [n - 1]
    while keep[-1] != 0:
        keep.append(int(prev[keep[-1]]))
    return keep[::-1]


def max_error(x, v, kx, kv):
    return max(np.abs(np.interp(x, kx, kv[:, c]) - v[:, c]).max() for c in range(3))


# --- VTK's colour spaces, reimplemented (the C++ follows these) ------------------------

def rgb_to_lab(c):
    c = np.asarray(c, dtype=float)
    c = np.where(c > 0.04045, ((c + 0.055) / 1.055) ** 2.4, c / 12.92)
    r, g, b = c
    xyz = np.array([r * 0.4124 + g * 0.3576 + b * 0.1805, r * 0.2126 + g * 0.7152 + b * 0.0722,
                    r * 0.0193 + g * 0.1192 + b * 0.9505]) / np.array([0.9505, 1.0, 1.089])
    v = np.where(xyz > 0.008856, np.cbrt(xyz), 7.787 * xyz + 16 / 116)
    return np.array([116 * v[1] - 16, 500 * (v[0] - v[1]), 200 * (v[1] - v[2])])


def lab_to_rgb(lab):
    y = (lab[0] + 16) / 116
    v = np.array([lab[1] / 500 + y, y, y - lab[2] / 200])
    v = np.where(v ** 3 > 0.008856, v ** 3, (v - 16 / 116) / 7.787) * np.array([0.9505, 1.0, 1.089])
    x, y, z = v
    c = np.array([x * 3.2406 + y * -1.5372 + z * -0.4986, x * -0.9689 + y * 1.8758 + z * 0.0415,
                  x * 0.0557 + y * -0.2040 + z * 1.0570])
    c = np.array([1.055 * e ** (1 / 2.4) - 0.055 if e > 0.0031308 else 12.92 * e for e in c])
    if c.max() > 1:
        c = c / c.max()
    return np.maximum(c, 0)


def lab_to_msh(lab):
    m = math.sqrt(lab @ lab)
    s = math.acos(lab[0] / m) if m > 0.001 else 0.0
    h = math.atan2(lab[2], lab[1]) if s > 0.001 else 0.0
    return np.array([m, s, h])


def msh_to_lab(msh):
    m, s, h = msh
    return np.array([m * math.cos(s), m * math.sin(s) * math.cos(h), m * math.sin(s) * math.sin(h)])


def angle_diff(a, b):
    d = abs(a - b)
    while d >= 2 * math.pi:
        d -= 2 * math.pi
    return 2 * math.pi - d if d > math.pi else d


def adjust_hue(msh, unsat_m):
    if msh[0] >= unsat_m - 0.1:
        return msh[2]
    spin = msh[1] * math.sqrt(unsat_m ** 2 - msh[0] ** 2) / (msh[0] * math.sin(msh[1]))
    return msh[2] + spin if msh[2] > -0.3 * math.pi else msh[2] - spin


def diverging(s, c1, c2):
    m1, m2 = lab_to_msh(rgb_to_lab(c1)), lab_to_msh(rgb_to_lab(c2))
    if m1[1] > 0.05 and m2[1] > 0.05 and angle_diff(m1[2], m2[2]) > 0.33 * math.pi:
        mid = max(m1[0], m2[0], 88.0)
        if s < 0.5:
            m2, s = np.array([mid, 0.0, 0.0]), 2 * s
        else:
            m1, s = np.array([mid, 0.0, 0.0]), 2 * s - 1
    if m1[1] < 0.05 and m2[1] > 0.05:
        m1[2] = adjust_hue(m2, m1[0])
    elif m2[1] < 0.05 and m1[1] > 0.05:
        m2[2] = adjust_hue(m1, m2[0])
    return lab_to_rgb(msh_to_lab((1 - s) * m1 + s * m2))


def rgb_to_hsv(c):
    r, g, b = c
    hi, lo = max(r, g, b), min(r, g, b)
    v = hi
    s = (hi - lo) / hi if hi > 0 else 0.0
    if s > 0:
        if r == hi:
            h = (g - b) / (hi - lo) / 6
        elif g == hi:
            h = 1 / 3 + (b - r) / (hi - lo) / 6
        else:
            h = 2 / 3 + (r - g) / (hi - lo) / 6
        if h < 0:
            h += 1
    else:
        h = 0.0
    return np.array([h, s, v])


def hsv_to_rgb(hsv):
    h, s, v = hsv
    if 1 / 6 < h <= 1 / 3:
        c = (( 1 / 3 - h) * 6, 1.0, 0.0)
    elif 1 / 3 < h <= 0.5:
        c = (0.0, 1.0, (h - 1 / 3) * 6)
    elif 0.5 < h <= 2 / 3:
        c = (0.0, (2 / 3 - h) * 6, 1.0)
    elif 2 / 3 < h <= 5 / 6:
        c = ((h - 2 / 3) * 6, 0.0, 1.0)
    elif 5 / 6 < h <= 1:
        c = (1.0, 0.0, (1 - h) * 6)
    else:
        c = (1.0, h * 6, 0.0)
    return np.array([(s * e + 1 - s) * v for e in c])


def interpolate(space, s, c1, c2, wrap):
    c1, c2 = np.asarray(c1, float), np.asarray(c2, float)
    if space == "RGB":
        return (1 - s) * c1 + s * c2
    if space == "Step":
        return c2
    if space == "Lab":
        return lab_to_rgb((1 - s) * rgb_to_lab(c1) + s * rgb_to_lab(c2))
    if space == "Diverging":
        return diverging(s, c1, c2)
    h1, h2 = rgb_to_hsv(c1), rgb_to_hsv(c2)
    if wrap and abs(h1[0] - h2[0]) > 0.5:
        if h1[0] > h2[0]:
            h1[0] -= 1
        else:
            h2[0] -= 1
    h = (1 - s) * h1 + s * h2
    if h[0] < 0:
        h[0] += 1
    return hsv_to_rgb(h)


def piecewise(s, y1, y2, midpoint, sharpness):
    """vtkPiecewiseFunction between two nodes at the fraction s of the interval."""
    midpoint = min(max(midpoint, 0.00001), 0.99999)
    s = 0.5 * s / midpoint if s < midpoint else 0.5 + 0.5 * (s - midpoint) / (1 - midpoint)
    if sharpness > 0.99:
        return y1 if s < 0.5 else y2
    if sharpness < 0.01:
        return (1 - s) * y1 + s * y2
    if s < 0.5:
        s = 0.5 * (2 * s) ** (1 + 10 * sharpness)
    elif s > 0.5:
        s = 1 - 0.5 * (2 * (1 - s)) ** (1 + 10 * sharpness)
    ss, sss = s * s, s * s * s
    t = (1 - sharpness) * (y2 - y1)
    y = (2 * sss - 3 * ss + 1) * y1 + (-2 * sss + 3 * ss) * y2 + (sss - 2 * ss + s) * t + (sss - ss) * t
    return min(max(y, min(y1, y2)), max(y1, y2))


# --- the ParaView fixtures ------------------------------------------------------------

PRESETS = [
    {"Name": "Lab Ramp", "ColorSpace": "Lab",
     "RGBPoints": [-50, 0.1, 0.1, 0.6, 30, 0.9, 0.9, 0.2, 150, 0.8, 0.1, 0.1],
     "Points": [-50, 0.0, 0.5, 0.0, 10, 0.2, 0.3, 0.6, 90, 0.6, 0.5, 0.2, 150, 0.9, 0.5, 0.0],
     "NanColor": [1, 1, 0]},
    {"Name": "Diverging Pair", "ColorSpace": "Diverging",
     "RGBPoints": [-1, 0.231373, 0.298039, 0.752941, 1, 0.705882, 0.0156863, 0.14902, 2, 0.9, 0.9, 0.9],
     "Points": [-1, 0.05, 0.2, 0.9, 0.5, 0.7, 0.8, 0.4, 2, 0.1, 0.5, 1.0]},
    {"Name": "HSV Wrapped", "ColorSpace": "HSV", "HSVWrap": 1,
     "RGBPoints": [0, 1.0, 0.0, 0.6, 10, 1.0, 0.6, 0.0, 20, 0.2, 0.4, 1.0]},
    {"Name": "HSV", "ColorSpace": "HSV",
     "RGBPoints": [0, 1.0, 0.0, 0.6, 10, 1.0, 0.6, 0.0, 20, 0.2, 0.4, 1.0],
     "Points": [0, 0.0, 0.5, 0.0, 20, 0.5, 0.5, 0.0]},
    {"Name": "Steps", "ColorSpace": "Step",
     "RGBPoints": [0, 0.1, 0.2, 0.3, 0.3333, 0.9, 0.1, 0.1, 0.6667, 0.1, 0.8, 0.2, 1, 0.95, 0.95, 0.2]},
    {"Name": "RGB Jump", "ColorSpace": "RGB",
     "RGBPoints": [0, 0, 0, 0, 0.5, 1, 0, 0, 0.5, 0, 0, 1, 1, 1, 1, 1],
     "Points": [0, 0.1, 0.5, 0.0, 0.4, 0.3, 0.5, 1.0, 1, 0.8, 0.5, 0.0]},
    {"Name": "CIELAB Spelling", "ColorSpace": "CIELAB",
     "RGBPoints": [0, 0.0, 0.0, 0.0, 1, 1.0, 1.0, 1.0]},
]
SINGLE = [{"Name": "Only One", "ColorSpace": "Diverging",
           "RGBPoints": [0, 0.231373, 0.298039, 0.752941, 255, 0.705882, 0.0156863, 0.14902],
           "Points": [0, 0.0, 0.5, 0.0, 255, 0.5, 0.5, 0.0]}]
VTK_SPACE = {"RGB": "SetColorSpaceToRGB", "Lab": "SetColorSpaceToLab", "CIELAB": "SetColorSpaceToLab",
             "Diverging": "SetColorSpaceToDiverging", "HSV": "SetColorSpaceToHSV", "Step": "SetColorSpaceToStep"}
SAMPLES = 201


def rounded(values):
    """Values to 9 decimals (the tests' tolerance is 1/256): a smaller file."""
    return [round(float(v), 9) for v in values]


def vtk_tables(p):
    """VTK's tables of one preset, set up as ParaView's ApplyPreset does (duplicate
    scalars allowed, HSVWrap 0 unless the preset says 1)."""
    rgb = np.array(p["RGBPoints"], float).reshape(-1, 4)
    f = vtk.vtkColorTransferFunction()
    getattr(f, VTK_SPACE[p["ColorSpace"]])()
    f.SetHSVWrap(int(p.get("HSVWrap", 0)))
    f.AllowDuplicateScalarsOn()
    for x, r, g, b in rgb:
        f.AddRGBPoint(x, r, g, b)
    x0, x1 = rgb[0, 0], rgb[-1, 0]
    xs = np.linspace(x0, x1, SAMPLES)
    out = {"x": rounded(xs), "rgb": [rounded(f.GetColor(x)) for x in xs]}
    if "Points" in p:
        pts = np.array(p["Points"], float).reshape(-1, 4)
        o = vtk_opacity(pts)
        ox = np.linspace(pts[0, 0], pts[-1, 0], SAMPLES)
        out["opacity_x"] = rounded(ox)
        out["alpha"] = rounded([o.GetValue(x) for x in ox])
    return out, f


def vtk_opacity(pts):
    """VTK's piecewise function of ParaView's opacity Points (x, alpha, midpoint, sharpness)."""
    o = vtk.vtkPiecewiseFunction()
    o.AllowDuplicateScalarsOn()
    for x, a, mid, sharp in pts:
        o.AddPoint(x, a, mid, sharp)
    return o


def check_own_implementation(p, f):
    """The generator's colour spaces against VTK on the preset's own points."""
    rgb = np.array(p["RGBPoints"], float).reshape(-1, 4)
    space = "Lab" if p["ColorSpace"] == "CIELAB" else p["ColorSpace"]
    worst = 0.0
    for k in range(len(rgb) - 1):
        x1, x2 = rgb[k, 0], rgb[k + 1, 0]
        if x2 == x1:
            continue
        for s in np.linspace(0.01, 0.99, 25):
            mine = interpolate(space, s, rgb[k, 1:], rgb[k + 1, 1:], p.get("HSVWrap", 0))
            worst = max(worst, np.abs(mine - np.array(f.GetColor(x1 + s * (x2 - x1)))).max())
    if "Points" in p:
        pts = np.array(p["Points"], float).reshape(-1, 4)
        o = vtk_opacity(pts)
        for k in range(len(pts) - 1):
            x1, x2 = pts[k, 0], pts[k + 1, 0]
            for s in np.linspace(0.013, 0.987, 30):  # not 0.5: a sharp step sits there
                mine = piecewise(s, pts[k, 1], pts[k + 1, 1], pts[k, 2], pts[k, 3])
                worst = max(worst, abs(mine - o.GetValue(x1 + s * (x2 - x1))))
    if worst > 1e-9:
        sys.exit(f"make_colormaps: own interpolation of '{p['Name']}' differs from VTK by {worst}")
    return worst


# --- output ---------------------------------------------------------------------------

def num(v):
    return repr(float(v))


def main():
    maps = [
        ("viridis", "matplotlib %s colormaps['viridis'], 256 entries" % matplotlib.__version__, matplotlib_map("viridis")),
        ("magma", "matplotlib %s colormaps['magma'], 256 entries" % matplotlib.__version__, matplotlib_map("magma")),
        ("inferno", "matplotlib %s colormaps['inferno'], 256 entries" % matplotlib.__version__, matplotlib_map("inferno")),
        ("plasma", "matplotlib %s colormaps['plasma'], 256 entries" % matplotlib.__version__, matplotlib_map("plasma")),
        ("cividis", "matplotlib %s colormaps['cividis'], 256 entries" % matplotlib.__version__, matplotlib_map("cividis")),
        ("grayscale", "(0, 0, 0) to (1, 1, 1)", (np.array([0.0, 1.0]), np.array([[0.0, 0, 0], [1.0, 1, 1]]))),
        ("cool_to_warm", "VTK %s vtkColorTransferFunction, Diverging, ParaView's 'Cool to Warm' ends, 1025 samples"
         % vtk.vtkVersion.GetVTKVersion(), cool_to_warm()),
        ("rainbow_uniform", "ParaView's 'Rainbow Uniform' RGBPoints (Remoting/Views/ColorMaps.json, RGB)",
         rainbow_uniform()),
    ]
    cpp = [
        "// GENERATED by tools/make_colormaps.py - do not edit. Re-make with",
        "//   /usr/bin/python3 tools/make_colormaps.py",
        "// The named colour maps as RGB control points over [0, 1]: for each, the fewest",
        "// points of its dense reference whose linear interpolation stays within 1/512 of",
        "// every reference point (tests/transfer/colormap_test.cpp checks them against",
        "// tests/data/tf/colormap_reference.json). Sources in the tool's docstring.",
        '#include "transfer/colormap_data.hpp"',
        "",
        "namespace vri::detail {",
        "",
        "namespace {",
        "",
    ]
    reference = {}
    table = []
    for name, source, (x, v) in maps:
        keep = reduce_points(x, v)
        kx, kv = x[keep], v[keep]
        err = max_error(x, v, kx, kv)
        assert err < TOL and kx[0] == 0 and kx[-1] == 1
        print(f"{name:16s} {len(x):5d} reference points -> {len(keep) - 1:3d} pieces, max error {err * 512:.4f}/512")
        ident = "k_" + name
        cpp.append(f"// {name}: {source}; {len(keep) - 1} pieces")
        cpp.append(f"constexpr ColormapPoint {ident}[] = {{")
        for xx, c in zip(kx, kv):
            cpp.append(f"    {{{num(xx)}, {num(c[0])}, {num(c[1])}, {num(c[2])}}},")
        cpp.append("};")
        cpp.append("")
        table.append(f'    {{"{name}",\n     "{source}",\n     {ident}}},')
        reference[name] = {"source": source, "points": [[float(a), *map(float, b)] for a, b in zip(x, v)]}
    cpp += ["}  // namespace", "", "const std::array<Colormap, %d> kColormaps = {{" % len(maps)] + table + ["}};", "",
                                                                                                         "}  // namespace vri::detail", ""]
    with open(os.path.join(ROOT, "src", "transfer", "colormap_data.cpp"), "w") as f:
        f.write("\n".join(cpp))

    tf_dir = os.path.join(ROOT, "tests", "data", "tf")
    os.makedirs(tf_dir, exist_ok=True)
    with open(os.path.join(tf_dir, "colormap_reference.json"), "w") as f:
        f.write('{\n' + ',\n'.join(
            f' "{name}": {{"source": {json.dumps(r["source"])}, "points": [\n  ' +
            ',\n  '.join(json.dumps(rounded(p)) for p in r["points"]) + ']}'
            for name, r in reference.items()) + '\n}\n')

    expected = {"generator": "tools/make_colormaps.py, VTK " + vtk.vtkVersion.GetVTKVersion(), "presets": {}}
    worst = 0.0
    for p in PRESETS + SINGLE:
        tables, f = vtk_tables(p)
        worst = max(worst, check_own_implementation(p, f))
        expected["presets"][p["Name"]] = tables
    print(f"own colour-space and opacity formulas against VTK: max difference {worst:.2e}")
    for name, presets in (("paraview_presets.json", PRESETS), ("paraview_single.json", SINGLE)):
        with open(os.path.join(tf_dir, name), "w") as f:
            json.dump(presets, f, indent=1)
            f.write("\n")
    with open(os.path.join(tf_dir, "paraview_expected.json"), "w") as f:
        json.dump(expected, f, separators=(",", ":"))
        f.write("\n")


if __name__ == "__main__":
    main()
