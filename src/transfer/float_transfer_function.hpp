#pragma once
// FloatTransferFunction: TransferFunction's evaluation (SPEC §3) in float, for
// riemann's float path and its packets of rays (issue 8; docs/PERFORMANCE.md,
// "Float paths and packets"). The same segments (TfSegment: v = ref + slope (s - s_ref)
// on [breakpoint i-1, breakpoint i)) with their numbers rounded to float; the
// segment of a scalar is found from a uniform grid of kBins bins over the
// breakpoints' span, which names a segment near it, and a short walk to the
// segment that holds it (the number of breakpoints <= s, as segment_index).
// Exact where a segment is zero: a scalar in a zero-opacity run gets tau = 0
// exactly, so empty-space skipping stays exact on this path.
#include <algorithm>
#include <array>
#include <vector>

#include "vri/transfer_function.hpp"

namespace vri {

class FloatTransferFunction {
 public:
  static constexpr int kBins = 1024;
  explicit FloatTransferFunction(const TransferFunction& tf);

  struct Sample {
    float r, g, b, tau;
  };
  Sample operator()(float s) const {
    const int i = segment(s);
    const float ds = s - s_ref_[i];
    const auto at = [&](int c) { return value_[c][i] + slope_[c][i] * ds; };
    return {at(0), at(1), at(2), at(3)};
  }
  // The number of breakpoints <= s.
  int segment(float s) const {
    int i = first_[bin(s)];
    while (breakpoints_[i] <= s) ++i;  // breakpoints_ ends with +inf
    while (i > 0 && breakpoints_[i - 1] > s) --i;
    return i;
  }
  int bin(float s) const {
    const float u = std::min(std::max((s - lo_) * scale_, 0.0f), static_cast<float>(kBins - 1));
    return static_cast<int>(u);
  }

  // What the evaluation reads, for the ray packets (src/methods/preint/float_packet.cpp).
  float lo() const { return lo_; }
  float scale() const { return scale_; }
  const int* first() const { return first_.data(); }
  const float* breakpoints() const { return breakpoints_.data(); }
  // Segments, and breakpoints with the closing +inf: one per segment.
  int segments() const { return static_cast<int>(s_ref_.size()); }
  int breakpoint_count() const { return static_cast<int>(breakpoints_.size()); }
  // Per segment: s_ref, the values there and their slopes (channels r, g, b, tau).
  const float* s_ref() const { return s_ref_.data(); }
  const float* value(int channel) const { return value_[channel].data(); }
  const float* slope(int channel) const { return slope_[channel].data(); }

 private:
  float lo_, scale_;
  std::vector<int> first_;          // per bin: a segment at or below those of its scalars
  std::vector<float> breakpoints_;  // ascending, then +inf
  std::vector<float> s_ref_;
  std::array<std::vector<float>, 4> value_, slope_;  // per channel r, g, b, tau
};

}  // namespace vri
