#include "vri/transfer_function.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "vri/error.hpp"

namespace vri {

namespace {

TfSample values_of(const ControlPoint& p) { return {p.r, p.g, p.b, p.tau}; }

}  // namespace

TransferFunction::TransferFunction(std::vector<ControlPoint> points) : points_(std::move(points)) {
  if (points_.empty()) throw Error("transfer function has no control points");
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const auto& p = points_[i];
    const std::string where = "transfer function point " + std::to_string(i);
    if (!std::isfinite(p.s)) throw Error(where + ": s is not finite");
    if (i > 0 && p.s < points_[i - 1].s)
      throw Error(where + ": s = " + format_g(p.s) + " is below the previous point's " + format_g(points_[i - 1].s) +
                  " (points must be sorted by s)");
    for (double c : {p.r, p.g, p.b})
      if (!(c >= 0 && c <= 1)) throw Error(where + ": colour components must be in [0, 1]");
    if (!(p.tau >= 0) || !std::isfinite(p.tau))
      throw Error(where + ": tau must be finite and >= 0, got " + format_g(p.tau));
  }
  // Points closer than kMergeDistance of the scalar range to the first point
  // of their group join it (issue 16): a piece a few ulps wide has a slope no
  // integrator can evaluate without cancellation. At a shared s the later
  // point holds (below), so the merge keeps SPEC §3's step. The range is
  // taken in halves so that +-1e308 does not overflow.
  const double merge = kMergeDistance * 2 * (0.5 * points_.back().s - 0.5 * points_.front().s);
  for (std::size_t i = 1, first = 0; i < points_.size(); ++i) {
    if (points_[i].s - points_[first].s <= merge) points_[i].s = points_[first].s;
    else first = i;
  }
  // Breakpoints and the linear pieces between them. Among points sharing one s,
  // the last is the left end of the piece above and the first the right end of
  // the piece below, so at exactly that s the later point holds.
  const double inf = std::numeric_limits<double>::infinity();
  segments_.push_back({-inf, points_.front().s, points_.front().s, values_of(points_.front()), {0, 0, 0, 0}});
  std::size_t i = 0;
  while (i < points_.size()) {
    std::size_t last = i;
    while (last + 1 < points_.size() && points_[last + 1].s == points_[i].s) ++last;
    breakpoints_.push_back(points_[i].s);
    if (last + 1 < points_.size()) {
      const auto& a = points_[last];
      const auto& b = points_[last + 1];
      // In halves where the width overflows (points near -+1e308).
      const double w = b.s - a.s, k = std::isfinite(w) ? 1.0 : 0.5, kw = std::isfinite(w) ? w : k * b.s - k * a.s;
      segments_.push_back({a.s, b.s, a.s, values_of(a),
                           {k * (b.r - a.r) / kw, k * (b.g - a.g) / kw, k * (b.b - a.b) / kw,
                            k * (b.tau - a.tau) / kw}});
    }
    i = last + 1;
  }
  segments_.push_back({points_.back().s, inf, points_.back().s, values_of(points_.back()), {0, 0, 0, 0}});
}

TransferFunction TransferFunction::from_opacity(const std::vector<OpacityPoint>& points,
                                                double unit_distance) {
  if (!(unit_distance > 0) || !std::isfinite(unit_distance))
    throw Error("transfer function unit_distance must be positive, got " +
                format_g(unit_distance));
  std::vector<ControlPoint> cps;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    if (!(p.a >= 0 && p.a < 1))
      throw Error("transfer function point " + std::to_string(i) +
                  ": opacity must be in [0, 1), got " + format_g(p.a));
    cps.push_back({p.s, p.r, p.g, p.b, -std::log1p(-p.a) / unit_distance});
  }
  return TransferFunction(std::move(cps));
}

int TransferFunction::segment_index(double s) const {
  return static_cast<int>(std::upper_bound(breakpoints_.begin(), breakpoints_.end(), s) -
                          breakpoints_.begin());
}

double TransferFunction::max_tau() const {
  double m = 0;
  for (const auto& p : points_) m = std::max(m, p.tau);
  return m;
}

}  // namespace vri
