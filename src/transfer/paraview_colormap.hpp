#pragma once
// ParaView's colour-map presets: the JSON that ParaView's "Choose Preset"
// dialog imports and exports, an array of objects each with "Name",
// "ColorSpace", "RGBPoints" [x, r, g, b, ...] and optionally "Points"
// [x, alpha, midpoint, sharpness, ...] (the opacity, alpha per unit distance).
// vri's transfer function is piecewise linear in RGB and in tau, so the
// curves VTK draws from a preset (vtkColorTransferFunction in the preset's
// colour space, vtkPiecewiseFunction with midpoint and sharpness) are sampled
// and reduced to linear pieces that stay within a tolerance of them. A scene
// uses a preset as {"paraview": "file.json", "name": ...} (docs/SCENES.md,
// "Transfer functions"); tools/make_colormaps.py writes the fixtures that
// check these curves against VTK's own tables.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "vri/transfer_function.hpp"

namespace vri {

// The colour spaces vri imports ("CIELAB" is read as Lab). Lab/CIEDE2000 is not.
enum class ColorSpace { Rgb, Hsv, Lab, Diverging, Step };

// One node of a preset's "Points": alpha at unit distance 1 at x; midpoint and
// sharpness shape the curve from this node to the next (vtkPiecewiseFunction).
struct OpacityNode {
  double x, alpha, midpoint, sharpness;
};

struct ParaviewColormap {
  std::string name;
  ColorSpace color_space = ColorSpace::Rgb;
  bool hsv_wrap = false;                   // "HSVWrap" (ParaView's default: off)
  std::vector<ColormapPoint> rgb_points;   // "RGBPoints", x as in the file (non-decreasing)
  std::vector<OpacityNode> opacity;        // "Points"; empty when the preset has none
};

// The preset called `name` of a ParaView colour-map file (a JSON array of
// presets, or one preset object); an empty `name` asks for the file's only
// preset. vri::Error with one line starting with `source` for malformed JSON,
// a missing or ambiguous preset (the message lists the names), RGBPoints or
// Points whose length is not a multiple of 4, decreasing x, colours or alpha
// outside [0, 1], midpoint or sharpness outside [0, 1], and what vri does not
// import: another colour space (Lab/CIEDE2000), "UseLogScale", indexed
// ("IndexedColors") maps. Other keys ("NanColor", "Creator", ...) are ignored.
ParaviewColormap parse_paraview_colormap(std::string_view json_text, const std::string& source,
                                         const std::string& name = "");

// The preset's colours as VTK draws them (vtkColorTransferFunction in its
// colour space, a node's midpoint 0.5 and sharpness 0 as RGBPoints give them;
// Step: a node's colour holds on (previous x, its x]) reduced to linear RGB
// pieces within `tolerance` of its samples: 16 even samples per interval,
// each halved while its midpoint lies over tolerance/8 off the chord (RGB and
// Step: the nodes themselves, exact). Pieces are found greedily (galloping),
// so they are few, not always the fewest. x as in the file.
std::vector<ColormapPoint> linear_colors(const ParaviewColormap& map, double tolerance = 1.0 / 512);

// An opacity curve (vtkPiecewiseFunction: linear in alpha, or the midpoint and
// sharpness curve) as points (x, tau), tau = -ln(1 - alpha) (unit distance 1),
// between which tau is linear, so that alpha = 1 - exp(-tau) is within
// `tolerance` of the curve's samples (32 even samples per interval, refined
// as the colours'; sharpness > 0.99: VTK's step, exact). A node's alpha of
// 1 (opaque at any distance: tau would be infinite) is read as kOpaqueAlpha.
struct TauPoint {
  double x, tau;
};
// The largest alpha a ParaView preset's 1 stands for: the largest double
// below 1 that float tables tell from it, 1 - 2^-24, so the largest finite
// extinction it gives is tau = 24 ln 2 = 16.64 per unit distance (6e-8 of
// the light left over it).
inline constexpr double kOpaqueAlpha = 1 - 0x1p-24;
std::vector<TauPoint> linear_opacity(const std::vector<OpacityNode>& nodes, double tolerance = 1.0 / 512);

// VTK's colour between the colours a (s = 0) and b (s = 1) in a colour space
// (vtkColorTransferFunction, sharpness 0): sRGB <-> CIE Lab through XYZ (D65,
// vtkMath's constants and gamut clipping), Moreland's Msh for Diverging (white
// inserted between two saturated colours of distant hues), HSV with or without
// wrapping the hue, Step (b).
std::array<double, 3> interpolate_color(ColorSpace space, double s, const std::array<double, 3>& a,
                                        const std::array<double, 3>& b, bool hsv_wrap);
// vtkPiecewiseFunction's value between the nodes' values y1 and y2 at the
// fraction s of the interval, shaped by the first node's midpoint and sharpness.
double opacity_curve(double s, double y1, double y2, double midpoint, double sharpness);

}  // namespace vri
