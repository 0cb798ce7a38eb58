#pragma once
// The scalar ranges a transfer function's "range" may ask of its volume
// (docs/SCENES.md, "Transfer functions"): the samples' minimum and maximum,
// or two of their percentiles. A grid's samples are its grid points, a mesh's
// its point scalars.
#include <cstdint>
#include <span>

#include "vri/scene.hpp"

namespace vri {

struct ValueRange {
  double lo, hi;
};

// [min, max] of the volume's samples.
ValueRange data_range(const Volume& volume);

// The percentiles p_lo and p_hi (0 <= p_lo <= p_hi <= 100) of the volume's
// samples, as numpy.percentile's default ("linear") defines them: the sorted
// samples v_0 <= ... <= v_{n-1}, rank r = p/100 (n - 1), value
// v_floor(r) + (r - floor(r)) (v_floor(r)+1 - v_floor(r)). Exact (nth_element on
// a copy) up to kExactPercentileSamples samples; above, read from a histogram
// of kPercentileBins bins over [min, max], linear inside the bin, so within
// (max - min) / kPercentileBins of the exact value.
constexpr std::uint64_t kExactPercentileSamples = std::uint64_t{1} << 26;  // 64 Mi
constexpr int kPercentileBins = 1 << 16;
ValueRange percentile_range(const Volume& volume, double p_lo, double p_hi);

// The same on samples given as floats (exact whatever their number).
ValueRange percentile_range(std::span<const float> samples, double p_lo, double p_hi);

}  // namespace vri
