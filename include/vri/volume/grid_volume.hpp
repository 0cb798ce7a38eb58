#pragma once
// GridVolume: a scalar field on nx*ny*nz points, x fastest, trilinear between
// samples; the medium is the closed box B of SPEC §1.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "vri/core/vec3.hpp"

namespace vri {

class GridVolume {
 public:
  // Largest accepted volume: 2^30 samples (4 GiB as float). Bigger requests are
  // refused before any allocation so absurd dims fail cleanly.
  static constexpr std::uint64_t kMaxSamples = std::uint64_t{1} << 30;

  // Checks dims >= 2, values.size() == nx*ny*nz, every value finite,
  // spacing > 0; throws vri::Error otherwise.
  GridVolume(std::array<int, 3> dims, std::vector<float> values, Vec3 spacing = {1, 1, 1},
             Vec3 origin = {0, 0, 0});

  // Throws vri::Error unless dims describe an acceptable volume; returns the sample count.
  static std::uint64_t checked_sample_count(std::array<std::int64_t, 3> dims);

  const std::array<int, 3>& dims() const { return dims_; }
  Vec3 spacing() const { return spacing_; }
  Vec3 origin() const { return origin_; }
  void set_spacing(Vec3 spacing);
  void set_origin(Vec3 origin);

  const std::vector<float>& values() const { return values_; }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims_[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims_[1]) * k);
  }
  float at(int i, int j, int k) const { return values_[index(i, j, k)]; }

  float min_value() const { return min_; }
  float max_value() const { return max_; }

  Vec3 box_lo() const { return origin_; }
  Vec3 box_hi() const;
  // min(sx, sy, sz): the unit of step sizes (SPEC §1).
  double voxel_unit() const;

  // Trilinear value at a world point; points outside B are clamped onto it.
  double sample(Vec3 p) const;

 private:
  std::array<int, 3> dims_;
  std::vector<float> values_;
  Vec3 spacing_, origin_;
  float min_ = 0, max_ = 0;
};

}  // namespace vri
