#include "vri/tables/zero_opacity.hpp"

#include <algorithm>
#include <cmath>

namespace vri {

ZeroOpacity::ZeroOpacity(const TransferFunction& tf) : tf_(&tf) {
  const auto& pieces = tf.segments();
  opaque_before_.assign(pieces.size() + 1, 0);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    opaque_before_[i + 1] = opaque_before_[i] + (pieces[i].transparent() ? 0 : 1);
}

ZeroOpacity::ZeroOpacity(const DiscreteTf& tf) : axis_(tf.axis()) {
  opaque_before_.assign(tf.size() + 1, 0);
  for (int i = 0; i < tf.size(); ++i) opaque_before_[i + 1] = opaque_before_[i] + (tf[i].tau != 0 ? 1 : 0);
}

bool ZeroOpacity::over(double lo, double hi) const {
  int first, last;  // inclusive
  if (tf_) {
    first = tf_->segment_index(lo);
    last = tf_->segment_index(hi);
  } else {
    // index() is monotone in s, so a lookup at any s in [lo, hi] gives weight
    // only to entries floor(index(lo)) .. ceil(index(hi)) (an entry of weight 0 adds 0).
    first = static_cast<int>(axis_.index(lo));
    last = static_cast<int>(std::ceil(axis_.index(hi)));
  }
  return opaque_before_[last + 1] == opaque_before_[first];
}

}  // namespace vri
