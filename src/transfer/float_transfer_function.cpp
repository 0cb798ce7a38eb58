#include "vri/transfer/float_transfer_function.hpp"

#include <algorithm>
#include <limits>

namespace vri {

FloatTransferFunction::FloatTransferFunction(const TransferFunction& tf) {
  for (double b : tf.breakpoints()) breakpoints_.push_back(static_cast<float>(b));
  breakpoints_.push_back(std::numeric_limits<float>::infinity());
  for (const TfSegment& seg : tf.segments()) {
    s_ref_.push_back(static_cast<float>(seg.s_ref));
    r_.push_back(static_cast<float>(seg.ref.r));
    g_.push_back(static_cast<float>(seg.ref.g));
    b_.push_back(static_cast<float>(seg.ref.b));
    tau_.push_back(static_cast<float>(seg.ref.tau));
    dr_.push_back(static_cast<float>(seg.slope.r));
    dg_.push_back(static_cast<float>(seg.slope.g));
    db_.push_back(static_cast<float>(seg.slope.b));
    dtau_.push_back(static_cast<float>(seg.slope.tau));
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

const float* FloatTransferFunction::value(int channel) const {
  const std::vector<float>* v[4] = {&r_, &g_, &b_, &tau_};
  return v[channel]->data();
}

const float* FloatTransferFunction::slope(int channel) const {
  const std::vector<float>* v[4] = {&dr_, &dg_, &db_, &dtau_};
  return v[channel]->data();
}

}  // namespace vri
