#include "vri/tables/discrete_tf.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vri/core/error.hpp"

namespace vri {

double ScalarAxis::index(double s) const {
  if (!(s_hi > s_lo)) return 0;
  const double u = (s - s_lo) / (s_hi - s_lo) * (n - 1);
  return std::clamp(u, 0.0, double(n - 1));
}

DiscreteTf::DiscreteTf(const TransferFunction& tf, int n) {
  if (n < 2 || n > kMaxSize)
    throw Error("table size must be in [2, " + std::to_string(kMaxSize) + "], got " + std::to_string(n));
  axis_ = {tf.s_lo(), tf.s_hi(), n};
  samples_.reserve(n);
  for (int i = 0; i < n; ++i) samples_.push_back(tf(axis_.scalar(i)));
}

TfSample DiscreteTf::at_index(double u) const {
  const int i = std::min(static_cast<int>(u), size() - 2);
  const double w = u - i;
  const TfSample& a = samples_[i];
  const TfSample& b = samples_[i + 1];
  // (1-w) a + w b is exactly a at w = 0 and exactly b at w = 1.
  return {(1 - w) * a.r + w * b.r, (1 - w) * a.g + w * b.g, (1 - w) * a.b + w * b.b,
          (1 - w) * a.tau + w * b.tau};
}

}  // namespace vri
