#include "vri/volume/grid_volume.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vri/core/error.hpp"

namespace vri {

std::uint64_t GridVolume::checked_sample_count(std::array<std::int64_t, 3> dims) {
  for (int a = 0; a < 3; ++a) {
    if (dims[a] < 2)
      throw Error("volume dims must each be at least 2, got " + std::to_string(dims[a]));
    if (dims[a] > (std::int64_t{1} << 24))
      throw Error("volume dim " + std::to_string(dims[a]) + " is absurdly large");
  }
  const std::uint64_t n = static_cast<std::uint64_t>(dims[0]) * dims[1] * dims[2];
  if (n > kMaxSamples)
    throw Error("volume of " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                std::to_string(dims[2]) + " samples exceeds the limit of " +
                std::to_string(kMaxSamples) + " samples");
  return n;
}

GridVolume::GridVolume(std::array<int, 3> dims, std::vector<float> values, Vec3 spacing,
                       Vec3 origin)
    : dims_(dims), values_(std::move(values)) {
  const std::uint64_t n = checked_sample_count({dims[0], dims[1], dims[2]});
  if (values_.size() != n)
    throw Error("volume has " + std::to_string(values_.size()) + " samples, dims need " +
                std::to_string(n));
  set_spacing(spacing);
  set_origin(origin);
  const auto bad = std::find_if(values_.begin(), values_.end(),
                                [](float v) { return !std::isfinite(v); });
  if (bad != values_.end())
    throw Error("volume sample " + std::to_string(bad - values_.begin()) + " is not finite");
  const auto [lo, hi] = std::minmax_element(values_.begin(), values_.end());
  min_ = *lo;
  max_ = *hi;
}

void GridVolume::set_spacing(Vec3 spacing) {
  for (int a = 0; a < 3; ++a)
    if (!(spacing[a] > 0) || !std::isfinite(spacing[a]))
      throw Error("volume spacing must be positive and finite");
  spacing_ = spacing;
}

void GridVolume::set_origin(Vec3 origin) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(origin[a])) throw Error("volume origin must be finite");
  origin_ = origin;
}

Vec3 GridVolume::box_hi() const {
  return {origin_.x + (dims_[0] - 1) * spacing_.x, origin_.y + (dims_[1] - 1) * spacing_.y,
          origin_.z + (dims_[2] - 1) * spacing_.z};
}

double GridVolume::voxel_unit() const {
  return std::min({spacing_.x, spacing_.y, spacing_.z});
}

double GridVolume::sample(Vec3 p) const {
  int c[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double u = std::clamp((p[a] - origin_[a]) / spacing_[a], 0.0, double(dims_[a] - 1));
    c[a] = std::min(static_cast<int>(u), dims_[a] - 2);
    f[a] = u - c[a];
  }
  const std::size_t sx = 1, sy = dims_[0], sz = std::size_t(dims_[0]) * dims_[1];
  const float* v = values_.data() + index(c[0], c[1], c[2]);
  const double c00 = v[0] + f[0] * (v[sx] - v[0]);
  const double c10 = v[sy] + f[0] * (v[sy + sx] - v[sy]);
  const double c01 = v[sz] + f[0] * (v[sz + sx] - v[sz]);
  const double c11 = v[sz + sy] + f[0] * (v[sz + sy + sx] - v[sz + sy]);
  const double c0 = c00 + f[1] * (c10 - c00);
  const double c1 = c01 + f[1] * (c11 - c01);
  return c0 + f[2] * (c1 - c0);
}

}  // namespace vri
