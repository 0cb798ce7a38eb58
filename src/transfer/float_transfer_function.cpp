#include "transfer/float_transfer_function.hpp"

#include <algorithm>
#include <limits>

namespace vri {

FloatTransferFunction::FloatTransferFunction(const TransferFunction& tf) {
  for (double b : tf.breakpoints()) breakpoints_.push_back(static_cast<float>(b));
  breakpoints_.push_back(std::numeric_limits<float>::infinity());
  const auto channels = [](const TfSample& v) { return std::array{v.r, v.g, v.b, v.tau}; };
  for (const TfSegment& seg : tf.segments()) {
    s_ref_.push_back(static_cast<float>(seg.s_ref));
    const auto ref = channels(seg.ref), slope = channels(seg.slope);
    for (int c = 0; c < 4; ++c) {
      value_[c].push_back(static_cast<float>(ref[c]));
      slope_[c].push_back(static_cast<float>(slope[c]));
    }
  }
  const float span = breakpoints_[breakpoints_.size() - 2] - breakpoints_.front();
  lo_ = breakpoints_.front();
  scale_ = span > 0 ? kBins / span : 0.0f;
  // Bin k holds the scalars from lo + k / scale: start at the breakpoints
  // below its lower end (the walk in `segment` corrects any rounding).
  first_.resize(kBins);
  const int n = static_cast<int>(breakpoints_.size()) - 1;
  for (int k = 0; k < kBins; ++k) {
    const float start = scale_ > 0 ? lo_ + static_cast<float>(k) / scale_ : lo_;
    first_[k] = static_cast<int>(std::upper_bound(breakpoints_.begin(), breakpoints_.begin() + n, start) -
                                 breakpoints_.begin());
  }
}

}  // namespace vri
