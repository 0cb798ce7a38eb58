#include "vri/volume.hpp"

#include <algorithm>
#include <cmath>

#include "vri/error.hpp"

namespace vri {

namespace {

template <class T>
Histogram count(std::span<const T> values, double lo, double hi, int bins) {
  if (bins < 1 || bins > 1 << 20) throw Error("histogram: bins must be 1 .. 1048576");
  Histogram h{lo, hi, std::vector<std::uint64_t>(std::size_t(bins), 0)};
  const double scale = hi > lo ? bins / (hi - lo) : 0;
  for (const T v : values)
    ++h.counts[std::min<std::size_t>(std::size_t(bins) - 1, std::size_t((double(v) - lo) * scale))];
  return h;
}

}  // namespace

Histogram histogram(const GridVolume& volume, int bins) {
  return volume.visit([&](auto v) { return count(v, volume.min_value(), volume.max_value(), bins); });
}

Histogram histogram(std::span<const float> scalars, int bins) {
  if (scalars.empty()) throw Error("histogram: no scalars");
  const auto [min, max] = std::minmax_element(scalars.begin(), scalars.end());
  return count(scalars, *min, *max, bins);
}

TransferFunction suggest_transfer_function(const Histogram& h, double diagonal) {
  const double lo = h.lo, hi = h.hi > h.lo ? h.hi : h.lo + 1;
  const int bins = int(h.counts.size());
  const double width = (hi - lo) / bins;
  // The background: the fullest bin, if it lies in the lowest quarter; its
  // edge: the first bin after it holding under 1% of it.
  const auto peak = std::max_element(h.counts.begin(), h.counts.end()) - h.counts.begin();
  double start = lo;
  if (peak < bins / 4) {
    auto edge = peak;
    while (edge + 1 < bins && h.counts[edge] * 100 >= h.counts[peak]) ++edge;
    start = lo + double(edge) * width;
  }
  start = std::min(start, lo + 0.9 * (hi - lo));
  const double tau = std::log(2.0) / (0.1 * std::max(diagonal, 1e-9));
  const double mid = 0.5 * (start + hi);
  return TransferFunction({{lo, 0, 0, 0, 0},
                           {start, 0.2, 0.4, 1.0, 0},
                           {mid, 1.0, 0.6, 0.2, 0.3 * tau},
                           {hi, 1.0, 1.0, 1.0, tau}});
}

}  // namespace vri
