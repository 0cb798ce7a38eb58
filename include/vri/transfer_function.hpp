#pragma once
// vri/transfer_function.hpp: the transfer function of SPEC §3 and the colormaps that make one.

#include <vector>
#include <array>
#include <span>
#include <string>
#include <string_view>

// ---- transfer_function -----------------------------------------------------
// TransferFunction (SPEC §3): control points (s, r, g, b, tau), r,g,b and tau
// linear in s between points, end values held outside, steps where two points
// share one s (the later one holds at exactly that s).

namespace vri {

struct ControlPoint {
  double s, r, g, b, tau;
};

// What the transfer function gives at one scalar: chromaticity and extinction.
struct TfSample {
  double r, g, b, tau;
};

// One linear piece of the transfer function, covering [s_lo, s_hi):
// v(s) = v_ref + slope * (s - s_ref), s_ref being a (finite) control point.
// The first and last pieces are the constant end regions (s_lo = -inf, s_hi = +inf).
struct TfSegment {
  double s_lo, s_hi;
  double s_ref;
  TfSample ref;    // values at s_ref
  TfSample slope;  // d/ds of each value
  bool transparent() const { return ref.tau == 0 && slope.tau == 0; }
  TfSample at(double s) const {
    const double ds = s - s_ref;
    return {ref.r + slope.r * ds, ref.g + slope.g * ds, ref.b + slope.b * ds,
            ref.tau + slope.tau * ds};
  }
};

class TransferFunction {
 public:
  // Validates: at least one point, s finite and non-decreasing, r,g,b in [0,1],
  // tau finite and >= 0. Throws vri::Error naming the offending point. Points
  // within kMergeDistance x (s_hi - s_lo) of an earlier point take its s.
  static constexpr double kMergeDistance = 1e-12;
  explicit TransferFunction(std::vector<ControlPoint> points);

  // VTK's opacity form: per point tau = -ln(1 - a) / unit_distance, a in [0, 1).
  struct OpacityPoint {
    double s, r, g, b, a;
  };
  static TransferFunction from_opacity(const std::vector<OpacityPoint>& points,
                                       double unit_distance);

  TfSample operator()(double s) const { return segments_[segment_index(s)].at(s); }

  const std::vector<ControlPoint>& points() const { return points_; }
  // The distinct control-point scalars, ascending: where the function may kink or step.
  const std::vector<double>& breakpoints() const { return breakpoints_; }
  // segments()[i] covers [breakpoints[i-1], breakpoints[i]); 0 and the last are the end regions.
  const std::vector<TfSegment>& segments() const { return segments_; }
  // The number of breakpoints <= s: the index of the segment that holds s.
  int segment_index(double s) const;

  // [s_lo, s_hi] spanned by the control points (SPEC §10 table axes).
  double s_lo() const { return points_.front().s; }
  double s_hi() const { return points_.back().s; }
  double max_tau() const;

 private:
  std::vector<ControlPoint> points_;
  std::vector<double> breakpoints_;
  std::vector<TfSegment> segments_;
};

}  // namespace vri

// ---- colormap --------------------------------------------------------------
// Named colour maps (issue 20): matplotlib's viridis, magma, inferno, plasma
// and cividis, grayscale, and ParaView's "Cool to Warm" and "Rainbow Uniform",
// each as RGB control points over [0, 1], linear between them. The points are
// the fewest of each map's dense reference (matplotlib's 256 entries, VTK's
// diverging interpolation, ParaView's preset) that reproduce it within 1/512
// in r, g and b; tools/make_colormaps.py generates them
// (src/transfer/colormap_data.cpp). A scene uses them as
// {"colormap": "viridis", ...} (docs/SCENES.md, "Transfer functions").

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
