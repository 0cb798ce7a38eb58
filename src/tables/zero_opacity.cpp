#include "tables/zero_opacity.hpp"

#include <algorithm>
#include <cmath>

namespace vri {

ZeroOpacity::ZeroOpacity(const TransferFunction& tf) : tf_(&tf) {
  const auto& pieces = tf.segments();
  opaque_before_.assign(pieces.size() + 1, 0);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    opaque_before_[i + 1] = opaque_before_[i] + (pieces[i].transparent() ? 0 : 1);
}

ZeroOpacity::ZeroOpacity(const DiscreteTf& tf, TableOrder order) : axis_(tf.axis()), order_(order) {
  const int n = tf.size();
  // Whether split bin k has extinction inside (a spike between two table scalars).
  const auto split_opaque = [&](int k) {
    for (const SubPiece& s : tf.sub_pieces(k))
      if (s.p.tau != 0 || s.q.tau != 0) return true;
    return false;
  };
  std::vector<char> opaque;
  if (order == TableOrder::First) {
    // A split bin with extinction inside marks both its table scalars opaque:
    // every entry that covers it then counts.
    opaque.resize(n);
    for (int i = 0; i < n; ++i) opaque[i] = tf[i].tau != 0;
    for (int k : tf.split_bins())
      if (split_opaque(k)) opaque[k] = opaque[k + 1] = 1;
  } else {
    // Table scalar i at position 2i, bin i (x_i .. x_i+1) at 2i + 1: a bin
    // with extinction inside counts, its table scalars only if they have it.
    opaque.resize(2 * n - 1);
    for (int i = 0; i < n; ++i) opaque[2 * i] = tf[i].tau != 0;
    for (int k = 0; k + 1 < n; ++k)
      opaque[2 * k + 1] = tf.sub_pieces(k).empty() ? tf[k].tau != 0 || tf[k + 1].tau != 0 : split_opaque(k);
  }
  opaque_before_.assign(opaque.size() + 1, 0);
  for (std::size_t i = 0; i < opaque.size(); ++i) opaque_before_[i + 1] = opaque_before_[i] + opaque[i];
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
  if (order_ == TableOrder::First) return opaque_before_[last + 1] == opaque_before_[first];
  // Positions 2 first .. 2 last (table scalars and the bins between them) have
  // no extinction; the run of such positions that holds them spans the table
  // scalars a..b; and the parabola's reach beyond the range of its three
  // scalars (header; El Hajjar et al. 2008, Eq. 2).
  const int opaque = opaque_before_[2 * first];
  if (opaque_before_[2 * last + 1] != opaque) return false;
  const auto begin = opaque_before_.begin();
  const int p = static_cast<int>(std::lower_bound(begin, begin + 2 * first + 1, opaque) - begin);
  const int q = static_cast<int>(std::upper_bound(begin + 2 * last + 1, opaque_before_.end(), opaque) - begin) - 2;
  const int a = (p + 1) / 2, b = q / 2;
  const double reach = (b - a) / 8.0 + 1e-3;
  return (a == 0 || first >= a + reach) && (b == axis_.n - 1 || last <= b - reach);
}

ZeroOpacityBins::ZeroOpacityBins(const ZeroOpacity& zero, double lo, double hi, int bins)
    : lo_(lo), hi_(hi), scale_(hi > lo ? bins / (hi - lo) : 0), last_(bins - 1), marked_before_(bins + 1, 0) {
  // A scalar that rounding puts a few ulps beyond its bin's ends stays covered.
  const double margin = 1e-9 * (hi - lo + std::max(std::abs(lo), std::abs(hi)));
  for (int i = 0; i < bins; ++i) {
    const double a = lo + (hi - lo) * i / bins, b = i == bins - 1 ? hi : lo + (hi - lo) * (i + 1) / bins;
    marked_before_[i + 1] = marked_before_[i] + (zero.over(a - margin, b + margin) ? 0 : 1);
  }
}

}  // namespace vri
