#pragma once
// TransferFunction (SPEC §3): control points (s, r, g, b, tau), r,g,b and tau
// linear in s between points, end values held outside, steps where two points
// share one s (the later one holds at exactly that s).
#include <vector>

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
