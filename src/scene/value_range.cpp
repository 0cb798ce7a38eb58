#include "scene/value_range.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "vri/volume.hpp"

namespace vri {

namespace {

void check_percentiles(double p_lo, double p_hi) {
  if (!(p_lo >= 0 && p_lo <= p_hi && p_hi <= 100))
    throw Error("percentiles must satisfy 0 <= p_lo <= p_hi <= 100, got [" + format_g(p_lo) + ", " +
                format_g(p_hi) + "]");
}

// numpy's "linear" percentile of `values` (reordered: nth_element).
template <class T>
double exact_percentile(std::vector<T>& values, double p) {
  const double rank = p / 100 * double(values.size() - 1);
  const auto k = static_cast<std::size_t>(std::floor(rank));
  const double frac = rank - double(k);
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  const double below = double(values[k]);
  if (frac == 0 || k + 1 >= values.size()) return below;
  // After nth_element everything past k is >= values[k]: the next order statistic is their minimum.
  const double above = double(*std::min_element(values.begin() + std::ptrdiff_t(k) + 1, values.end()));
  return below + frac * (above - below);
}

template <class T>
ValueRange exact_range(std::span<const T> samples, double p_lo, double p_hi) {
  check_allocation(samples.size(), sizeof(T), "a copy of the samples for their percentiles");
  std::vector<T> copy(samples.begin(), samples.end());
  return {exact_percentile(copy, p_lo), exact_percentile(copy, p_hi)};
}

// The value below which a share p/100 of the samples lie, read from the histogram.
double histogram_percentile(const Histogram& h, std::uint64_t n, double p) {
  const double rank = p / 100 * double(n - 1);
  const double width = (h.hi - h.lo) / double(h.counts.size());
  std::uint64_t before = 0;
  for (std::size_t i = 0; i < h.counts.size(); ++i) {
    const std::uint64_t c = h.counts[i];
    if (c > 0 && rank < double(before + c)) {
      const double inside = (rank - double(before) + 0.5) / double(c);
      return std::min(h.hi, h.lo + width * (double(i) + std::clamp(inside, 0.0, 1.0)));
    }
    before += c;
  }
  return h.hi;
}

}  // namespace

ValueRange data_range(const Volume& volume) {
  if (const auto* g = std::get_if<GridVolume>(&volume)) return {g->min_value(), g->max_value()};
  const auto& s = std::get<TetMesh>(volume).scalars();
  if (s.empty()) throw Error("the mesh has no scalars");
  const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
  return {*lo, *hi};
}

ValueRange percentile_range(std::span<const float> samples, double p_lo, double p_hi) {
  check_percentiles(p_lo, p_hi);
  if (samples.empty()) throw Error("percentiles of no samples");
  return exact_range(samples, p_lo, p_hi);
}

ValueRange percentile_range(const Volume& volume, double p_lo, double p_hi) {
  check_percentiles(p_lo, p_hi);
  if (const auto* m = std::get_if<TetMesh>(&volume)) return percentile_range(m->scalars(), p_lo, p_hi);
  const auto& g = std::get<GridVolume>(volume);
  if (g.brick())
    throw Error("a percentile range needs every sample, and this process holds one part of the grid: "
                "give \"data\" or [lo, hi] for distributed rendering");
  const std::uint64_t n = g.size();
  if (n <= kExactPercentileSamples)
    return g.visit([&](auto v) { return exact_range(std::span(v.data(), v.size()), p_lo, p_hi); });
  const Histogram h = histogram(g, kPercentileBins);
  // Exact at the ends: the histogram's edges are the data's minimum and maximum.
  const auto at = [&](double p) {
    return p == 0 ? h.lo : p == 100 ? h.hi : histogram_percentile(h, n, p);
  };
  return {at(p_lo), at(p_hi)};
}

}  // namespace vri
