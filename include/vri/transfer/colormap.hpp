#pragma once
// Named colour maps (issue 20): matplotlib's viridis, magma, inferno, plasma
// and cividis, grayscale, and ParaView's "Cool to Warm" and "Rainbow Uniform",
// each as RGB control points over [0, 1], linear between them. The points are
// the fewest of each map's dense reference (matplotlib's 256 entries, VTK's
// diverging interpolation, ParaView's preset) that reproduce it within 1/512
// in r, g and b; tools/make_colormaps.py generates them
// (src/transfer/colormap_data.cpp). A scene uses them as
// {"colormap": "viridis", ...} (docs/SCENES.md, "Transfer functions").
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vri {

struct ColormapPoint {
  double x, r, g, b;
};

struct Colormap {
  std::string_view name;                  // canonical: lower case, words joined by '_'
  std::string_view source;                // where the values come from
  std::span<const ColormapPoint> points;  // x ascending, first 0, last 1

  // r, g, b at x: linear between points, the end colours held outside [0, 1].
  std::array<double, 3> at(double x) const;
};

// The map called `name`, compared without regard to case and with spaces or
// hyphens read as '_' ("Cool to Warm" is cool_to_warm); nullptr if none is.
const Colormap* find_colormap(std::string_view name);
// The canonical names, in the order listed in messages and documents.
std::vector<std::string> colormap_names();

}  // namespace vri
